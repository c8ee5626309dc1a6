// One measured stress-strain curve in the project's experiment format (docs/fitting.md, "Data
// format"): a CSV with "# key: value" header lines (test type, strain rate [1/s], temperature [K],
// strain and stress measures, source) and two columns, strain and stress [Pa].
//
// The reader converts every curve to true plastic strain and true stress (positive in tension and
// in compression), and says what it did in `conversions`:
//   engineering -> true: tension eps = ln(1 + e), sigma = s (1 + e); compression (magnitudes)
//                        eps = -ln(1 - e), sigma = s (1 - e);
//   total -> plastic:    eps_p = eps - sigma / E (E from the header or the fit's material);
//   points with eps_p <= 0 (the elastic part) are dropped; tension tests stop at the maximum
//   (engineering) stress, where necking starts.
// Every problem is an InputError naming the file and the line (and, for a data cell, the column);
// a suspicious but possible value (a temperature below 50 K: degC?) is a warning in `warnings`.
#pragma once

#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "models/core/input.hpp"

namespace impact::pointdriver::fit {

enum class TestType { uniaxial_compression, uniaxial_tension };
enum class StrainMeasure { true_plastic, true_total, engineering_total };
enum class StressMeasure { true_stress, engineering };
/// How the test is run through the driver: `automatic` = adiabatic at or above the fit's rate
/// threshold, isothermal below it.
enum class ThermalMode { automatic, isothermal, adiabatic };

struct Experiment {
  std::string file;  ///< as given
  std::string name;  ///< the file stem
  TestType type = TestType::uniaxial_compression;
  double strain_rate = 0.0;  ///< nominal [1/s], > 0
  double temperature = 0.0;  ///< initial [K]
  StrainMeasure strain_measure = StrainMeasure::true_plastic;
  StressMeasure stress_measure = StressMeasure::true_stress;
  ThermalMode thermal = ThermalMode::automatic;
  double weight = 1.0;
  std::string source;
  std::string converted_from;
  std::optional<double> youngs_modulus;  ///< from the header [Pa]
  std::vector<double> plastic_strain;    ///< true plastic strain [-], increasing
  std::vector<double> stress;            ///< true stress [Pa], > 0
  std::vector<std::string> conversions;  ///< what the reader did, for the report
  /// Admissible but suspicious values, "file:line: why" (a temperature that looks like degC);
  /// the command line prints them.
  std::vector<std::string> warnings;
};

std::string to_string(TestType);
std::string to_string(StrainMeasure);
std::string to_string(StressMeasure);
std::string to_string(ThermalMode);

/// Reads an experiment file. `youngs_modulus` [Pa] is used to remove the elastic strain of a
/// total-strain curve when the file gives none (an error if neither is available).
Experiment read_experiment(const std::string& file,
                           std::optional<double> youngs_modulus = std::nullopt);

/// The same from a stream; `file` names it in messages.
Experiment parse_experiment(std::istream& in, const std::string& file,
                            std::optional<double> youngs_modulus = std::nullopt);

}  // namespace impact::pointdriver::fit
