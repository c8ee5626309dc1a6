#include "mpm/output/observables.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace impact::mpm {

Gauges::Gauges(const Scene& scene, const Particles& initial) {
  for (const GaugeSpec& g : scene.output.gauges) {
    Gauge gauge;
    const char* unit = g.type == GaugeType::velocity ? "m/s"
                       : g.type == GaugeType::strain ? "-"
                                                     : "Pa";
    gauge.column = "gauge_" + g.name + " [" + unit + "]";
    gauge.type = g.type;
    gauge.component = g.component;
    for (std::size_t p = 0; p < initial.size(); ++p) {
      if (initial.object[p] != g.object || !in_box(initial.x[p], g.lower, g.upper)) continue;
      gauge.members.push_back(p);
    }
    if (gauge.members.empty()) {
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

std::vector<double> Gauges::read(const Particles& P) const {
  std::vector<double> values;
  values.reserve(gauges_.size());
  for (const Gauge& g : gauges_) {
    // Mass-weighted over the members still in play (a removed particle has zero mass); NaN once
    // all have left the grid (grid.outflow = remove).
    double sum = 0.0, mass = 0.0;
    for (const std::size_t p : g.members) {
      const double value = g.type == GaugeType::velocity ? P.v[p](g.component)
                           : g.type == GaugeType::strain ? log_strain(P.state[p].F, g.component)
                                                         : pressure(P.state[p].stress);
      sum += P.mass[p] * value;
      mass += P.mass[p];
    }
    values.push_back(mass > 0.0 ? sum / mass : std::numeric_limits<double>::quiet_NaN());
  }
  return values;
}

Observables::Observables(const Scene& scene, const Particles& initial)
    : max_pressure_(scene.objects.size(), -std::numeric_limits<double>::infinity()),
      max_pressure_time_(scene.objects.size(), 0.0),
      crater_(scene.output.crater),
      dx_(scene.grid.spacing()(0)) {
  for (const SceneObject& o : scene.objects) names_.push_back(o.name);
  if (!crater_) return;
  crater_object_ = scene.objects[crater_->object].name;
  for (std::size_t p = 0; p < initial.size(); ++p) {
    if (initial.object[p] != crater_->object) continue;
    if (std::abs(initial.x[p](0) - crater_->face) > dx_) continue;
    face_.push_back(p);
    face_x0_.push_back(initial.x[p]);
  }
}

void Observables::sample(const Particles& P, double time) {
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double pr = pressure(P.state[p].stress);
    const auto o = P.object[p];
    if (pr > max_pressure_[o]) {
      max_pressure_[o] = pr;
      max_pressure_time_[o] = time;
    }
  }
}

Crater Observables::crater(const Particles& P) const {
  Crater c;
  c.face_particles = face_.size();
  c.depth = -std::numeric_limits<double>::infinity();
  double y = 0.0, z = 0.0;
  for (std::size_t i = 0; i < face_.size(); ++i) {
    const Vec3& x = P.x[face_[i]];
    const double u = x(0) - face_x0_[i](0);
    c.depth = std::max(c.depth, u);
    if (u > 0.5 * dx_) {
      ++c.displaced_particles;
      y += x(1);
      z += x(2);
    }
  }
  if (face_.empty()) c.depth = 0.0;
  if (c.displaced_particles == 0) return c;
  c.axis_y = crater_->axis ? (*crater_->axis)[0] : y / double(c.displaced_particles);
  c.axis_z = crater_->axis ? (*crater_->axis)[1] : z / double(c.displaced_particles);
  double r2 = 0.0;
  for (std::size_t i = 0; i < face_.size(); ++i) {
    const Vec3& x = P.x[face_[i]];
    if (x(0) - face_x0_[i](0) <= 0.5 * dx_) continue;
    r2 =
        std::max(r2, (x(1) - c.axis_y) * (x(1) - c.axis_y) + (x(2) - c.axis_z) * (x(2) - c.axis_z));
  }
  c.diameter = 2.0 * std::sqrt(r2);
  return c;
}

Json Observables::summary(const Particles& P) const {
  const std::size_t n = names_.size();
  std::vector<double> mass(n, 0.0), ke(n, 0.0);
  std::vector<Vec3> momentum(n, Vec3::Zero());
  for (std::size_t p = 0; p < P.size(); ++p) {
    const auto o = P.object[p];
    mass[o] += P.mass[p];
    momentum[o] += P.mass[p] * P.v[p];
    ke[o] += 0.5 * P.mass[p] * P.v[p].squaredNorm();
  }
  Json objects = Json::object();
  for (std::size_t o = 0; o < n; ++o) {
    const Vec3 v = mass[o] > 0.0 ? Vec3(momentum[o] / mass[o]) : Vec3::Zero();
    const bool sampled = std::isfinite(max_pressure_[o]);
    objects[names_[o]] = {{"mass [kg]", mass[o]},
                          {"mean_velocity [m/s]", Json::array({v(0), v(1), v(2)})},
                          {"kinetic_energy [J]", ke[o]},
                          {"max_pressure [Pa]", sampled ? max_pressure_[o] : 0.0},
                          {"max_pressure_time [s]", max_pressure_time_[o]}};
  }
  Json j = {{"objects", objects}};
  if (crater_) {
    const Crater c = crater(P);
    j["crater"] = {{"object", crater_object_},
                   {"face [m]", crater_->face},
                   {"depth [m]", c.depth},
                   {"diameter [m]", c.diameter},
                   {"axis_yz [m]", Json::array({c.axis_y, c.axis_z})},
                   {"face_particles", c.face_particles},
                   {"displaced_particles", c.displaced_particles}};
  }
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
