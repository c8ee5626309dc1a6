// `pointdriver fit` in strength mode: read the curves, start values (Johnson-Cook: the staged
// guess; any other law: the material's values or the configuration's starts), global least
// squares over the law's free parameters, by name, through the driver (curve_model.hpp,
// least_squares.hpp), errors per curve for the fitted set and for the material's own set (e.g.
// the published one).
//
// Residual: the vertical stress error at the data's plastic strains, sqrt(weight) (sigma_model -
// sigma_data) in MPa (the MPa scaling only conditions the solver; reports are in Pa and MPa).
#pragma once

#include <string>
#include <vector>

#include "pointdriver/fit/curve_model.hpp"
#include "pointdriver/fit/experiment_data.hpp"
#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/least_squares.hpp"
#include "pointdriver/fit/parameter_bounds.hpp"
#include "pointdriver/fit/staged_guess.hpp"

namespace impact::pointdriver::fit {

/// Stress errors of one curve, model minus data [Pa].
struct CurveErrors {
  std::string name;
  double temperature = 0.0;
  double strain_rate = 0.0;
  bool adiabatic = false;
  int points = 0;
  double rms = 0.0;
  double max = 0.0;  ///< largest |error|
  double mean_signed = 0.0;
  double mean_stress = 0.0;  ///< of the data
  double rms_percent() const { return mean_stress > 0 ? 100.0 * rms / mean_stress : 0.0; }
  double max_percent() const { return mean_stress > 0 ? 100.0 * max / mean_stress : 0.0; }
  double mean_signed_percent() const {
    return mean_stress > 0 ? 100.0 * mean_signed / mean_stress : 0.0;
  }
};

CurveErrors curve_errors(const Experiment& e, const std::vector<double>& model, bool adiabatic);

/// RMS and max over every point of several curves [Pa].
struct OverallErrors {
  double rms = 0.0;
  double max = 0.0;
  int points = 0;
};
OverallErrors overall(const std::vector<CurveErrors>& errors);

struct StrengthFit {
  std::vector<Experiment> experiments;
  std::vector<bool> adiabatic;
  std::string law;                    ///< the law's JSON type
  std::vector<Parameter> parameters;  ///< every parameter of the law as started (bounds, free)
  std::vector<std::string> units;     ///< SI unit of each parameter
  ParameterValues material_values;    ///< the input material's own set
  /// The staged guess (Johnson-Cook with initial_guess "staged"; otherwise not run: empty).
  StagedGuess staged;
  bool staged_run = false;
  ParameterValues start;
  /// Start values that lay on or outside their bounds and were moved inside: one message each.
  std::vector<std::string> start_warnings;
  LeastSquaresResult lsq;
  ParameterValues fitted;
  /// Per parameter: the bound a free one ended on (none for the fixed ones).
  std::vector<BoundSide> at_bound;
  /// The free parameters that ended on a bound, with at_bound_message's text.
  std::vector<std::string> at_bound_messages() const;
  std::vector<CurveErrors> errors_fitted, errors_material;
  OverallErrors overall_fitted, overall_material;
  std::vector<std::vector<Curve>> curves;  ///< [0] fitted, [1] material: full driver curves
  /// Driver runs of the final curves that did not complete (curve, set and the driver's message):
  /// their points past the last solved step compare with the last computed stress.
  std::vector<std::string> warnings;
  double wall_time = 0.0;  ///< whole command [s]
};

/// Builds the forward model of a configuration.
CurveModel make_curve_model(const std::string& material_file, const Json& overrides,
                            const std::vector<DataEntry>& data, const CurveSettings& settings);

/// Reads the configuration's data and fits.
StrengthFit fit_strength(const FitConfig& config);

/// Fits with a given forward model (its experiments); uses the configuration's parameters,
/// initial_guess, room_tolerance and solver only.
StrengthFit fit_strength(const CurveModel& model, const FitConfig& config);

}  // namespace impact::pointdriver::fit
