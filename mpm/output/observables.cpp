#include "mpm/output/observables.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mpm/ledger/ledger.hpp"

namespace impact::mpm {

Gauges::Gauges(const Scene& scene, const Particles& initial, const Communicator& comm)
    : comm_(comm) {
  for (const GaugeSpec& g : scene.output.gauges) {
    Gauge gauge;
    const char* unit = g.type == GaugeType::velocity ? "m/s"
                       : g.type == GaugeType::strain ? "-"
                                                     : "Pa";
    gauge.unit = unit;
    gauge.column = "gauge_" + g.name + " [" + unit + "]";
    gauge.type = g.type;
    gauge.component = g.component;
    std::vector<std::uint64_t> local;
    for (std::size_t p = 0; p < initial.size(); ++p) {
      if (initial.object[p] != g.object || !in_box(initial.x[p], g.lower, g.upper)) continue;
      local.push_back(seed_index(initial, p));
    }
    if (members_.ids(members_.add(local, comm)).empty()) {
      throw std::logic_error("gauge " + g.name + ": no particle in its region");
    }
    gauges_.push_back(std::move(gauge));
  }
}

std::vector<std::string> Gauges::columns() const {
  std::vector<std::string> c;
  for (const Gauge& g : gauges_) c.push_back(g.column);
  return c;
}

std::vector<std::string> Gauges::units() const {
  std::vector<std::string> u;
  for (const Gauge& g : gauges_) u.push_back(g.unit);
  return u;
}

std::vector<double> Gauges::read(const Particles& P) const {
  if (gauges_.empty()) return {};
  // Mass-weighted over the members still in play (a removed particle has zero mass); NaN once
  // all have left the grid (grid.outflow = remove). Per gauge: sum of m value, sum of m.
  const auto found = members_.find(P);
  std::vector<double> sums(2 * gauges_.size(), 0.0);
  for (std::size_t k = 0; k < gauges_.size(); ++k) {
    const Gauge& g = gauges_[k];
    for (const ParticleSets::Member& m : found[k]) {
      const std::size_t p = m.p;
      const double value = g.type == GaugeType::velocity ? P.v[p](g.component)
                           : g.type == GaugeType::strain ? log_strain(P.state[p].F, g.component)
                                                         : pressure(P.state[p].stress);
      sums[2 * k] += P.mass[p] * value;
      sums[2 * k + 1] += P.mass[p];
    }
  }
  sums = comm_.sum(sums);
  std::vector<double> values;
  values.reserve(gauges_.size());
  for (std::size_t k = 0; k < gauges_.size(); ++k) {
    const double mass = sums[2 * k + 1];
    values.push_back(mass > 0.0 ? sums[2 * k] / mass : std::numeric_limits<double>::quiet_NaN());
  }
  return values;
}

Observables::Observables(const Scene& scene, const Particles& initial, const Communicator& comm)
    : max_pressure_(scene.objects.size(), -std::numeric_limits<double>::infinity()),
      max_pressure_time_(scene.objects.size(), 0.0),
      momentum_components_(scene.grid.geometry_facts().momentum_components.data()),
      units_(ExtensiveUnits::of(scene.grid.per_metre_of_thickness())),
      comm_(comm) {
  for (const SceneObject& o : scene.objects) names_.push_back(o.name);
  if (!scene.output.crater) return;
  crater_.emplace(scene, *scene.output.crater, initial, comm);
  crater_object_ = scene.objects[scene.output.crater->object].name;
  crater_face_ = scene.output.crater->face;
}

void Observables::sample(const Particles& P, double time) {
  std::vector<double> largest(max_pressure_.size(), -std::numeric_limits<double>::infinity());
  for (std::size_t p = 0; p < P.size(); ++p) {
    const auto o = P.object[p];
    largest[o] = std::max(largest[o], pressure(P.state[p].stress));
  }
  largest = comm_.max(largest);
  for (std::size_t o = 0; o < largest.size(); ++o) {
    if (largest[o] > max_pressure_[o]) {
      max_pressure_[o] = largest[o];
      max_pressure_time_[o] = time;
    }
  }
}

Json Observables::summary(const Particles& P) const {
  const std::size_t n = names_.size();
  // Per object: mass, momentum (3), kinetic energy.
  std::vector<double> sums(5 * n, 0.0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    double* s = &sums[5 * P.object[p]];
    s[0] += P.mass[p];
    for (int d = 0; d < 3; ++d) s[1 + d] += P.mass[p] * P.v[p](d);
    s[4] += 0.5 * P.mass[p] * P.v[p].squaredNorm();
  }
  sums = comm_.sum(sums);
  Json objects = Json::object();
  for (std::size_t o = 0; o < n; ++o) {
    const double* s = &sums[5 * o];
    Vec3 v = s[0] > 0.0 ? Vec3(Vec3(s[1], s[2], s[3]) / s[0]) : Vec3::Zero();
    // A ring's radial velocities cancel around it: the revolved body's mean velocity is axial
    // (its momentum too: the ledger books the axial component only, ledger.hpp).
    v = body_components(v, momentum_components_);
    const bool sampled = std::isfinite(max_pressure_[o]);
    objects[names_[o]] = {{"mass [" + units_.mass + "]", s[0]},
                          {"mean_velocity [m/s]", Json::array({v(0), v(1), v(2)})},
                          {"kinetic_energy [" + units_.energy + "]", s[4]},
                          {"max_pressure [Pa]", sampled ? max_pressure_[o] : 0.0},
                          {"max_pressure_time [s]", max_pressure_time_[o]}};
  }
  Json j = {{"objects", objects}};
  if (crater_) j["crater"] = crater(P).json(crater_object_, crater_face_);
  return j;
}

std::vector<double> Observables::state() const {
  std::vector<double> s = max_pressure_;
  s.insert(s.end(), max_pressure_time_.begin(), max_pressure_time_.end());
  return s;
}

void Observables::restore(const std::vector<double>& state) {
  const std::size_t n = max_pressure_.size();
  if (state.size() != 2 * n) {
    throw std::invalid_argument("observables: " + std::to_string(state.size()) + " values for " +
                                std::to_string(n) + " objects");
  }
  std::copy(state.begin(), state.begin() + n, max_pressure_.begin());
  std::copy(state.begin() + n, state.end(), max_pressure_time_.begin());
}

}  // namespace impact::mpm
