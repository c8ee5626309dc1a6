// The forward model of the fit: each experiment is run as the driver's named `uniaxial_stress` path
// (compression or tension at the test's rate and initial temperature; elasticity, the material's
// equation of state and, for adiabatic tests, heating with the material's Taylor-Quinney chi), and
// the computed true stress is read at the data's plastic strains by linear interpolation in
// eps_p. So the model that is fitted is the model users run.
//
// Every parameter set is one ElasticPlastic built from the material with its flow-stress law's
// parameters replaced by name (any law of models/flow_stress/flow_stress_law.hpp); N parameter
// sets x M experiments are run in one run_batch call (threads).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "models/material/elastic_plastic.hpp"
#include "pointdriver/driver/driver.hpp"
#include "pointdriver/fit/experiment_data.hpp"
#include "pointdriver/path/path.hpp"

namespace impact::pointdriver::fit {

/// Every parameter of a flow-stress law, in parameter_names(law) order
/// (models/flow_stress/flow_stress_law.hpp).
using ParameterValues = std::vector<double>;
ParameterValues law_values(const FlowStressLaw& law);

/// Johnson-Cook strength parameters in the order A [Pa], B [Pa], n, C, m (the staged guess's).
using JcValues = std::array<double, 5>;
inline constexpr std::array<const char*, 5> jc_names{"A", "B", "n", "C", "m"};

/// The law's values of jc_names, by name.
JcValues jc_values(const FlowStressLaw& law);

struct CurveSettings {
  int steps = 60;                      ///< driver steps per test (log-spaced, see first_step)
  double first_step_fraction = 2e-3;   ///< first step / path duration (steps grow geometrically)
  double adiabatic_above_rate = 10.0;  ///< automatic tests at or above this rate are adiabatic
  int threads = 0;                     ///< 0: all cores
};

/// One computed curve: every row of the run.
struct Curve {
  std::vector<double> plastic_strain;  ///< [-]
  std::vector<double> stress;          ///< |sigma_xx| [Pa]
  std::vector<double> temperature;     ///< [K]
  bool completed = false;
  std::string error;
};

/// Linear interpolation of the stress at plastic strain x over the plastic rows (eps_p > 0);
/// linear extrapolation from the end segments outside them; the last stress if the curve has
/// fewer than two plastic rows.
double interpolate_stress(const Curve& curve, double x);

class CurveModel {
 public:
  /// `material_file` with the merge patch `overrides` (the fit adds erosion "none": a failure
  /// criterion must not cut a strength curve short); one path per experiment.
  CurveModel(const std::string& material_file, const Json& overrides,
             std::vector<Experiment> experiments, const CurveSettings& settings);

  const std::vector<Experiment>& experiments() const { return experiments_; }
  const ElasticPlasticParams& base() const { return base_; }
  const CurveSettings& settings() const { return settings_; }
  bool adiabatic(std::size_t experiment) const;
  double youngs_modulus() const;

  /// The material's law's parameter names (the order of ParameterValues).
  const std::vector<std::string>& parameter_names() const { return names_; }
  /// The material with the given values of every parameter of its law.
  ElasticPlastic model(const ParameterValues& values) const;

  /// Curves of every experiment for every parameter set: [set][experiment].
  std::vector<std::vector<Curve>> curves(const std::vector<ParameterValues>& sets) const;

  /// The model stress at each experiment's data points: [set][experiment][point] [Pa].
  std::vector<std::vector<std::vector<double>>> predict(
      const std::vector<ParameterValues>& sets) const;

 private:
  std::vector<Experiment> experiments_;
  CurveSettings settings_;
  ElasticPlasticParams base_;
  std::vector<std::string> names_;
  std::vector<Path> paths_;
};

}  // namespace impact::pointdriver::fit
