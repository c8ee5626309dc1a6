#include "pointdriver/fit/strength_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "pointdriver/format/text_format.hpp"

namespace impact::pointdriver::fit {

CurveErrors curve_errors(const Experiment& e, const std::vector<double>& model, bool adiabatic) {
  CurveErrors c;
  c.name = e.name;
  c.temperature = e.temperature;
  c.strain_rate = e.strain_rate;
  c.adiabatic = adiabatic;
  c.points = static_cast<int>(e.stress.size());
  double ss = 0, sum = 0, data = 0;
  for (std::size_t k = 0; k < e.stress.size(); ++k) {
    const double r = model[k] - e.stress[k];
    ss += r * r;
    sum += r;
    data += e.stress[k];
    c.max = std::max(c.max, std::abs(r));
  }
  const double n = static_cast<double>(std::max(c.points, 1));
  c.rms = std::sqrt(ss / n);
  c.mean_signed = sum / n;
  c.mean_stress = data / n;
  return c;
}

OverallErrors overall(const std::vector<CurveErrors>& errors) {
  OverallErrors o;
  double ss = 0;
  for (const auto& c : errors) {
    ss += c.rms * c.rms * c.points;
    o.points += c.points;
    o.max = std::max(o.max, c.max);
  }
  o.rms = o.points ? std::sqrt(ss / o.points) : 0.0;
  return o;
}

std::vector<std::string> StrengthFit::at_bound_messages() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < at_bound.size(); ++i)
    if (at_bound[i] != BoundSide::none)
      out.push_back(at_bound_message(parameters[i], at_bound[i], fitted[i], units[i]));
  return out;
}

CurveModel make_curve_model(const std::string& material_file, const Json& overrides,
                            const std::vector<DataEntry>& data, const CurveSettings& settings) {
  // E of the material (for total-strain curves) before the experiments are read.
  Json patch = overrides;
  const Material m = load_material(material_file, patch);
  const double K = m.model.params().bulk_modulus, G = m.model.params().shear_modulus;
  return CurveModel(material_file, overrides, read_experiments(data, 9 * K * G / (3 * K + G)),
                    settings);
}

StrengthFit fit_strength(const FitConfig& config) {
  const auto t0 = std::chrono::steady_clock::now();
  const CurveModel model =
      make_curve_model(config.material_file, config.overrides, config.data, config.curves);
  StrengthFit out = fit_strength(model, config);
  out.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

StrengthFit fit_strength(const CurveModel& model, const FitConfig& config) {
  const auto t0 = std::chrono::steady_clock::now();
  StrengthFit out;
  out.experiments = model.experiments();
  for (std::size_t i = 0; i < out.experiments.size(); ++i)
    out.adiabatic.push_back(model.adiabatic(i));
  const FlowStressLaw& law = model.base().flow_stress;
  const std::vector<std::string>& names = model.parameter_names();
  out.law = std::string(law_type(law));
  out.material_values = law_values(law);

  // Start: given values, else the material's; a parameter the configuration does not list (a
  // forward model built by a caller) keeps the law's defaults.
  ParameterValues start = out.material_values;
  out.parameters.resize(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    Parameter& p = out.parameters[i];
    const FitBounds b = fit_bounds(law, names[i]);
    p = {names[i], start[i], !b.empty() && start[i] != 0.0, b.lower, b.upper};
    if (const ParameterSpec* s = find_parameter(config, names[i])) {
      p = {names[i], s->start.value_or(start[i]), s->free, s->lower, s->upper};
    }
    start[i] = p.value;
    out.units.emplace_back(parameter_unit(law, names[i]));
  }
  // Johnson-Cook: the staged guess replaces the free values not given a start.
  if (std::holds_alternative<JohnsonCookParams>(law) && config.initial_guess == "staged") {
    JcValues jc{};
    std::array<bool, 5> free{};
    std::array<std::size_t, 5> at{};
    for (std::size_t k = 0; k < 5; ++k) {
      at[k] = static_cast<std::size_t>(std::find(names.begin(), names.end(), jc_names[k]) -
                                       names.begin());
      jc[k] = start[at[k]];
      free[k] = out.parameters[at[k]].free;
    }
    out.staged =
        staged_guess(out.experiments, out.adiabatic, model.base(), jc, free, config.room_tolerance);
    out.staged_run = true;
    for (std::size_t k = 0; k < 5; ++k) {
      const ParameterSpec* s = find_parameter(config, jc_names[k]);
      if (free[k] && !(s && s->start)) start[at[k]] = out.staged.values[k];
    }
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    Parameter& p = out.parameters[i];
    p.value = start[i];
    // A start on or outside a bound is moved inside it, and the user told: the solver cannot
    // start on a bound, and a silent move hides a start the user (or the staged guess) chose.
    if (const auto moved = p.free ? move_inside_bounds(p, p.value) : std::nullopt) {
      const ParameterSpec* s = find_parameter(config, names[i]);
      const bool staged = out.staged_run && !(s && s->start) &&
                          std::find(jc_names.begin(), jc_names.end(), names[i]) != jc_names.end();
      const std::string unit = out.units[i] == "-" ? "" : " " + out.units[i];
      out.start_warnings.push_back(
          "start value of " + p.name + " (" + format_number(p.value) + unit + ", " +
          (s && s->start ? "the configuration's"
           : staged      ? "the staged guess"
                         : "the material's") +
          ") is on or outside its bounds [" + format_number(p.lower) + ", " +
          format_number(p.upper) + "]" + unit + ": moved to " + format_number(*moved) + unit);
      p.value = *moved;
    }
    start[i] = p.value;
  }
  out.start = start;
  const std::vector<Parameter>& parameters = out.parameters;

  std::vector<double> weights;
  for (const auto& e : out.experiments) weights.push_back(std::sqrt(e.weight));
  const BatchResidual residual = [&](const std::vector<std::vector<double>>& sets) {
    const auto pred = model.predict(sets);
    std::vector<Eigen::VectorXd> r;
    for (const auto& per_set : pred) {
      std::vector<double> v;
      for (std::size_t e = 0; e < per_set.size(); ++e)
        for (std::size_t k = 0; k < per_set[e].size(); ++k)
          v.push_back(weights[e] * (per_set[e][k] - out.experiments[e].stress[k]) / 1e6);
      r.push_back(Eigen::Map<Eigen::VectorXd>(v.data(), static_cast<long>(v.size())));
    }
    return r;
  };
  out.lsq = least_squares(parameters, residual, config.solver);
  out.fitted = out.lsq.values;
  out.at_bound.assign(names.size(), BoundSide::none);
  for (std::size_t i = 0; i < names.size(); ++i)
    if (parameters[i].free) out.at_bound[i] = at_bound(parameters[i], out.fitted[i]);

  out.curves = model.curves({out.fitted, out.material_values});
  for (std::size_t s = 0; s < 2; ++s) {
    auto& errors = s == 0 ? out.errors_fitted : out.errors_material;
    for (std::size_t e = 0; e < out.experiments.size(); ++e) {
      std::vector<double> v;
      for (double x : out.experiments[e].plastic_strain)
        v.push_back(interpolate_stress(out.curves[s][e], x));
      errors.push_back(curve_errors(out.experiments[e], v, out.adiabatic[e]));
      if (!out.curves[s][e].completed)
        out.warnings.push_back(out.experiments[e].name + " (" +
                               (s == 0 ? "fitted set" : "material's set") +
                               "): the driver run did not complete: " + out.curves[s][e].error);
    }
  }
  out.overall_fitted = overall(out.errors_fitted);
  out.overall_material = overall(out.errors_material);
  out.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace impact::pointdriver::fit
