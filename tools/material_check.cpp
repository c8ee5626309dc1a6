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
  impact::cli::report_file_size_limits();
  CLI::App app{"Validates a material file and prints its resolved parameters (SI units).",
               "material_check"};
  impact::cli::Verbosity verbosity;
  std::string file;
  std::vector<std::string> patches;
  app.add_option("MATERIAL.json", file, "material file (docs/models.md)")->required();
  impact::cli::add_set(app, patches, "the material");
  impact::cli::describe(
      app, "Exit codes: 0 valid, 1 usage error, 2 input error, 3 the output could not be written.",
      verbosity);
  if (const auto code = impact::cli::parse(app, argc, argv, verbosity)) return *code;
  std::vector<impact::Json> parsed;  // a problem at a key a --set patch set names the patch
  try {
    parsed = impact::cli::patches_of(patches);
    const impact::Material m = impact::load_material(file, parsed);
    for (const auto& w : impact::cli::set_origins(file, parsed).attribute(m.warnings))
      std::cerr << "material_check: warning: " << w << '\n';
    std::cout << impact::to_json(m).dump(2) << '\n';
  } catch (const impact::InputError& e) {
    std::cerr << impact::cli::set_origins(file, parsed).attribute(e).what() << '\n';
    return 2;
  }
  return impact::cli::stdout_checked(0, "material_check");
}
