// pointdriver run: one path, one CSV row per step, a summary beside it, a replay file on failure.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "pointdriver/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/driver/driver.hpp"
#include "pointdriver/output/csv_writer.hpp"
#include "pointdriver/output/junit.hpp"

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
    "error, 3 a step could not be solved or a check failed.\n"};

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
  for (const auto& s : o.all("--set")) {
    try {
      patches.push_back(Json::parse(s));
    } catch (const Json::parse_error& e) {
      std::cerr << "pointdriver run: --set: invalid JSON: " << e.what() << '\n';
      return 1;
    }
  }
  Path path;
  try {
    path = load_path(file, patches);
  } catch (const InputError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  }
  for (const auto& w : path.warnings) std::cerr << "pointdriver run: warning: " << w << '\n';
  if (o.verbosity.verbose) std::cerr << path.resolved.dump(2) << '\n';
  const std::filesystem::path out =
      o.get("--output", std::filesystem::path(file).stem().string() + ".csv");
  std::filesystem::path stem = out;
  stem.replace_extension();
  if (out.has_parent_path()) {  // -o DIR/OUT.csv into a new DIR, as mpm run --out makes its DIR
    std::error_code ec;
    std::filesystem::create_directories(out.parent_path(), ec);
    if (ec) {
      std::cerr << "pointdriver run: cannot create " << out.parent_path().string() << ": "
                << ec.message() << '\n';
      return 2;
    }
  }
  RunResult r;
  try {
    CsvWriter csv(out.string(), path.material.model.params());
    r = run_path(path, [&](const Row& row) { csv.write(row); });
  } catch (const std::runtime_error& e) {
    std::cerr << "pointdriver run: " << e.what() << '\n';
    return 2;
  }

  Json summary = {{"path_file", file},
                  {"csv", out.string()},
                  {"completed", r.completed},
                  {"steps", r.steps},
                  {"end_time [s]", r.end_time},
                  {"failure_cause", cause_name(r.failure)},
                  {"failure_time [s]", r.failure_time},
                  {"error", r.error},
                  {"columns", csv_columns()},
                  {"resolved_path", path.resolved}};
  const std::string summary_file = stem.string() + ".summary.json";
  std::ofstream(summary_file) << summary.dump(2) << '\n';
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
      return 2;
    }
  }
  if (!r.completed) {
    const std::string replay_file = stem.string() + ".replay.json";
    std::ofstream(replay_file) << r.replay->dump(2) << '\n';
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
