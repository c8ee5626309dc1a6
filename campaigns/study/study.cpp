// `mpm study` (docs/mpm.md#table-2-study-mpm-study): the cases run one after another, each with
// all the threads it is given (the machine has few cores; running cases side by side would only
// share them), then study_plot.py draws the figures and writes the table.
#include "campaigns/study/study.hpp"
#include "mpm/input/scene_reader.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "mpm/run/run.hpp"
#include "mpm/run/summary.hpp"
#include "mpm/simulation/simulation.hpp"
#include "support/atomic_file.hpp"
#include "support/command_line.hpp"
#include "support/python_launcher.hpp"
#include "support/shipped_file.hpp"

namespace impact::mpm {

namespace {

namespace fs = std::filesystem;

/// study_plot.py: $MPM_STUDY_PLOT_SCRIPT when set, else the shipped copy
/// (support/shipped_file.hpp).
std::string study_plot_script_path() {
  if (const char* env = std::getenv("MPM_STUDY_PLOT_SCRIPT"); env && *env) return env;
  return shipped_file("campaigns/study/study_plot.py").string();
}

/// Runs study_plot.py on OUT. Never changes the study's result: a missing interpreter or a failing
/// script is a warning with the command to run by hand.
void run_plot(const fs::path& out, bool figures) {
  const std::string script = study_plot_script_path();
  const std::string by_hand =
      "python3 " + script + " " + out.string() + (figures ? "" : " --no-figures");
  if (!fs::is_regular_file(script)) {
    std::cerr
        << "mpm study: warning: plotting script not found: " << script
        << " (set MPM_STUDY_PLOT_SCRIPT to campaigns/study/study_plot.py); no table or figures\n";
    return;
  }
  const PythonInterpreter python = find_python();
  if (python.command.empty()) {
    std::cerr
        << "mpm study: warning: no python3 found ($IMPACT_PYTHON, /usr/bin/python3, python3); "
           "no table or figures. Install python3 and python3-matplotlib, then run:\n  "
        << by_hand << '\n';
    return;
  }
  if (figures && !python.matplotlib) {
    std::cerr
        << "mpm study: warning: no python3 with matplotlib ($IMPACT_PYTHON, /usr/bin/python3, "
           "python3): writing the table only. For the figures install python3-matplotlib "
           "(apt-get install -y python3-matplotlib) and run:\n  python3 "
        << script << ' ' << out.string() << '\n';
    figures = false;
  }
  std::vector<std::string> argv{python.command, script, out.string()};
  if (!figures) argv.push_back("--no-figures");
  if (const int code = spawn_process(argv, false); code != 0) {
    std::cerr << "mpm study: warning: " << script << " exited with code " << code
              << "; run it by hand: " << by_hand << '\n';
  }
}

std::string stem_of(const std::string& file) {
  return fs::path(file).stem().string();
}

}  // namespace

std::vector<std::string> study_scene_files(const std::string& scene_dir,
                                           const std::vector<std::string>& selected) {
  std::error_code ec;
  if (!fs::is_directory(scene_dir, ec))
    throw InputError({scene_dir + ": not a directory (expected the study's scene directory)"});
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(scene_dir)) {
    const fs::path& p = entry.path();
    const std::string stem = p.stem().string();
    if (!entry.is_regular_file() || p.extension() != ".json") continue;
    if (stem.rfind("case", 0) == 0 || stem == "recommended") files.push_back(p.string());
  }
  // By name, recommended.json last: case01 ... case16 is the report's order.
  std::sort(files.begin(), files.end(), [](const std::string& a, const std::string& b) {
    const bool ra = stem_of(a) == "recommended", rb = stem_of(b) == "recommended";
    return ra != rb ? rb : stem_of(a) < stem_of(b);
  });
  if (files.empty()) throw InputError({scene_dir + ": no case*.json or recommended.json scenes"});
  if (selected.empty()) return files;
  std::set<std::string> wanted;
  for (std::string s : selected) {
    if (s.size() > 5 && s.compare(s.size() - 5, 5, ".json") == 0) s.resize(s.size() - 5);
    wanted.insert(s);
  }
  std::vector<std::string> chosen;
  for (const auto& f : files)
    if (wanted.erase(stem_of(f))) chosen.push_back(f);
  if (!wanted.empty()) {
    std::string available;
    for (const auto& f : files) available += (available.empty() ? "" : ", ") + stem_of(f);
    std::vector<std::string> problems;
    for (const auto& w : wanted)
      problems.push_back(scene_dir + ": no case '" + w + "' (available: " + available + ")");
    throw InputError(problems);
  }
  return chosen;
}

