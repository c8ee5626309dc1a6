#include "pointdriver/fit/fit_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

#include "models/material/material.hpp"
#include "pointdriver/plot/plot_script.hpp"
#include "support/atomic_file.hpp"
#include "support/shipped_file.hpp"

namespace impact::pointdriver::fit {

namespace fs = std::filesystem;

namespace {

std::string num(double v, int precision = 4) {
  std::ostringstream o;
  o << std::setprecision(precision) << v;
  return o.str();
}

/// A parameter in a readable unit: stresses in MPa.
double shown(const std::string& unit, double v) {
  return unit == "Pa" ? v / 1e6 : v;
}
std::string shown_unit(const std::string& unit) {
  return unit == "Pa" ? "MPa" : unit;
}
/// The Johnson-Cook parameter k (jc_names) of a staged stage, shown.
double shown_jc(std::size_t k, double v) {
  return k < 2 ? v / 1e6 : v;
}

}  // namespace

void print_errors(std::ostream& out, const std::vector<CurveErrors>& errors) {
  out << std::left << std::setw(30) << "curve" << std::right << std::setw(7) << "T [K]"
      << std::setw(10) << "rate" << std::setw(6) << "heat" << std::setw(5) << "pts" << std::setw(10)
      << "RMS MPa" << std::setw(8) << "RMS %" << std::setw(10) << "max MPa" << std::setw(8)
      << "max %" << std::setw(11) << "mean MPa" << std::setw(8) << "mean %" << '\n';
  out << std::fixed;
  for (const auto& c : errors) {
    out << std::left << std::setw(30) << c.name << std::right << std::setw(7)
        << std::setprecision(0) << c.temperature << std::setw(10) << num(c.strain_rate, 3)
        << std::setw(6) << (c.adiabatic ? "adia" : "iso") << std::setw(5) << c.points
        << std::setprecision(2) << std::setw(10) << c.rms / 1e6 << std::setw(8) << c.rms_percent()
        << std::setw(10) << c.max / 1e6 << std::setw(8) << c.max_percent() << std::setw(11)
        << c.mean_signed / 1e6 << std::setw(8) << c.mean_signed_percent() << '\n';
  }
  out.unsetf(std::ios::floatfield);
  const OverallErrors o = overall(errors);
  out << "overall: " << o.points << " points, RMS " << num(o.rms / 1e6) << " MPa, max "
      << num(o.max / 1e6) << " MPa\n";
}

void print_fit_report(std::ostream& out, const FitConfig& config, const StrengthFit& fit) {
  out << fit.law << " strength fit: " << fit.experiments.size() << " curves, material "
      << config.material_file << "\n\n";
  if (fit.staged_run) {
    out << "Staged initial guess:\n";
    for (const auto& s : fit.staged.stages) {
      out << "  stage " << s.name << ": " << s.curves << " curves, " << s.points << " points, RMS "
          << num(s.rms / 1e6) << " MPa";
      out << "  ->";
      for (std::size_t k = 0; k < 5; ++k)
        out << ' ' << jc_names[k] << '=' << num(shown_jc(k, s.values[k]));
      out << '\n';
      if (!s.note.empty()) out << "    " << s.note << '\n';
    }
  } else {
    out << "Start: the configuration's start values, else the material's (the staged guess is "
           "Johnson-Cook's)\n";
  }
  for (const auto& w : fit.start_warnings) out << "WARNING: " << w << '\n';
  out << "\nGlobal refinement (GSL multifit_nlinear, LM with geodesic acceleration, through the "
         "driver):\n  "
      << fit.lsq.iterations << " iterations, " << fit.lsq.residual_evaluations
      << " parameter sets run (" << fit.lsq.batch_calls << " batches), "
      << num(fit.lsq.wall_time, 3) << " s; " << fit.lsq.stop_reason << "; residual s.d. "
      << num(std::sqrt(fit.lsq.variance)) << " MPa\n\n";
  // The free parameters, then the fixed ones (as used).
  std::vector<std::size_t> free, fixed;
  for (std::size_t i = 0; i < fit.parameters.size(); ++i)
    (fit.parameters[i].free ? free : fixed).push_back(i);
  out << std::left << std::setw(22) << "par" << std::setw(8) << "unit" << std::right
      << std::setw(12) << "material" << std::setw(12) << "start" << std::setw(12) << "fitted"
      << std::setw(12) << "std err" << std::setw(9) << "rel %"
      << "  status [bounds]\n";
  for (const std::vector<std::size_t>* group : {&free, &fixed}) {
    for (const std::size_t i : *group) {
      const Parameter& p = fit.parameters[i];
      const std::string& u = fit.units[i];
      out << std::left << std::setw(22) << p.name << std::setw(8) << shown_unit(u) << std::right
          << std::setw(12) << num(shown(u, fit.material_values[i]), 5) << std::setw(12)
          << num(shown(u, fit.start[i]), 5) << std::setw(12) << num(shown(u, fit.fitted[i]), 6);
      if (p.free) {
        // A parameter the bound stopped is flagged in capitals: its value is the bound's.
        const BoundSide side = i < fit.at_bound.size() ? fit.at_bound[i] : BoundSide::none;
        out << std::setw(12) << num(shown(u, fit.lsq.std_errors[i]), 3) << std::setw(9)
            << num(100 * fit.lsq.std_errors[i] / std::abs(fit.fitted[i]), 3) << "  "
            << (side == BoundSide::lower   ? "AT LOWER BOUND"
                : side == BoundSide::upper ? "AT UPPER BOUND"
                                           : "free")
            << " [" << num(shown(u, p.lower)) << ", " << num(shown(u, p.upper)) << "]\n";
      } else {
        out << std::setw(12) << "" << std::setw(9) << ""
            << "  fixed\n";
      }
    }
  }
  for (const auto& m : fit.at_bound_messages()) out << "WARNING: " << m << '\n';
  out << "\nCorrelation matrix (free parameters; from J at the optimum):\n" << std::setw(22) << "";
  for (const std::size_t j : free) out << std::setw(8) << fit.parameters[j].name.substr(0, 7);
  out << '\n';
  for (const std::size_t i : free) {
    out << std::left << std::setw(22) << fit.parameters[i].name << std::right;
    for (const std::size_t j : free)
      out << std::setw(8) << std::fixed << std::setprecision(3)
          << fit.lsq.correlation(static_cast<long>(i), static_cast<long>(j));
    out << '\n';
  }
  out.unsetf(std::ios::floatfield);
  out << "\nFitted set, per curve (model - data):\n";
  print_errors(out, fit.errors_fitted);
  out << "\nMaterial's own set (" << config.material_file << "), per curve:\n";
  print_errors(out, fit.errors_material);
  const double gain = 100.0 * (1.0 - fit.overall_fitted.rms / fit.overall_material.rms);
  out << "\nOverall RMS: fitted " << num(fit.overall_fitted.rms / 1e6) << " MPa, material's set "
      << num(fit.overall_material.rms / 1e6) << " MPa (" << num(gain, 3) << " % lower)\n";
  for (const auto& w : fit.warnings) out << "WARNING: " << w << '\n';
  bool any = false;
  for (const auto& e : fit.experiments)
    if (!e.conversions.empty()) {
      if (!any) out << "\nConversions done by the reader:\n";
      any = true;
      for (const auto& c : e.conversions) out << "  " << e.name << ": " << c << '\n';
    }
  out << "Wall time " << num(fit.wall_time, 3) << " s\n";
}

Json errors_json(const std::vector<CurveErrors>& errors) {
  Json a = Json::array();
  for (const auto& c : errors)
    a.push_back({{"curve", c.name},
                 {"temperature [K]", c.temperature},
                 {"strain_rate [1/s]", c.strain_rate},
                 {"adiabatic", c.adiabatic},
                 {"points", c.points},
                 {"rms [Pa]", c.rms},
                 {"max [Pa]", c.max},
                 {"mean_signed [Pa]", c.mean_signed},
                 {"rms [%]", c.rms_percent()},
                 {"max [%]", c.max_percent()},
                 {"mean_signed [%]", c.mean_signed_percent()}});
  return a;
}

Json fit_report_json(const FitConfig& config, const StrengthFit& fit) {
  Json j;
  j["configuration"] = config.file;
  j["material"] = config.material_file;
  j["residual"] =
      "vertical stress error at the data's plastic strains, sqrt(weight) (model - data)";
  j["law"] = fit.law;
  Json stages = Json::array();
  for (const auto& s : fit.staged.stages) {
    Json v;
    for (std::size_t k = 0; k < 5; ++k) v[jc_names[k]] = s.values[k];
    stages.push_back({{"stage", s.name},
                      {"method", s.method},
                      {"curves", s.curves},
                      {"points", s.points},
                      {"rms [Pa]", s.rms},
                      {"note", s.note},
                      {"values", v}});
  }
  j["staged_guess"] = stages;
  Json params = Json::object();
  Json at_bounds = Json::array();
  std::vector<std::string> order;
  for (std::size_t i = 0; i < fit.parameters.size(); ++i) {
    const Parameter& p = fit.parameters[i];
    order.push_back(p.name);
    const BoundSide side = i < fit.at_bound.size() ? fit.at_bound[i] : BoundSide::none;
    params[p.name] = {{"unit", fit.units[i]},
                      {"material", fit.material_values[i]},
                      {"start", fit.start[i]},
                      {"fitted", fit.fitted[i]},
                      {"std_error", fit.lsq.std_errors[i]},
                      {"free", p.free},
                      {"lower", p.lower},
                      {"upper", p.upper},
                      {"at_bound", side == BoundSide::none ? Json() : Json(to_string(side))}};
    if (side != BoundSide::none) at_bounds.push_back(p.name);
    if (fit.staged_run) {
      const auto k = std::find(jc_names.begin(), jc_names.end(), p.name) - jc_names.begin();
      if (k < 5) params[p.name]["staged"] = fit.staged.values[std::size_t(k)];
    }
  }
  j["parameters"] = params;
  j["parameters_at_bounds"] = at_bounds;
  Json corr = Json::array();
  const long np = static_cast<long>(fit.parameters.size());
  for (long i = 0; i < np; ++i) {
    Json row = Json::array();
    for (long k = 0; k < np; ++k) row.push_back(fit.lsq.correlation(i, k));
    corr.push_back(row);
  }
  j["correlation"] = {{"order", order}, {"matrix", corr}};
  j["solver"] = {{"iterations", fit.lsq.iterations},
                 {"parameter_sets_run", fit.lsq.residual_evaluations},
                 {"batches", fit.lsq.batch_calls},
                 {"stop_reason", fit.lsq.stop_reason},
                 {"residual_sd [MPa]", std::sqrt(fit.lsq.variance)},
                 {"wall_time [s]", fit.lsq.wall_time}};
  j["curves_fitted"] = errors_json(fit.errors_fitted);
  j["curves_material"] = errors_json(fit.errors_material);
  j["overall"] = {{"fitted_rms [Pa]", fit.overall_fitted.rms},
                  {"fitted_max [Pa]", fit.overall_fitted.max},
                  {"material_rms [Pa]", fit.overall_material.rms},
                  {"material_max [Pa]", fit.overall_material.max},
                  {"points", fit.overall_fitted.points}};
  Json conv = Json::object();
  for (const auto& e : fit.experiments)
    if (!e.conversions.empty()) conv[e.name] = e.conversions;
  j["conversions"] = conv;
  Json warnings = fit.start_warnings;
  for (const auto& m : fit.at_bound_messages()) warnings.push_back(m);
  for (const auto& w : fit.warnings) warnings.push_back(w);
  j["warnings"] = warnings;
  j["wall_time [s]"] = fit.wall_time;
  return j;
}

Json fitted_material(const FitConfig& config, const StrengthFit& fit) {
  Json doc = load_json_file(config.material_file);
  // The configuration's overrides (reference rate, temperatures, chi, ...) were part of the fitted
  // model, so they go into the fitted material too (the fit's own erosion switch does not).
  doc.merge_patch(config.overrides);
  std::string fitted_names;
  for (std::size_t i = 0; i < fit.parameters.size(); ++i) {
    // The fitted ones, and a fixed one the configuration set to another value than the file's.
    if (!fit.parameters[i].free && fit.fitted[i] == fit.material_values[i]) continue;
    doc["constitutive_model"]["flow_stress"][fit.parameters[i].name] = fit.fitted[i];
    if (fit.parameters[i].free)
      fitted_names += (fitted_names.empty() ? "" : ", ") + fit.parameters[i].name;
  }
  if (!doc.contains("sources") || !doc["sources"].is_object()) doc["sources"] = Json::object();
  std::ostringstream note;
  note << fit.law << " " << fitted_names << " fitted by `pointdriver fit " << config.file << "` to "
       << fit.experiments.size() << " curves (overall RMS " << num(fit.overall_fitted.rms / 1e6)
       << " MPa; the input set gave " << num(fit.overall_material.rms / 1e6)
       << " MPa); the rest of the file is " << config.material_file;
  doc["sources"]["flow_stress"] = note.str();
  doc["description"] = fit.law +
                       " strength fitted by pointdriver fit (sources.flow_stress); "
                       "everything else from " +
                       config.material_file + ": " + doc.value("description", std::string());
  read_material(doc, "fitted material");  // throws if the result is not a valid material
  return doc;
}

std::vector<std::string> write_figures(const std::string& directory, const std::string& prefix,
                                       const std::vector<Experiment>& experiments,
                                       const std::vector<Curve>& model,
                                       const std::vector<Curve>& reference,
                                       const std::string& model_label,
                                       const std::string& reference_label) {
  // Temperature groups: sorted, a new group when more than 10 K above the group's first.
  std::vector<std::size_t> order(experiments.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return experiments[a].temperature < experiments[b].temperature;
  });
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i : order) {
    if (groups.empty() ||
        experiments[i].temperature > experiments[groups.back().front()].temperature + 10.0)
      groups.emplace_back();
    groups.back().push_back(i);
  }
  for (auto& g : groups)  // within a group: by rate, then name
    std::stable_sort(g.begin(), g.end(), [&](std::size_t a, std::size_t b) {
      return experiments[a].strain_rate < experiments[b].strain_rate;
    });
  auto line = [](const Curve& c, double ep_max) {
    Json a = Json::array();
    for (std::size_t k = 0; k < c.plastic_strain.size(); ++k)
      if (c.plastic_strain[k] > 0 && c.plastic_strain[k] <= ep_max)
        a.push_back({c.plastic_strain[k], c.stress[k] / 1e6});
    return a;
  };
  Json spec = {{"model_label", model_label},
               {"reference_label", reference_label},
               {"figures", Json::array()}};
  std::vector<std::string> files;
  for (const auto& g : groups) {
    double T = experiments[g.front()].temperature;  // the group's lowest
    for (std::size_t i : g) T = std::min(T, experiments[i].temperature);
    const std::string file =
        (fs::path(directory) /
         (prefix + "_" + std::to_string(static_cast<int>(std::lround(T))) + "K.png"))
            .string();
    Json curves = Json::array();
    for (std::size_t i : g) {
      const Experiment& e = experiments[i];
      Json data = Json::array();
      for (std::size_t k = 0; k < e.stress.size(); ++k)
        data.push_back({e.plastic_strain[k], e.stress[k] / 1e6});
      const double ep_max = 1.02 * e.plastic_strain.back();
      Json c = {{"label",
                 e.name + " (" + num(e.temperature, 3) + " K, " + num(e.strain_rate, 3) + " /s)"},
                {"data", data},
                {"model", line(model[i], ep_max)}};
      if (!reference.empty()) c["reference"] = line(reference[i], ep_max);
      curves.push_back(c);
    }
    spec["figures"].push_back({{"file", file},
                               {"title", prefix + ": tests near " + num(T, 3) + " K"},
                               {"curves", curves}});
    files.push_back(file);
  }
  const fs::path spec_file = fs::path(directory) / (prefix + "_figures.json");
  write_file_atomically(spec_file, [&](std::ostream& o) { o << spec.dump(1) << '\n'; });
  // The plotting helper runs fit_plot.py (shipped beside the binary, or in the source tree).
  const char* old = std::getenv("POINTDRIVER_PLOT_SCRIPT");
  const std::string saved = old ? old : "";
  const std::string script = shipped_file("pointdriver/fit/fit_plot.py").string();
  setenv("POINTDRIVER_PLOT_SCRIPT", script.c_str(), 1);
  const PlotRun run = run_plot_script({spec_file.string()});
  if (old)
    setenv("POINTDRIVER_PLOT_SCRIPT", saved.c_str(), 1);
  else
    unsetenv("POINTDRIVER_PLOT_SCRIPT");
  if (run.status != PlotRun::Status::ok)
    throw std::runtime_error("figures not written: " + run.message);
  return files;
}

}  // namespace impact::pointdriver::fit
