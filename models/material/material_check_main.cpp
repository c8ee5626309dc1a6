// material_check MATERIAL.json [--set JSON]...: validates a material file and prints the resolved
// parameters, or every input problem (file, JSON key path, expectation) with exit code 2.
// Warnings (a likely unit slip) go to stderr and do not change the exit code. The command line
// follows the programs' convention (support/command_line.hpp; the library itself does not use it).
#include <iostream>
#include <string>
#include <vector>

#include "models/material/material.hpp"
#include "support/command_line.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Validates a material file and prints its resolved parameters (SI units).",
               "material_check"};
  impact::cli::Verbosity verbosity;
  std::string file;
  std::vector<std::string> patches;
  app.add_option("MATERIAL.json", file, "material file (docs/models.md)")->required();
  impact::cli::add_set(app, patches, "the material");
  impact::cli::describe(app, "Exit codes: 0 valid, 1 usage error, 2 input error.", verbosity);
  if (const auto code = impact::cli::parse(app, argc, argv, verbosity)) return *code;
  try {
    const impact::Material m = impact::load_material(file, impact::cli::patches_of(patches));
    for (const auto& w : m.warnings) std::cerr << "material_check: warning: " << w << '\n';
    std::cout << impact::to_json(m).dump(2) << '\n';
    return 0;
  } catch (const impact::InputError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  }
}
