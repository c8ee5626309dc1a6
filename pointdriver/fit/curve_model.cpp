#include "pointdriver/fit/curve_model.hpp"

#include <algorithm>
#include <cmath>

#include "pointdriver/study/batch.hpp"

namespace impact::pointdriver::fit {

ParameterValues law_values(const FlowStressLaw& law) {
  ParameterValues v;
  for (const std::string& name : parameter_names(law)) v.push_back(parameter(law, name));
  return v;
}

JcValues jc_values(const FlowStressLaw& law) {
  JcValues v{};
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = parameter(law, jc_names[i]);
  return v;
}

double interpolate_stress(const Curve& curve, double x) {
  // The plastic rows, strictly increasing in eps_p.
  std::size_t first = 0;
  while (first < curve.plastic_strain.size() && curve.plastic_strain[first] <= 0.0) ++first;
  const std::size_t n = curve.plastic_strain.size();
  if (n == 0) return 0.0;
  if (n - first < 2) return curve.stress.back();
  const auto& e = curve.plastic_strain;
  const auto& s = curve.stress;
  // Segment [k, k+1] with e[k] <= x < e[k+1], clamped to the first and last segments.
  auto it = std::upper_bound(e.begin() + static_cast<long>(first), e.end(), x);
  std::size_t k = it == e.begin() + static_cast<long>(first)
                      ? first
                      : static_cast<std::size_t>(it - e.begin()) - 1;
  if (k + 1 >= n) k = n - 2;
  // Skip repeated eps_p (elastic rows after plastic ones).
  while (k > first && e[k + 1] <= e[k]) --k;
  if (e[k + 1] <= e[k]) return s[k];
  if (!curve.completed && x > e.back()) return s.back();  // a run cut short: no extrapolation
  const double t = (x - e[k]) / (e[k + 1] - e[k]);
  return s[k] + t * (s[k + 1] - s[k]);
}

CurveModel::CurveModel(const std::string& material_file, const Json& overrides,
                       std::vector<Experiment> experiments, const CurveSettings& settings)
    : experiments_(std::move(experiments)), settings_(settings) {
  Json patch = overrides.is_object() ? overrides : Json::object();
  patch["constitutive_model"]["erosion"] = {{"algorithm", "none"}};
  const Material material = load_material(material_file, patch);
  base_ = material.model.params();
  names_ = impact::parameter_names(base_.flow_stress);
  for (std::size_t i = 0; i < experiments_.size(); ++i) {
    const Experiment& x = experiments_[i];
    const double ep_max = x.plastic_strain.back();
    // Independent of the measured stresses (so synthetic and fitted runs share one path): the
    // margin covers the elastic strain of stresses up to E / 100 (700 MPa for aluminium).
    const double strain = 1.05 * ep_max + 0.02;
    const double sign = x.type == TestType::uniaxial_tension ? 1.0 : -1.0;
    const double duration = strain / x.strain_rate;
    Json leg = {{"type", "uniaxial_stress"},
                {"strain", sign * strain},
                {"strain_rate", sign * x.strain_rate},
                {"steps", settings_.steps},
                {"first_step", duration * settings_.first_step_fraction}};
    Json doc = {{"material", {{"file", material_file}, {"overrides", patch}}},
                {"temperature", x.temperature},
                {"thermal", adiabatic(i) ? "adiabatic" : "isothermal"},
                {"failure_policy", "stop"},
                {"legs", Json::array({leg})}};
    paths_.push_back(read_path(doc, x.file));
  }
}

bool CurveModel::adiabatic(std::size_t i) const {
  const Experiment& x = experiments_[i];
  if (x.thermal == ThermalMode::automatic) return x.strain_rate >= settings_.adiabatic_above_rate;
  return x.thermal == ThermalMode::adiabatic;
}

double CurveModel::youngs_modulus() const {
  const double K = base_.bulk_modulus, G = base_.shear_modulus;
  return 9.0 * K * G / (3.0 * K + G);
}

ElasticPlastic CurveModel::model(const ParameterValues& v) const {
  ElasticPlasticParams p = base_;
  for (std::size_t i = 0; i < v.size(); ++i) set_parameter(p.flow_stress, names_[i], v[i]);
  return ElasticPlastic(p);
}

std::vector<std::vector<Curve>> CurveModel::curves(const std::vector<ParameterValues>& sets) const {
  std::vector<ElasticPlastic> models;
  models.reserve(sets.size());
  for (const auto& s : sets) models.push_back(model(s));
  std::vector<BatchJob> jobs;
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (const Path& p : paths_) jobs.push_back({&p, &models[s]});
  std::vector<Curve> out(jobs.size());
  BatchOptions options;
  options.threads = settings_.threads;
  options.make_sink = [&out](std::size_t i, const BatchJob&) -> RowSink {
    Curve* c = &out[i];
    return [c](const Row& row) {
      c->plastic_strain.push_back(row.state.plastic_strain);
      c->stress.push_back(std::abs(row.stress_path(0, 0)));
      c->temperature.push_back(row.state.temperature);
    };
  };
  const auto results = run_batch_jobs(jobs, options);
  std::vector<std::vector<Curve>> grid(sets.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    out[i].completed = results[i].result.completed;
    out[i].error = results[i].result.error;
    grid[i / paths_.size()].push_back(std::move(out[i]));
  }
  return grid;
}

std::vector<std::vector<std::vector<double>>> CurveModel::predict(
    const std::vector<ParameterValues>& sets) const {
  const auto grid = curves(sets);
  std::vector<std::vector<std::vector<double>>> out(sets.size());
  for (std::size_t s = 0; s < sets.size(); ++s) {
    for (std::size_t e = 0; e < experiments_.size(); ++e) {
      std::vector<double> v;
      v.reserve(experiments_[e].plastic_strain.size());
      for (double x : experiments_[e].plastic_strain)
        v.push_back(interpolate_stress(grid[s][e], x));
      out[s].push_back(std::move(v));
    }
  }
  return out;
}

}  // namespace impact::pointdriver::fit
