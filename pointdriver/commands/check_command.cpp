// pointdriver check CHECK.json: a parameter set against measured curves, with tolerances (for
// users' CI): per-curve RMS, max and mean signed errors, overlay figures, exit 3 when a tolerance
// is exceeded.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "pointdriver/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/fit_report.hpp"
#include "pointdriver/fit/strength_fit.hpp"
#include "pointdriver/output/junit.hpp"

namespace impact::pointdriver {

namespace {

namespace fs = std::filesystem;

const char* check_help =
    "usage: pointdriver check CHECK.json [--out DIR] [--no-figures] [--junit FILE]\n"
    "Runs the material of CHECK.json on every data curve through the driver's uniaxial-stress\n"
    "path and prints per-curve errors (model - data): RMS, max, mean signed, in MPa and % of the\n"
    "curve's mean stress. Writes DIR/check_report.json and one overlay figure per temperature\n"
    "group (DIR/check_<T>K.png). DIR: --out, else output.directory (default: check).\n"
    "--junit FILE: one JUnit test case per curve (failed when one of its tolerances is exceeded)\n"
    "and one for the overall RMS.\n"
    "Exit codes: 0 within every tolerance, 1 usage, 2 input error, 3 a tolerance exceeded.\n";

}  // namespace

int command_check(const std::vector<std::string>& args) {
  Options o;
  if (const auto exit_code = parse_command(
          "check", check_help, o, args, {{"--out", 1}, {"--no-figures", 0}, {"--junit", 1}}, 1)) {
    return *exit_code;
  }
  if (o.positional.size() != 1) {
    std::cerr << "pointdriver check: expected one CHECK.json\n" << check_help;
    return 1;
  }
  try {
    fit::CheckConfig config = fit::read_check_config(o.positional[0]);
    for (const auto& w : config.warnings) std::cerr << "pointdriver check: warning: " << w << '\n';
    if (o.has("--out")) config.output_directory = o.get("--out", "check");
    if (o.has("--no-figures")) config.figures = false;
    fs::create_directories(config.output_directory);
    const fit::CurveModel model =
        fit::make_curve_model(config.material_file, config.overrides, config.data, config.curves);
    for (const auto& e : model.experiments()) {
      for (const auto& w : e.warnings) std::cerr << "pointdriver check: warning: " << w << '\n';
    }
    const auto curves = model.curves({fit::law_values(model.base().flow_stress)});
    std::vector<fit::CurveErrors> errors;
    for (std::size_t e = 0; e < model.experiments().size(); ++e) {
      std::vector<double> v;
      for (double x : model.experiments()[e].plastic_strain)
        v.push_back(fit::interpolate_stress(curves[0][e], x));
      errors.push_back(fit::curve_errors(model.experiments()[e], v, model.adiabatic(e)));
      if (!curves[0][e].completed)
        std::cerr << "WARNING: " << model.experiments()[e].name
                  << ": the driver run did not complete (points past the last solved step are "
                     "compared with its stress): "
                  << curves[0][e].error << '\n';
    }
    std::cout << "check of " << config.material_file << " against " << errors.size()
              << " curves (model - data):\n";
    fit::print_errors(std::cout, errors);
    // Tolerances.
    Json failures = Json::array();
    std::vector<JunitCase> junit;
    const auto& t = config.tolerance;
    for (const auto& c : errors) {
      const std::size_t before = failures.size();
      auto test = [&](const char* what, std::optional<double> limit, double value, const char* unit,
                      double scale) {
        if (limit && value > *limit) {
          std::ostringstream s;
          s << c.name << ": " << what << ' ' << value / scale << ' ' << unit << " exceeds "
            << *limit / scale << ' ' << unit;
          failures.push_back(s.str());
        }
      };
      test("RMS", t.rms, c.rms, "MPa", 1e6);
      test("max", t.max, c.max, "MPa", 1e6);
      test("|mean signed|", t.mean_signed, std::abs(c.mean_signed), "MPa", 1e6);
      test("RMS", t.rms_percent, c.rms_percent(), "%", 1.0);
      std::ostringstream what;
      what << "RMS " << c.rms / 1e6 << " MPa (" << c.rms_percent() << " %), max " << c.max / 1e6
           << " MPa, mean signed " << c.mean_signed / 1e6 << " MPa";
      std::optional<std::string> failed;
      for (std::size_t k = before; k < failures.size(); ++k)
        failed = failed.value_or("") + (k > before ? "; " : "") + failures[k].get<std::string>();
      junit.push_back(
          {c.name, "check." + fs::path(config.file).stem().string(), 0.0, failed, what.str()});
    }
    const auto all = fit::overall(errors);
    if (config.overall_rms && all.rms > *config.overall_rms) {
      std::ostringstream s;
      s << "overall RMS " << all.rms / 1e6 << " MPa exceeds " << *config.overall_rms / 1e6
        << " MPa";
      failures.push_back(s.str());
    }
    if (config.overall_rms) {
      std::ostringstream s;
      s << "overall RMS " << all.rms / 1e6 << " MPa, limit " << *config.overall_rms / 1e6 << " MPa";
      junit.push_back({"overall RMS", "check." + fs::path(config.file).stem().string(), 0.0,
                       all.rms > *config.overall_rms ? std::optional(s.str()) : std::nullopt,
                       s.str()});
    }
    if (o.has("--junit"))
      write_junit(o.get("--junit", ""), "pointdriver check " + config.file, junit);
    // The verdict goes to stderr, so that a CI log shows it beside any error.
    for (const auto& f : failures) std::cerr << "EXCEEDED: " << f.get<std::string>() << '\n';
    std::cerr << (failures.empty() ? "all within tolerance\n" : "tolerance exceeded\n");
    const fs::path dir = config.output_directory;
    Json report = {{"configuration", config.file},
                   {"material", config.material_file},
                   {"curves", fit::errors_json(errors)},
                   {"overall", {{"rms [Pa]", all.rms}, {"max [Pa]", all.max}}},
                   {"exceeded", failures},
                   {"passed", failures.empty()}};
    std::ofstream(dir / "check_report.json") << report.dump(2) << '\n';
    if (config.figures) {
      try {
        fit::write_figures(config.output_directory, "check", model.experiments(), curves[0], {},
                           fs::path(config.material_file).filename().string(), "");
      } catch (const std::runtime_error& e) {
        std::cerr << "pointdriver check: " << e.what() << '\n';
      }
    }
    return failures.empty() ? 0 : 3;
  } catch (const InputError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  } catch (const std::runtime_error& e) {  // the JUnit file could not be written
    std::cerr << "pointdriver check: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace impact::pointdriver