int run_study(const StudyOptions& options) {
  const std::vector<std::string> files = study_scene_files(options.scene_dir, options.cases);
  // Every scene is read before anything runs, so a typo in the last case does not surface hours
  // into the study.
  std::vector<Scene> scenes;
  std::vector<std::string> problems;
  for (const auto& f : files) {
    const PatchOrigins origins = cli::set_origins(f, options.patches);
    try {
      Json document = load_scene_document(f);
      for (const Json& patch : options.patches) document.merge_patch(patch);
      scenes.push_back(read_scene(document, f));
      for (const std::string& w : origins.attribute(scenes.back().warnings))
        std::cerr << "mpm study: warning: " << w << '\n';
      scenes.back().output.snapshots = false;  // the study needs the ledger only; VTUs are GBs
    } catch (const InputError& e) {
      const InputError attributed = origins.attribute(e);
      problems.insert(problems.end(), attributed.problems().begin(), attributed.problems().end());
    }
  }
  if (!problems.empty()) throw InputError(problems);

  const int procs = std::max(1, omp_get_num_procs());
  const int threads = options.threads < 1 ? procs : std::min(options.threads, procs);
  if (threads < options.threads)
    std::cerr << "mpm study: " << options.threads << " threads requested, " << procs
              << " processors available: using " << threads << '\n';

  const fs::path out(options.out_dir);
  create_output_directory(out);
  Json record = Json::array();
  std::vector<std::string> failed;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const std::string name = stem_of(files[i]);
    const fs::path dir = out / name;
    fs::create_directories(dir);
    // A stale summary or history from an earlier study must not pass for this run's.
    fs::remove(dir / "summary.json");
    fs::remove(dir / "history.csv");
    std::cerr << "mpm study: case " << name << " (" << i + 1 << " of " << scenes.size() << ", "
              << threads << " threads) -> " << dir.string() << '\n';
    const auto t0 = std::chrono::steady_clock::now();
    int code = 0;
    std::string message;
    try {
      RunOptions run_options;
      run_options.out_dir = dir.string();
      run_options.threads = threads;
      run_options.progress = options.progress;
      code = run(scenes[i], run_options);
    } catch (const std::exception& e) {  // e.g. a model that cannot be built: not a SolverFailure
      code = 3;
      message = e.what();
      std::cerr << "mpm study: case " << name << " failed: " << message << '\n';
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!fs::exists(dir / "summary.json")) {  // run() did not get as far as its summary
      write_file_atomically(dir / "summary.json", [&](std::ostream& o) {
        o << Json{{"status", "failed"}, {"message", message}, {"wall_time [s]", wall}}.dump(2)
          << '\n';
      });
    } else if (code != 0) {
      std::ifstream in(dir / "summary.json");
      const Json summary = Json::parse(in, nullptr, false);
      if (summary.is_object()) message = summary.value("message", "");
    }
    const std::string status = code == 0 ? "completed" : "failed";
    if (code != 0) failed.push_back(name);
    std::cerr << "mpm study: case " << name << " " << status << " in " << wall << " s\n";
    record.push_back({{"case", name},
                      {"scene", files[i]},
                      {"status", status},
                      {"exit_code", code},
                      {"message", message},
                      {"wall_time [s]", wall}});
  }
  const Json study = {
      {"scene_directory", options.scene_dir}, {"threads", threads}, {"cases", record}};
  write_file_atomically(out / "study.json", [&](std::ostream& o) { o << study.dump(2) << '\n'; });
  std::cerr << "mpm study: " << scenes.size() - failed.size() << " of " << scenes.size()
            << " cases completed";
  for (std::size_t i = 0; i < failed.size(); ++i)
    std::cerr << (i ? ", " : "; failed: ") << failed[i];
  std::cerr << '\n';
  run_plot(out, options.plot);
  return failed.empty() ? 0 : 3;
}

}  // namespace impact::mpm
