// pointdriver fit FIT.json: flow-stress parameters (any law, by name) from measured curves, through
// the driver (pointdriver/fit/, docs/fitting.md).
#include <filesystem>
#include <iostream>

#include "pointdriver/commands/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/fit/damage_fit.hpp"
#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/fit_report.hpp"
#include "pointdriver/fit/strength_fit.hpp"
#include "support/atomic_file.hpp"

namespace impact::pointdriver {

namespace {

namespace fs = std::filesystem;

const CommandSpec fit_command{
    "fit",
    "Fits the material's flow-stress law to measured curves (docs/fitting.md).\n"
    "mode \"strength\": the law's free parameters by name (Johnson-Cook: staged initial guess\n"
    "A, B, n; C; m; other laws start from the file), then GSL multifit_nlinear (LM with\n"
    "geodesic acceleration) whose residuals are the stress errors of the driver's uniaxial-stress\n"
    "path for each test (elasticity; adiabatic heating at and above adiabatic_above_rate).\n"
    "mode \"damage\": D1..D5 from fracture strains (eq. 7, constant triaxiality).\n"
    "Prints the report and writes DIR/fit_report.json, DIR/<material>_fitted.json (a material\n"
    "file the driver and MPM read) and one figure per temperature group (DIR/fit_<T>K.png).\n"
    "DIR: --out, else output.directory of FIT.json (default: fit).",
    "FIT.json", 1,
    "A free parameter that ends on one of its bounds is flagged in the report (AT LOWER/UPPER\n"
    "BOUND, fit_report.json parameters_at_bounds) and warned about; a start value on or outside\n"
    "its bounds is moved inside with a warning.\n"
    "Exit codes: 0 done, 1 usage, 2 input error, 3 the fit did not converge, an output could not\n"
    "be written (or, with --fail-at-bound, a free parameter ended on a bound).\n"};

}  // namespace

int command_fit(const std::vector<std::string>& args) {
  Options o;
  if (const auto exit_code = parse_command(
          fit_command, o, args,
          {{"-o|--out", 1, "output directory", "DIR"},
           {"--set", 1, "JSON merge patch over FIT.json (repeatable)", "JSON"},
           {"--no-figures", 0, "no overlay figures"},
           {"--fail-at-bound", 0, "exit 3 when a free parameter ends on one of its bounds"}})) {
    return *exit_code;
  }
  if (o.positional.size() != 1) {
    std::cerr << "pointdriver fit: expected one FIT.json (pointdriver fit --help)\n";
    return 1;
  }
  std::vector<Json> patches;
  try {
    patches = cli::patches_of(o.all("--set"));
    const Json document = patched_json_file(o.positional[0], patches);
    if (o.verbosity.verbose) std::cerr << document.dump(2) << '\n';
    fit::FitConfig config = fit::read_fit_config(document, o.positional[0]);
    for (const auto& w : cli::set_origins(o.positional[0], patches).attribute(config.warnings))
      std::cerr << "pointdriver fit: warning: " << w << '\n';
    if (o.has("--out")) config.output_directory = o.get("--out", "fit");
    if (o.has("--no-figures")) config.figures = false;
    if (o.has("--fail-at-bound")) config.fail_at_bound = true;
    create_output_directory(config.output_directory);
    if (config.mode == "damage") return fit::run_damage_fit(config, std::cout);
    const fit::StrengthFit result = fit::fit_strength(config);
    for (const auto& e : result.experiments) {
      for (const auto& w : e.warnings) std::cerr << "pointdriver fit: warning: " << w << '\n';
    }
    // Also on stderr, where a CI log or a user redirecting the report sees them.
    for (const auto& w : result.start_warnings)
      std::cerr << "pointdriver fit: warning: " << w << '\n';
    const std::vector<std::string> at_bound = result.at_bound_messages();
    for (const auto& m : at_bound) std::cerr << "pointdriver fit: warning: " << m << '\n';
    fit::print_fit_report(std::cout, config, result);
    const fs::path dir = config.output_directory;
    const Json report = fit::fit_report_json(config, result);
    const Json material = fit::fitted_material(config, result);
    write_file_atomically(dir / "fit_report.json",
                          [&](std::ostream& out) { out << report.dump(2) << '\n'; });
    write_file_atomically(dir / config.output_material,
                          [&](std::ostream& out) { out << material.dump(2) << '\n'; });
    std::cout << "wrote " << (dir / "fit_report.json").string() << ", "
              << (dir / config.output_material).string() << '\n';
    if (config.figures) {
      try {
        fit::write_figures(
            config.output_directory, "fit", result.experiments, result.curves[0], result.curves[1],
            "fitted",
            "material's set (" + fs::path(config.material_file).filename().string() + ")");
      } catch (const OutputError&) {
        throw;
      } catch (const std::runtime_error& e) {  // no python3 or matplotlib: the figures only
        std::cerr << "pointdriver fit: " << e.what() << '\n';
      }
    }
    if (result.lsq.status != 0) return cli::kExitFailed;
    if (config.fail_at_bound && !at_bound.empty()) {
      std::cerr << "pointdriver fit: " << at_bound.size()
                << " parameter(s) ended on a bound (--fail-at-bound): exit 3\n";
      return cli::kExitFailed;
    }
    return 0;
  } catch (const InputError& e) {
    std::cerr << cli::set_origins(o.positional[0], patches).attribute(e).what() << '\n';
    return cli::kExitInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "pointdriver fit: " << e.what() << '\n';
    return cli::kExitInput;
  } catch (const OutputError& e) {
    std::cerr << "pointdriver fit: " << e.what() << '\n';
    return cli::kExitFailed;
  }
}

}  // namespace impact::pointdriver
