// pointdriver run: one path, one CSV row per step, a summary beside it, a replay file on failure.
#include <filesystem>
#include <iostream>
#include <optional>

#include "pointdriver/commands/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/driver/driver.hpp"
#include "pointdriver/output/csv_writer.hpp"
#include "pointdriver/output/junit.hpp"
#include "pointdriver/output/run_estimate.hpp"
#include "support/atomic_file.hpp"
#include "support/interrupt_signals.hpp"
#include "support/system_resources.hpp"

namespace impact::pointdriver {

namespace {

const CommandSpec run_command{
    "run",
    "Runs the path and writes one CSV row per step (header `name [unit]`, SI units; columns in\n"
    "docs/pointdriver.md), OUT.summary.json (resolved path, how the run ended) and, when a step\n"
    "cannot be solved after the cut-backs, OUT.replay.json: the state at the start of that step\n"
    "as a path file that reproduces it. The path's \"checks\" (a column against a value or a\n"
    "reference CSV) are evaluated after the run and printed.",
    "PATH.json", 1,
    "Exit codes: 0 done (including a failure stopped by the failure policy), 1 usage, 2 input\n"
    "error, 3 a step could not be solved, a check failed or an output could not be written, 4\n"
    "refused before the run: the estimated CSV exceeds the free space (or ulimit -f), or the\n"
    "estimated memory the available memory, 130 interrupted (Ctrl-C), 143 terminated (SIGTERM):\n"
    "the CSV is not written.\n"};

const char* cause_name(FailureCause c) {
  return to_string(c).data();
}

}  // namespace

int command_run(const std::vector<std::string>& args) {
  Options o;
  if (const auto exit_code = parse_command(
          run_command, o, args,
          {{"-o|--out|--output", 1, "CSV file (default: PATH's name with .csv, here)", "FILE"},
           {"--set", 1, "JSON merge patch over the path (repeatable)", "JSON"},
           {"--junit", 1, "the path's checks as JUnit XML", "FILE"}})) {
    return *exit_code;
  }
  if (o.positional.empty()) {
    std::cerr << "pointdriver run: missing PATH.json (pointdriver run --help)\n";
    return 1;
  }
  const std::string file = o.positional[0];
  std::vector<Json> patches;
  Path path;
  try {
    patches = cli::patches_of(o.all("--set"));
    path = load_path(file, patches);
  } catch (const InputError& e) {
    std::cerr << cli::set_origins(file, patches).attribute(e).what() << '\n';
    return cli::kExitInput;
  }
  for (const auto& w : cli::set_origins(file, patches).attribute(path.warnings))
    std::cerr << "pointdriver run: warning: " << w << '\n';
  if (o.verbosity.verbose) std::cerr << path.resolved.dump(2) << '\n';
  const std::filesystem::path out =
      o.get("--output", std::filesystem::path(file).stem().string() + ".csv");
  // -o names the CSV file: a directory there is a usage error, not a file that cannot be written.
  if (std::error_code ec; std::filesystem::is_directory(out, ec)) {
    std::cerr << "pointdriver run: -o " << out.string()
              << " is a directory; -o names the CSV file to write (e.g. -o "
              << (out / (std::filesystem::path(file).stem().string() + ".csv")).string() << ")\n";
    return cli::kExitUsage;
  }
  std::filesystem::path stem = out;
  stem.replace_extension();
  // The first directory of -o's parent that does not exist yet: a refused run removes what it made.
  std::filesystem::path made;
  for (auto p = out.parent_path(); !p.empty() && !std::filesystem::exists(p); p = p.parent_path())
    made = p;
  if (out.has_parent_path()) {  // -o DIR/OUT.csv into a new DIR, as mpm run --out makes its DIR
    try {
      create_output_directory(out.parent_path());
    } catch (const OutputError& e) {
      std::cerr << "pointdriver run: " << e.what() << '\n';
      return cli::kExitFailed;
    }
  }
  // The CSV is opened first, so that a place no file can be made (a read-only file system, /sys,
  // whose free space reads 0) is reported with the system's reason, not as a CSV too large.
  std::optional<CsvWriter> csv;
  try {
    csv.emplace(out.string(), path.material.model.params());
  } catch (const std::runtime_error& e) {
    std::cerr << "pointdriver run: " << e.what() << '\n';
    return cli::kExitFailed;
  }
  // Refused before a row is written when it cannot fit (a leg of 1e9 steps: 440 GB of CSV); the
  // opened CSV's temporary goes with `csv`, the previous CSV stays, a directory made for it goes.
  const RunEstimate estimate = estimate_run(path);
  if (o.verbosity.verbose) {
    std::cerr << "pointdriver run: estimated " << estimate.rows << " rows, CSV "
              << estimate.csv_bytes / 1e6 << " MB, memory " << estimate.memory_bytes / 1e6
              << " MB\n";
  }
  const std::string refusal =
      run_refusal(estimate, out.string(), available_output_bytes(out), available_memory());
  if (!refusal.empty()) {
    std::cerr << "pointdriver run: " << refusal << '\n';
    csv.reset();
    std::error_code ignored;  // only empty directories go: remove() leaves a non-empty one
    for (auto p = out.parent_path(); !made.empty() && !p.empty(); p = p.parent_path()) {
      std::filesystem::remove(p, ignored);
      if (p == made) break;
    }
    return cli::kExitRefused;
  }
  RunResult r;
  // Ctrl-C or SIGTERM: stop after the step, remove the CSV's temporary (a 5e7-step run had left
  // 210 MB of OUT.csv.tmp in 2 s) and exit 128 + the signal, the previous CSV, if any, kept.
  struct Interrupted {
    int signal;
  };
  std::size_t rows = 0;
  try {
    const InterruptSignals signals;
    r = run_path(path, [&](const Row& row) {
      if (const int signal = InterruptSignals::pending()) throw Interrupted{signal};
      csv->write(row);
      ++rows;
    });
    csv->close();
  } catch (const Interrupted& i) {
    csv.reset();
    std::cerr << "pointdriver run: interrupted by " << InterruptSignals::name(i.signal) << " after "
              << rows << " rows; " << out.string() << " not written\n";
    return 128 + i.signal;
  } catch (const std::runtime_error& e) {  // the CSV cannot be written: no partial file is left
    std::cerr << "pointdriver run: " << e.what() << '\n';
    return cli::kExitFailed;
  }

  Json summary = {{"path_file", file},
                  {"csv", out.string()},
                  {"completed", r.completed},
                  {"steps", r.steps},
                  {"end_time [s]", r.end_time},
                  {"failure_cause", cause_name(r.failure)},
                  // null when the run did not fail (no -1 sentinel)
                  {"failure_time [s]", r.failure_time >= 0.0 ? Json(r.failure_time) : Json()},
                  {"error", r.error},
                  {"columns", csv_columns()},
                  // the numbers without a unit in their name (the CSV's columns carry theirs)
                  {"units", {{"steps", "-"}}},
                  {"resolved_path", path.resolved}};
  const std::string summary_file = stem.string() + ".summary.json";
  try {
    write_file_atomically(summary_file, [&](std::ostream& s) { s << summary.dump(2) << '\n'; });
  } catch (const OutputError& e) {
    std::cerr << "pointdriver run: " << e.what() << '\n';
    return cli::kExitFailed;
  }
  // The path's checks, on what the run wrote (also after a failure: its rows up to it).
  const std::vector<CheckOutcome> checks = evaluate_checks(path.checks, out.string());
  bool checks_passed = true;
  std::vector<JunitCase> cases;
  for (const CheckOutcome& c : checks) {
    checks_passed = checks_passed && c.passed;
    std::cout << (c.passed ? "check passed: " : "CHECK FAILED: ") << c.name << ": " << c.message
              << '\n';
    cases.push_back(
        {c.name, file, 0.0, c.passed ? std::nullopt : std::optional(c.message), c.message});
  }
  if (o.has("--junit")) {
    if (!r.completed) cases.push_back({"run", file, 0.0, r.error, "the path did not complete"});
    try {
      write_junit(o.get("--junit", ""), "pointdriver run " + file, cases);
    } catch (const std::runtime_error& e) {
      std::cerr << "pointdriver run: " << e.what() << '\n';
      return cli::kExitFailed;
    }
  }
  const std::string replay_file = stem.string() + ".replay.json";
  if (r.completed) {  // a replay of an earlier failed run beside this one's rows would mislead
    std::error_code ec;
    if (std::filesystem::is_regular_file(replay_file, ec)) std::filesystem::remove(replay_file, ec);
  } else {
    try {
      write_file_atomically(replay_file, [&](std::ostream& s) { s << r.replay->dump(2) << '\n'; });
    } catch (const OutputError& e) {
      std::cerr << "pointdriver run: " << e.what() << '\n';
      return cli::kExitFailed;
    }
    std::cerr << "pointdriver run: " << file << ": " << r.error
              << "\n  rows up to the last solved step are in " << out.string()
              << "; the state at the start of the failed step is in " << replay_file
              << " (reproduce with: pointdriver run " << replay_file << ")\n";
    return 3;
  }
  std::cout << file << ": " << r.steps << " steps to t = " << r.end_time << " s";
  if (r.failure != FailureCause::none) {
    std::cout << "; failed (" << cause_name(r.failure) << ") at t = " << r.failure_time << " s";
  }
  std::cout << " -> " << out.string() << '\n';
  if (!checks_passed) {
    std::cerr << "pointdriver run: " << file << ": a check failed\n";
    return 3;
  }
  return 0;
}

}  // namespace impact::pointdriver
