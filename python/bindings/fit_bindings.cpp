// Fit and check from a configuration (file or document): the reports `pointdriver fit` and
// `pointdriver check` write, as JSON text, plus every curve (data, fitted and the material's set)
// so that a notebook can plot them.
#include <pybind11/stl.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "models/core/input.hpp"
#include "pointdriver/fit/curve_check.hpp"
#include "pointdriver/fit/damage_fit.hpp"
#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/fit_report.hpp"
#include "pointdriver/fit/strength_fit.hpp"
#include "python/bindings/bindings.hpp"

namespace impact::python {

namespace {

namespace fit = impact::pointdriver::fit;

Json curve_json(const fit::Curve& c) {
  return {{"plastic_strain", c.plastic_strain},
          {"stress", c.stress},
          {"temperature", c.temperature},
          {"completed", c.completed}};
}

Json experiment_json(const fit::Experiment& e) {
  return {{"name", e.name},
          {"file", e.file},
          {"strain_rate", e.strain_rate},
          {"temperature", e.temperature},
          {"plastic_strain", e.plastic_strain},
          {"stress", e.stress}};
}

/// The configuration's warnings and its experiment files' (likely unit slips), as the commands
/// print them.
template <class Config>
Json warnings_of(const Config& config, const std::vector<fit::Experiment>& experiments) {
  Json out = config.warnings;
  for (const fit::Experiment& e : experiments)
    for (const std::string& w : e.warnings) out.push_back(w);
  return out;
}

/// Strength: fit_report.json plus "fitted_material" and "curves"; damage: the damage report
/// (written to the configuration's output directory, as the command does).
std::string run_fit(const fit::FitConfig& config) {
  if (config.mode == "damage") {
    std::filesystem::create_directories(config.output_directory);
    std::ostringstream log;
    const int status = fit::run_damage_fit(config, log);
    Json report = load_json_file(
        (std::filesystem::path(config.output_directory) / "damage_fit_report.json").string());
    report["converged"] = status == 0;
    report["log"] = log.str();
    return report.dump();
  }
  fit::StrengthFit result;
  {
    py::gil_scoped_release release;
    result = fit::fit_strength(config);
  }
  Json report = fit::fit_report_json(config, result);
  report["warnings"] = warnings_of(config, result.experiments);
  report["fitted_material"] = fit::fitted_material(config, result);
  report["converged"] = result.lsq.status == 0;
  Json curves = Json::array();
  for (std::size_t e = 0; e < result.experiments.size(); ++e) {
    curves.push_back({{"data", experiment_json(result.experiments[e])},
                      {"fitted", curve_json(result.curves[0][e])},
                      {"material", curve_json(result.curves[1][e])}});
  }
  report["series"] = curves;
  return report.dump();
}

std::string run_check(const fit::CheckConfig& config) {
  fit::CurveCheck check;
  {
    py::gil_scoped_release release;
    check = fit::check_curves(config);
  }
  Json report = check.report;
  Json warnings = warnings_of(config, check.experiments);
  for (const std::string& w : check.warnings) warnings.push_back(w);
  report["warnings"] = warnings;
  Json curves = Json::array();
  for (std::size_t e = 0; e < check.experiments.size(); ++e) {
    curves.push_back({{"data", experiment_json(check.experiments[e])},
                      {"material", curve_json(check.curves[e])}});
  }
  report["series"] = curves;
  return report.dump();
}

}  // namespace

void bind_fit(py::module_& m) {
  m.def(
      "fit_file", [](const std::string& file) { return run_fit(fit::read_fit_config(file)); },
      py::arg("file"));
  m.def(
      "fit_document",
      [](const std::string& text, const std::string& label) {
        return run_fit(fit::read_fit_config(parse_json(text, label), label));
      },
      py::arg("text"), py::arg("label"));
  m.def(
      "check_file", [](const std::string& file) { return run_check(fit::read_check_config(file)); },
      py::arg("file"));
  m.def(
      "check_document",
      [](const std::string& text, const std::string& label) {
        return run_check(fit::read_check_config(parse_json(text, label), label));
      },
      py::arg("text"), py::arg("label"));
}

}  // namespace impact::python
