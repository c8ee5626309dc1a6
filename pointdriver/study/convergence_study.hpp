// Accuracy versus cost of the point driver ("Accuracy versus cost"): three paths run with
// N = 10 ... 100000 uniform steps; each run is timed and compared with the most refined run of its
// series, the observed order of convergence is fitted, and runs that cannot be solved or give
// non-finite output are marked. Comparison series use the 2004 return algorithm and the Jaumann
// rate, where methods fail.
//
// Error measures (both relative, both on the full Cauchy stress tensor in the path frame, with the
// Frobenius norm |s|^2 = sum_ij s_ij^2):
//   curve error  e = max_k |s_N(x_k) - s_ref(x_k)| / max_k |s_ref(x_k)|   (discrete max norm)
//   final error  e_end = |s_N(end) - s_ref(end)| / |s_ref(end)|
// over the K = 10 common strains x_k = (k / 10) x_end, k = 1..10, of the path's strain measure x
// (axial log strain, or the shear F_xy). Both runs are interpolated linearly in x; with uniform
// steps, x linear in time and N a multiple of 10, the x_k are output points of every run, so the
// interpolation is exact and the error is the time-integration error alone.
// The reference of a series is its most refined run that completed with finite output (the
// finest N unless the method fails there).
// Observed order: least-squares slope of log e against log dt over the asymptotic range
// N_ref / 500 <= N <= N_ref / 10 (at least 10 x the reference's step, so that the reference's own
// error biases e by at most ~10 % for a first-order method).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "models/core/input.hpp"

namespace impact::pointdriver {

struct ConvergenceSettings {
  /// Step counts, ascending, every entry a multiple of 10. The reference of a series is its most
  /// refined run that completed with finite output.
  std::vector<int> steps{10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000, 20000, 50000, 100000};
  std::string material_file;  ///< default: <source dir>/data/materials/al6061_t6.json
  int repeats_small = 5;      ///< timing repeats (best of) for N <= 1000
  int repeats_medium = 3;     ///< for 1000 < N <= 10000 (one run above)
  std::function<void(const std::string&)> progress;  ///< a line per run, when set
};

/// The step counts of --quick: 10 ... 1000.
std::vector<int> quick_convergence_steps();

struct ConvergenceRun {
  std::string path, variant;
  int steps = 0;
  double dt = 0.0;              ///< [s]
  double wall_time = 0.0;       ///< [s], best of the repeats
  double error = 0.0;           ///< curve error against the series' reference [-] (NaN: unknown)
  double final_error = 0.0;     ///< final-stress error against the series' reference [-]
  double baseline_error = 0.0;  ///< curve error against the baseline series' reference [-]
  double local_order = 0.0;     ///< log(e_prev / e) / log(dt_prev / dt) with the coarser run [-]
  double iterations_per_step = 0.0;  ///< Newton iterations of the mixed control
  double substeps_per_step = 1.0;    ///< > 1 when steps were cut back
  std::string status;                ///< ok | reference | unsolved | non_finite | failed_<cause>
  std::string message;               ///< why (unsolved runs)
};

struct ConvergenceOrder {
  std::string path, variant;
  double order = 0.0;        ///< slope of log(curve error) vs log dt [-] (NaN: < 2 points)
  double final_order = 0.0;  ///< the same for the final-stress error
  double r_squared = 0.0;    ///< of the curve-error fit
  int points = 0;
  int n_ref = 0;             ///< step count of the series' reference run (0: none completed)
  int n_min = 0, n_max = 0;  ///< fit range (step counts)
};

struct ConvergenceResult {
  std::vector<ConvergenceRun> runs;
  std::vector<ConvergenceOrder> orders;
};

/// The paths and series of the study, for the docs: (path, variant, description).
struct ConvergenceSeries {
  std::string path, variant, description;
};
std::vector<ConvergenceSeries> convergence_series();

/// Runs the study (serially: each run is timed alone). Throws InputError on a bad material file.
ConvergenceResult run_convergence_study(const ConvergenceSettings& settings);

/// convergence.csv: path, variant, steps, dt [s], wall time [s], error [-], status, and the
/// other measures.
void write_convergence_csv(const ConvergenceResult& result, const std::string& file);

/// convergence_orders.csv: path, variant, reference steps, order [-], final stress order [-],
/// r squared [-], fit steps min, fit steps max, points.
void write_convergence_orders_csv(const ConvergenceResult& result, const std::string& file);

/// The measured tables (per path, and the orders) as Markdown.
std::string convergence_markdown(const ConvergenceResult& result);

}  // namespace impact::pointdriver
