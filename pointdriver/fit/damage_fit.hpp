// `pointdriver fit` in damage mode: Johnson-Cook damage D1..D5 from fracture strains measured at
// constant triaxiality, rate and temperature, through report eq. 7 in closed form (at constant
// triaxiality, rate and temperature, D = eps_p / eps_f reaches 1 at eps_p = eps_f):
//   eps_f = [D1 + D2 exp(D3 eta)] [1 + D4 ln max(rate*, 1)] [1 + D5 T*]
// (models/damage/johnson_cook_damage.hpp evaluates it: the model users run). Residuals are
// eps_f(model) - eps_f(data), fitted with the same GSL least squares as the strength mode.
//
// Data: a CSV with "# source: ..." (required) and other "# key: value" lines, then the header
// `triaxiality [-],strain_rate [1/s],temperature [K],fracture_strain [-]` and one row per test.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "models/damage/johnson_cook_damage.hpp"
#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/least_squares.hpp"

namespace impact::pointdriver::fit {

struct FracturePoint {
  double triaxiality = 0.0;
  double strain_rate = 0.0;  ///< [1/s]
  double temperature = 0.0;  ///< [K]
  double fracture_strain = 0.0;
  int line = 0;
};

struct FractureData {
  std::string file;
  std::string source;
  std::vector<FracturePoint> points;
  std::vector<std::string> warnings;  ///< "file:line: why" (a temperature that looks like degC)
};

/// Reads a fracture-strain file; errors name the file and line.
FractureData read_fracture_data(const std::string& file);

/// eps_f of eq. 7 at each point with D1..D5 = `d` (other constants from `base`).
std::vector<double> fracture_strains(const JohnsonCookDamageParams& base,
                                     const std::vector<double>& d,
                                     const std::vector<FracturePoint>& points);

/// The least-squares fit of D1..D5 (`parameters`, in that order) to the points; `weights` are
/// per point (empty: all 1).
LeastSquaresResult fit_damage(const std::vector<FracturePoint>& points,
                              const JohnsonCookDamageParams& base,
                              const std::vector<Parameter>& parameters,
                              const LeastSquaresOptions& options,
                              const std::vector<double>& weights = {});

/// Runs the damage fit of `config` (mode "damage"), prints the report, writes
/// DIR/damage_fit_report.json and the fitted material. Returns the exit code.
int run_damage_fit(const FitConfig& config, std::ostream& out);

}  // namespace impact::pointdriver::fit
