// pointdriver check CHECK.json: a parameter set against measured curves, with tolerances (for
// users' CI): per-curve RMS, max and mean signed errors, overlay figures, exit 3 when a tolerance
// is exceeded.
#include <filesystem>
#include <iostream>

#include "pointdriver/commands/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/fit/curve_check.hpp"
#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/fit_report.hpp"
#include "pointdriver/output/junit.hpp"
#include "support/atomic_file.hpp"

namespace impact::pointdriver {

namespace {

namespace fs = std::filesystem;

const CommandSpec check_command{
    "check",
    "Runs the material of CHECK.json on every data curve through the driver's uniaxial-stress\n"
    "path and prints per-curve errors (model - data): RMS, max, mean signed, in MPa and % of the\n"
    "curve's mean stress. Writes DIR/check_report.json and one overlay figure per temperature\n"
    "group (DIR/check_<T>K.png). DIR: --out, else output.directory (default: check).\n"
    "--junit FILE: one JUnit test case per curve (failed when one of its tolerances is exceeded)\n"
    "and one for the overall RMS.",
    "CHECK.json", 1,
    "Exit codes: 0 within every tolerance, 1 usage, 2 input error, 3 a tolerance exceeded or an\n"
    "output could not be written.\n"};

}  // namespace

int command_check(const std::vector<std::string>& args) {
  Options o;
  if (const auto exit_code =
          parse_command(check_command, o, args,
                        {{"-o|--out", 1, "output directory", "DIR"},
                         {"--set", 1, "JSON merge patch over CHECK.json (repeatable)", "JSON"},
                         {"--no-figures", 0, "no overlay figures"},
                         {"--junit", 1, "one JUnit test case per curve", "FILE"}})) {
    return *exit_code;
  }
  if (o.positional.size() != 1) {
    std::cerr << "pointdriver check: expected one CHECK.json (pointdriver check --help)\n";
    return 1;
  }
  std::vector<Json> patches;
  try {
    patches = cli::patches_of(o.all("--set"));
    const Json document = patched_json_file(o.positional[0], patches);
    if (o.verbosity.verbose) std::cerr << document.dump(2) << '\n';
    fit::CheckConfig config = fit::read_check_config(document, o.positional[0]);
    for (const auto& w : cli::set_origins(o.positional[0], patches).attribute(config.warnings))
      std::cerr << "pointdriver check: warning: " << w << '\n';
    if (o.has("--out")) config.output_directory = o.get("--out", "check");
    if (o.has("--no-figures")) config.figures = false;
    create_output_directory(config.output_directory);
    const fit::CurveCheck check = fit::check_curves(config);
    for (const auto& e : check.experiments) {
      for (const auto& w : e.warnings) std::cerr << "pointdriver check: warning: " << w << '\n';
    }
    for (const auto& w : check.warnings) std::cerr << "WARNING: " << w << '\n';
    std::cout << "check of " << config.material_file << " against " << check.errors.size()
              << " curves (model - data):\n";
    fit::print_errors(std::cout, check.errors);
    if (o.has("--junit"))
      write_junit(o.get("--junit", ""), "pointdriver check " + config.file, check.junit);
    // The verdict goes to stderr, so that a CI log shows it beside any error.
    for (const auto& f : check.exceeded) std::cerr << "EXCEEDED: " << f << '\n';
    std::cerr << (check.exceeded.empty() ? "all within tolerance\n" : "tolerance exceeded\n");
    write_file_atomically(fs::path(config.output_directory) / "check_report.json",
                          [&](std::ostream& out) { out << check.report.dump(2) << '\n'; });
    if (config.figures) {
      try {
        fit::write_figures(config.output_directory, "check", check.experiments, check.curves, {},
                           fs::path(config.material_file).filename().string(), "");
      } catch (const OutputError&) {
        throw;
      } catch (const std::runtime_error& e) {  // no python3 or matplotlib: the figures only
        std::cerr << "pointdriver check: " << e.what() << '\n';
      }
    }
    return check.exceeded.empty() ? 0 : cli::kExitFailed;
  } catch (const InputError& e) {
    std::cerr << cli::set_origins(o.positional[0], patches).attribute(e).what() << '\n';
    return cli::kExitInput;
  } catch (const std::runtime_error& e) {  // an output (report, JUnit file) cannot be written
    std::cerr << "pointdriver check: " << e.what() << '\n';
    return cli::kExitFailed;
  }
}

}  // namespace impact::pointdriver
