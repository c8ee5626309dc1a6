// material_check FILE [--set JSON]: validates a material file and prints the resolved parameters,
// or every input problem (file, JSON key path, expectation) with exit code 2. Warnings (a likely
// unit slip) go to stderr and do not change the exit code.
#include <cstring>
#include <iostream>
#include <vector>

#include "models/material/material.hpp"

int main(int argc, char** argv) {
  const char* usage =
      "usage: material_check MATERIAL.json [--set JSON_MERGE_PATCH]\n"
      "Validates a material file and prints its resolved parameters (SI units).\n"
      "Exit codes: 0 valid, 1 usage error, 2 input error.\n";
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    std::cout << usage;
    return argc < 2 ? 1 : 0;
  }
  std::vector<impact::Json> patches;  // applied in order; kept apart so nulls delete keys
  for (int i = 2; i < argc; ++i) {
    if (std::strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
      try {
        patches.push_back(impact::Json::parse(argv[++i]));
      } catch (const impact::Json::parse_error& e) {
        std::cerr << "material_check: --set: invalid JSON: " << e.what() << '\n';
        return 1;
      }
    } else {
      std::cerr << "material_check: unknown option '" << argv[i] << "'\n" << usage;
      return 1;
    }
  }
  try {
    const impact::Material m = impact::load_material(argv[1], patches);
    for (const auto& w : m.warnings) std::cerr << "material_check: warning: " << w << '\n';
    std::cout << impact::to_json(m).dump(2) << '\n';
    return 0;
  } catch (const impact::InputError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  }
}
