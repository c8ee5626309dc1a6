// material_check MATERIAL.json [--set JSON]...: validates a material file and prints the resolved
// parameters, or every input problem (file, JSON key path, expectation) with exit code 2.
// material_check --keys [--format md|json]: every key the material reader asks for, with its
// type, range, default and meaning (models/material/material_keys.hpp; docs/models.md).
// Warnings (a likely unit slip) go to stderr and do not change the exit code. The command line
// follows the programs' convention (support/command_line.hpp; the library itself does not use it).
#include <iostream>
#include <string>
#include <vector>

#include "models/material/material.hpp"
#include "models/material/material_keys.hpp"
#include "support/command_line.hpp"

int main(int argc, char** argv) {
  impact::cli::report_file_size_limits();
  CLI::App app{"Validates a material file and prints its resolved parameters (SI units).",
               "material_check"};
  impact::cli::Verbosity verbosity;
  std::string file;
  std::vector<std::string> patches;
  bool keys = false;
  std::string keys_format = "md";
  CLI::Option* material = app.add_option("MATERIAL.json", file, "material file (docs/models.md)");
  CLI::Option* keys_flag =
      app.add_flag("--keys", keys, "list the material keys instead: type, range, default, meaning");
  app.add_option("--format", keys_format, "with --keys: md (a Markdown table) or json")
      ->check(CLI::IsMember({"md", "json"}))
      ->needs(keys_flag);
  keys_flag->excludes(material);
  keys_flag->excludes(impact::cli::add_set(app, patches, "the material"));
  impact::cli::describe(
      app, "Exit codes: 0 valid, 1 usage error, 2 input error, 3 the output could not be written.",
      verbosity);
  if (const auto code = impact::cli::parse(app, argc, argv, verbosity))
    return impact::cli::stdout_checked(*code, "material_check");  // --help > /dev/full: exit 3
  if (keys) {
    try {
      const impact::InputKeyRecorder recorded = impact::material_keys();
      if (keys_format == "json") {
        std::cout << impact::keys_json(recorded.keys(), "").dump(2) << '\n';
      } else {
        std::cout << impact::keys_markdown(recorded.keys(), "");
      }
    } catch (const impact::InputError& e) {  // a sample material refused: a bug, reported as input
      std::cerr << e.what() << '\n';
      return 2;
    }
    return impact::cli::stdout_checked(0, "material_check");
  }
  if (file.empty()) {  // CLI11's words for a missing required positional: it is one without --keys
    std::cerr << "material_check: MATERIAL.json is required\nRun 'material_check --help' for the "
                 "options.\n";
    return impact::cli::kExitUsage;
  }
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
