// What `pointdriver fit` and `pointdriver check` write: the printed tables, the JSON report, the
// fitted material file (the input material document with the fitted flow_stress values merged
// in) and the overlay figures (one per temperature group, drawn by pointdriver/fit/fit_plot.py).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "pointdriver/fit/curve_model.hpp"
#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/strength_fit.hpp"

namespace impact::pointdriver::fit {

/// Per-curve error table (RMS, max, mean signed in MPa and %).
void print_errors(std::ostream& out, const std::vector<CurveErrors>& errors);

void print_fit_report(std::ostream& out, const FitConfig& config, const StrengthFit& fit);
Json fit_report_json(const FitConfig& config, const StrengthFit& fit);
Json errors_json(const std::vector<CurveErrors>& errors);

/// The material document of `config` with the fitted Johnson-Cook values; validated by reading
/// it back (read_material). Returns the document.
Json fitted_material(const FitConfig& config, const StrengthFit& fit);

/// One figure per temperature group (temperatures within 10 K share a figure):
/// `<directory>/<prefix>_<T>K.png`. `reference` may be empty. Returns the files written, or
/// throws std::runtime_error with the plotting helper's message.
std::vector<std::string> write_figures(const std::string& directory, const std::string& prefix,
                                       const std::vector<Experiment>& experiments,
                                       const std::vector<Curve>& model,
                                       const std::vector<Curve>& reference,
                                       const std::string& model_label,
                                       const std::string& reference_label);

}  // namespace impact::pointdriver::fit
