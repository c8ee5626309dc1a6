#include "campaigns/plot/run_plot.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

#include "support/python_launcher.hpp"
#include "support/shipped_file.hpp"

namespace impact::mpm {

namespace {

std::string run_plot_script_path() {
  if (const char* env = std::getenv("MPM_PLOT_SCRIPT"); env && *env) return env;
  return shipped_file("campaigns/plot/run_plot.py").string();
}

constexpr const char* kInstall = "apt-get install -y python3 python3-matplotlib";
constexpr int kScriptMissingMatplotlib = 4;  // run_plot.py's code

}  // namespace

int plot_run(const std::string& run, const std::string& figure) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // The reason a user can act on: no such directory, a file given for the directory, or a
  // directory without a run's history.
  if (!fs::exists(run, ec)) {
    std::cerr << "mpm plot: " << run << ": no such directory (expected a directory `mpm run` "
              << "wrote: mpm run SCENE --out DIR)\n";
    return 2;
  }
  if (!fs::is_directory(run, ec)) {
    std::cerr << "mpm plot: " << run << ": not a directory (expected the directory `mpm run` "
              << "wrote, which holds history.csv)\n";
    return 2;
  }
  if (!fs::is_regular_file(fs::path(run) / "history.csv", ec)) {
    std::cerr << "mpm plot: " << run
              << ": no history.csv (expected a directory `mpm run` wrote: mpm run SCENE --out "
                 "DIR)\n";
    return 2;
  }
  const std::string script = run_plot_script_path();
  if (!fs::is_regular_file(script, ec)) {
    std::cerr << "mpm plot: plotting script not found: " << script
              << " (set MPM_PLOT_SCRIPT to campaigns/plot/run_plot.py)\n";
    return 1;
  }
  const PythonInterpreter python = find_python();
  if (!python.matplotlib) {
    std::cerr << "mpm plot: "
              << (python.any_runs ? "python3 cannot import matplotlib" : "no python3 found")
              << " ($IMPACT_PYTHON, /usr/bin/python3, python3); install it with: " << kInstall
              << '\n';
    return 1;
  }
  std::vector<std::string> argv{python.command, script, run};
  if (!figure.empty()) argv.push_back("--out=" + figure);
  const int code = spawn_process(argv, false);
  // run_plot.py's documented codes, each after its own line (or, 141, in silence: stdout's
  // reader went away): usage, input, an output it could not write, Ctrl-C.
  if (code == 0 || code == 1 || code == 2 || code == 3 || code == 130 || code == 141) return code;
  if (code == kScriptMissingMatplotlib) {
    std::cerr << "mpm plot: matplotlib missing; install it with: " << kInstall << '\n';
    return 1;
  }
  std::cerr << "mpm plot: " << script << " exited with code " << code << '\n';
  return 3;
}

}  // namespace impact::mpm
