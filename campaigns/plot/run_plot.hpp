// `mpm plot RUN`: one run's energy books, energy error, momentum and observables, drawn by
// campaigns/plot/run_plot.py (python3 + matplotlib) from what `mpm run` wrote into RUN.
#pragma once

#include <string>

namespace impact::mpm {

/// Draws RUN's figure into `figure` (empty: RUN/run.png) with run_plot.py ($MPM_PLOT_SCRIPT when
/// set, else the shipped copy), the interpreter by support/python_launcher.hpp's rule. Returns
/// the exit code: 0 done, 1 no python3 or matplotlib (the install command printed) or a figure
/// name without .png, .pdf or .svg, 2 RUN is not a run directory (or the script refused it), 3
/// the figure or stdout could not be written or the script failed otherwise, 130 Ctrl-C, 141
/// stdout closed by its reader (nothing printed).
int plot_run(const std::string& run, const std::string& figure);

}  // namespace impact::mpm
