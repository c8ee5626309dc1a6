// A material file (data/materials/*.json): the report's Table 1 properties plus a
// `constitutive_model` block naming every sub-model. This is the one catalogue of sub-model names:
// a name not listed here is rejected with the list of known ones.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "models/material/elastic_plastic.hpp"

namespace impact {

/// The strain rates and temperatures a material's parameters were fitted on (`fitted_range`):
/// outside them the law extrapolates its fit (mpm run warns once per material at start when a
/// scene's nominal strain rate or initial temperature lies outside, docs/models.md).
struct FittedRange {
  double strain_rate_min = 0.0, strain_rate_max = 0.0;  ///< [1/s]
  double temperature_min = 0.0, temperature_max = 0.0;  ///< [K]
};

struct Material {
  std::string name;
  std::string file;                   ///< where it was read from (for messages)
  double thermal_conductivity = 0.0;  ///< [W/(m K)]; carried for completeness, unused (adiabatic)
  ElasticPlastic model;
  std::optional<FittedRange> fitted_range;  ///< absent: not stated
  /// Admissible but suspicious values ("file: /key/path: why"), e.g. a likely unit slip; the
  /// reader does not print them, the command line does.
  std::vector<std::string> warnings;
};

/// Validates a material document; every problem is collected and thrown as one InputError whose
/// lines name `file` and the JSON key path. With `keys`, every key the reader asks for is
/// recorded there (models/material/material_keys.hpp); nullptr, the default, records nothing.
Material read_material(const Json& document, const std::string& file,
                       InputKeyRecorder* keys = nullptr);

/// Loads a material file and applies `overrides` as an RFC 7396 JSON merge patch before validation
/// (how a scene or a path file changes a material inline).
Material load_material(const std::string& file, const Json& overrides = Json::object());

/// As above with several merge patches applied in order (a null in a patch deletes that key, so a
/// patch can remove a required value and the validator reports it).
Material load_material(const std::string& file, const std::vector<Json>& patches);

/// The resolved parameters as JSON (for `material_check` and copies of resolved inputs).
Json to_json(const Material& material);

}  // namespace impact
