// FIT.json and CHECK.json (docs/fitting.md): validated with every problem reported at once, each
// naming the file and the JSON key path. Relative file names are looked up in the working
// directory, then beside the configuration file and in its parent directories; a file found
// nowhere is a problem at the key path that names it, and the material (with its overrides) is
// validated with the configuration.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "pointdriver/fit/curve_model.hpp"
#include "pointdriver/fit/experiment_data.hpp"
#include "pointdriver/fit/least_squares.hpp"

namespace impact::pointdriver::fit {

struct DataEntry {
  std::string file;  ///< resolved
  double weight = 1.0;
  /// Replace the file's header values (a test whose file states them wrongly or not in SI).
  std::optional<double> strain_rate;  ///< [1/s]
  std::optional<double> temperature;  ///< [K]
};

/// One parameter the fit may vary: in strength mode every parameter of the material's law
/// (models/flow_stress/flow_stress_law.hpp, in its order) with the law's default bounds, free by
/// default when the law gives bounds and the material's value is not 0 (a term the material
/// switches off stays off); in damage mode D1..D5. The configuration's "parameters" block
/// overrides any of it.
struct ParameterSpec {
  std::string name;
  std::string unit = "-";  ///< SI
  bool free = true;
  std::optional<double> start;  ///< given start value (else staged guess or the material's)
  double lower = 0.0;
  double upper = 1.0;
};

struct FitConfig {
  std::string file;
  std::string mode = "strength";    ///< strength | damage
  std::string material_file;        ///< resolved
  Json overrides = Json::object();  ///< merge patch over the material (includes the keys below)
  std::vector<DataEntry> data;
  std::vector<ParameterSpec> parameters;  ///< the law's (strength); D1..D5 (damage)
  std::string initial_guess = "staged";   ///< staged | start
  double room_tolerance = 10.0;           ///< [K] for the staged guess
  CurveSettings curves;
  LeastSquaresOptions solver;
  std::string output_directory = "fit";
  std::string output_material;  ///< file name in the output directory
  bool figures = true;
  /// `pointdriver fit --fail-at-bound`: exit 3 when a free parameter ends on a bound.
  bool fail_at_bound = false;
  std::vector<std::string> warnings;  ///< "file: /key/path: why", the material's included
};

struct CheckTolerance {
  std::optional<double> rms;          ///< [Pa]
  std::optional<double> max;          ///< [Pa]
  std::optional<double> mean_signed;  ///< |mean signed error| [Pa]
  std::optional<double> rms_percent;  ///< [%] of the curve's mean stress
};

struct CheckConfig {
  std::string file;
  std::string material_file;
  Json overrides = Json::object();
  std::vector<DataEntry> data;
  CurveSettings curves;
  CheckTolerance tolerance;           ///< per curve
  std::optional<double> overall_rms;  ///< [Pa]
  std::string output_directory = "check";
  bool figures = true;
  std::vector<std::string> warnings;  ///< "file: /key/path: why", the material's included
};

/// The spec of parameter `name`; null when the configuration has none such.
const ParameterSpec* find_parameter(const FitConfig& config, std::string_view name);

FitConfig read_fit_config(const std::string& file);
FitConfig read_fit_config(const Json& document, const std::string& file);
CheckConfig read_check_config(const std::string& file);
CheckConfig read_check_config(const Json& document, const std::string& file);

/// Reads every data entry (experiment files), with E from the material for total-strain curves.
std::vector<Experiment> read_experiments(const std::vector<DataEntry>& data, double youngs_modulus);

/// `name` relative to the working directory, else to the directory of `relative_to` or one of
/// its parents; `name` itself if found nowhere (the reader then reports it).
std::string resolve_file(const std::string& name, const std::string& relative_to);

/// Files matching a pattern with '*' and '?' in its last component, sorted.
std::vector<std::string> glob_files(const std::string& pattern);

}  // namespace impact::pointdriver::fit
