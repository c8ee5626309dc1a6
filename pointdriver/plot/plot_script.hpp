// Running the plotting helper pointdriver/plot/plot.py (python3 + matplotlib) from C++:
// `pointdriver plot` hands its arguments over; `pointdriver convergence` and `verify` and the fit
// report (fit/fit_report.cpp) draw their figures with it.
#pragma once

#include <string>
#include <vector>

namespace impact::pointdriver {

/// The command that installs what the plots need (printed when python3 or matplotlib is missing).
inline constexpr const char* plot_install_hint = "apt-get install -y python3 python3-matplotlib";

/// plot.py: $POINTDRIVER_PLOT_SCRIPT when set, else <source dir>/pointdriver/plot/plot.py.
std::string plot_script_path();

/// How a plot.py run ended.
struct PlotRun {
  enum class Status {
    ok,
    no_python,      ///< python3 could not be started
    no_matplotlib,  ///< python3 runs but cannot import matplotlib
    no_script,      ///< plot.py not found
    usage_error,    ///< plot.py refused its arguments (a figure name without .png/.pdf/.svg): 1
    input_error,    ///< plot.py rejected the input (missing file or column): exit 2
    output_error,   ///< a figure or stdout could not be written: exit 3
    stopped,        ///< Ctrl-C (130) or stdout closed by its reader (141, `| head`)
    failed          ///< any other non-zero exit
  } status = Status::ok;
  int exit_code = 0;
  std::string message;  ///< for the user, with the fix where there is one
};

/// Whether the script said why it ended on its own stderr (usage, input and output errors, one
/// line each; stopped: Ctrl-C, or nothing when stdout's reader went away): `message` would only
/// repeat it with less.
bool said_why(const PlotRun& run);

/// Runs `python3 plot.py args...` (no shell: arguments are passed as they are; the interpreter
/// by support/python_launcher.hpp's rule), with plot.py's output going to this process's
/// stdout/stderr; with `script_stdout` false its stdout is passed on through std::cout, so that a
/// stdout that cannot take it fails once, under the caller's name (pointdriver verify: the
/// script's lines on a full stdout failed as "pointdriver plot" before verify's own).
PlotRun run_plot_script(const std::vector<std::string>& args, bool script_stdout = true);

/// The exit code of a command whose result is the figure: 0 drawn, 1 python3, matplotlib or
/// plot.py missing or a usage error, 2 input error, 3 a figure or stdout not written (or plot.py
/// failed otherwise), 130 and 141 as plot.py ended (Ctrl-C; stdout closed by its reader).
int plot_exit_code(const PlotRun& run);

}  // namespace impact::pointdriver
