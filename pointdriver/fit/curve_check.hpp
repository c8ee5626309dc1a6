// A parameter set against measured curves with tolerances: what `pointdriver check` prints and
// writes, and what the Python module's impact.check returns. Each curve runs through the driver's
// uniaxial-stress path; errors are model - data at the data's plastic strains.
#pragma once

#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "pointdriver/fit/curve_model.hpp"
#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/strength_fit.hpp"
#include "pointdriver/output/junit.hpp"

namespace impact::pointdriver::fit {

struct CurveCheck {
  std::vector<Experiment> experiments;
  std::vector<Curve> curves;  ///< the material's driver curve of each experiment
  std::vector<CurveErrors> errors;
  OverallErrors overall;
  /// "name: RMS 12 MPa exceeds 10 MPa", one per tolerance exceeded (empty: passed).
  std::vector<std::string> exceeded;
  /// Driver runs that did not complete: their points past the last solved step compare with the
  /// last computed stress.
  std::vector<std::string> warnings;
  std::vector<JunitCase> junit;  ///< one case per curve, and one for the overall RMS if set
  Json report;                   ///< check_report.json
};

/// Runs the configuration's material on every curve and applies its tolerances; throws
/// InputError for bad data files.
CurveCheck check_curves(const CheckConfig& config);

}  // namespace impact::pointdriver::fit
