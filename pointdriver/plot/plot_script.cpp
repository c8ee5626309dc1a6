// Running pointdriver/plot/plot.py: where the script is, which interpreter, what went wrong.
#include "pointdriver/plot/plot_script.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "support/python_launcher.hpp"
#include "support/shipped_file.hpp"

namespace impact::pointdriver {

std::string plot_script_path() {
  if (const char* env = std::getenv("POINTDRIVER_PLOT_SCRIPT"); env && *env) return env;
  return shipped_file("pointdriver/plot/plot.py").string();
}

PlotRun run_plot_script(const std::vector<std::string>& args, bool script_stdout) {
  PlotRun r;
  const std::string script = plot_script_path();
  if (!std::filesystem::is_regular_file(script)) {
    r.status = PlotRun::Status::no_script;
    r.message = "plotting script not found: " + script +
                " (set POINTDRIVER_PLOT_SCRIPT to the path of pointdriver/plot/plot.py)";
    return r;
  }
  const PythonInterpreter found = find_python();
  if (!found.any_runs) {
    r.status = PlotRun::Status::no_python;
    r.exit_code = 127;
    r.message = std::string("python3 is not installed; install it and matplotlib with: ") +
                plot_install_hint;
    return r;
  }
  if (!found.matplotlib) {
    r.status = PlotRun::Status::no_matplotlib;
    r.exit_code = 1;
    r.message =
        std::string("python3 cannot import matplotlib; install it with: ") + plot_install_hint;
    return r;
  }
  const std::string& python = found.command;
  std::vector<std::string> argv{python, script};
  argv.insert(argv.end(), args.begin(), args.end());
  if (script_stdout) {
    r.exit_code = spawn_process(argv, false);
  } else {
    // The script's lines through a private file into std::cout (the caller's stream).
    std::error_code ec;
    std::string pattern =
        (std::filesystem::temp_directory_path(ec) / "impact_plot_stdout_XXXXXX").string();
    char* name = pattern.data();
    const int fd = mkstemp(name);
    if (fd >= 0) close(fd);
    r.exit_code = fd >= 0 ? spawn_process(argv, false, name) : spawn_process(argv, false);
    if (fd >= 0) {
      std::ifstream lines(name);
      std::cout << lines.rdbuf();
      std::filesystem::remove(name);
    }
  }
  if (r.exit_code == 0) return r;
  switch (r.exit_code) {  // the script's documented codes
    case 1:
      r.status = PlotRun::Status::usage_error;
      break;
    case 2:
      r.status = PlotRun::Status::input_error;
      break;
    case 3:
      r.status = PlotRun::Status::output_error;
      break;
    case 130:
    case 141:
      r.status = PlotRun::Status::stopped;
      break;
    case 4:
      r.status = PlotRun::Status::no_matplotlib;
      break;
    default:
      r.status = PlotRun::Status::failed;
  }
  r.message = r.status == PlotRun::Status::no_matplotlib
                  ? std::string("matplotlib missing; install it with: ") + plot_install_hint
                  : std::filesystem::path(script).filename().string() + " exited with code " +
                        std::to_string(r.exit_code);
  return r;
}

bool said_why(const PlotRun& run) {
  using S = PlotRun::Status;
  return run.status == S::usage_error || run.status == S::input_error ||
         run.status == S::output_error || run.status == S::stopped;
}

int plot_exit_code(const PlotRun& run) {
  switch (run.status) {
    case PlotRun::Status::ok:
      return 0;
    case PlotRun::Status::input_error:
      return 2;
    case PlotRun::Status::output_error:
    case PlotRun::Status::failed:
      return 3;
    case PlotRun::Status::stopped:
      return run.exit_code;
    default:
      return 1;
  }
}

}  // namespace impact::pointdriver
