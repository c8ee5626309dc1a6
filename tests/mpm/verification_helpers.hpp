// Shared by the MPM verification tests: load a data/scenes/verification scene with a JSON merge
// patch on top (how a test varies interpolation or scheme), and small measurements.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "mpm/input/scene_reader.hpp"
#include "mpm/run/run.hpp"
#include "mpm/simulation/simulation.hpp"

namespace impact::mpm::test {

/// A scene shipped under data/scenes/ (`path` relative to it), with `patch` merged on top.
inline Scene shipped_scene(const std::string& path, const Json& patch = Json::object()) {
  const std::string file = std::string(IMPACT_SOURCE_DIR) + "/data/scenes/" + path;
  Json doc = load_scene_document(file);
  doc.merge_patch(patch);
  return read_scene(doc, file);
}

inline Scene verification_scene(const std::string& name, const Json& patch = Json::object()) {
  return shipped_scene("verification/" + name, patch);
}

inline Json with_solver(const char* interpolation, const char* scheme) {
  return {{"solver", {{"interpolation", interpolation}, {"scheme", scheme}}}};
}

/// Longitudinal (uniaxial-strain) wave speed sqrt((K + 4 mu/3)/rho0) of the first material.
inline double longitudinal_wave_speed(const Scene& s) {
  const auto& p = s.materials.front().material.model.params();
  return std::sqrt((p.bulk_modulus + 4.0 * p.shear_modulus / 3.0) / p.density);
}

/// Young's modulus E = 9 K G / (3 K + G) [Pa] and Poisson's ratio nu = (3 K - 2 G) / (2 (3 K + G))
/// of the first material, from its bulk and shear moduli.
inline double youngs_modulus(const Scene& s) {
  const auto& p = s.materials.front().material.model.params();
  return 9.0 * p.bulk_modulus * p.shear_modulus / (3.0 * p.bulk_modulus + p.shear_modulus);
}
inline double poissons_ratio(const Scene& s) {
  const auto& p = s.materials.front().material.model.params();
  return (3.0 * p.bulk_modulus - 2.0 * p.shear_modulus) /
         (2.0 * (3.0 * p.bulk_modulus + p.shear_modulus));
}

/// The patch that puts the report's case01 (data/scenes/sphere_cylinder/case01.json) on an
/// axisymmetric grid: the 3D twin's spacing (2.38 x 3.3 mm) over the half-section y >= 0, the
/// sphere moved onto the axis (docs/scenes.md#2d-grids). Tests add their own time and output.
inline Json axisymmetric_case01_patch() {
  return {{"grid",
           {{"geometry", "axisymmetric"},
            {"lower", {0.0, 0.0}},
            {"upper", {119.0e-3, 33.0e-3}},
            {"cells", {50, 10}},
            {"boundary", {{"z-", nullptr}, {"z+", nullptr}}}}},
          {"objects",
           {{"sphere",
             {{"geometry", {{"center", {9.75e-3, 0.0, 0.0}}}}, {"particles_per_cell", {2, 2}}}},
            {"target", {{"particles_per_cell", {2, 2}}}}}}};
}

/// The index of the scene's object `name` (Particles::object).
inline int object_index(const Scene& s, const std::string& name) {
  for (std::size_t o = 0; o < s.objects.size(); ++o)
    if (s.objects[o].name == name) return static_cast<int>(o);
  throw std::invalid_argument("no object " + name);
}

/// One object's centre of mass [m], its velocity [m/s], and its spin about the centre in the x-y
/// plane, omega_z = sum m (r x u)_z / sum m |r|^2 [rad/s] (r, u: position and velocity relative to
/// the centre's), the rigid-body fit of the particles' motion; its mass [kg] and kinetic energy
/// [J].
struct BodyMotion {
  Vec3 centre = Vec3::Zero(), velocity = Vec3::Zero();
  double omega = 0.0, mass = 0.0, kinetic_energy = 0.0;
};
inline BodyMotion motion_of(const Particles& P, int object) {
  BodyMotion b;
  Vec3 mx = Vec3::Zero(), mv = Vec3::Zero();
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.object[p] != object) continue;
    b.mass += P.mass[p];
    mx += P.mass[p] * P.x[p];
    mv += P.mass[p] * P.v[p];
    b.kinetic_energy += 0.5 * P.mass[p] * P.v[p].squaredNorm();
  }
  b.centre = mx / b.mass;
  b.velocity = mv / b.mass;
  double angular = 0.0, inertia = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.object[p] != object) continue;
    const Vec3 r = P.x[p] - b.centre, u = P.v[p] - b.velocity;
    angular += P.mass[p] * (r(0) * u(1) - r(1) * u(0));
    inertia += P.mass[p] * (r(0) * r(0) + r(1) * r(1));
  }
  b.omega = angular / inertia;
  return b;
}

/// How closely a body's velocity along y follows a law of friction over a run to its end (a block
/// sliding to a stop, one dragged by a moving floor): the worst |v_y - law(t)| while t < t_change
/// and the worst |v_y - after| once t > 1.05 t_change (the law's end, given a twentieth of it to
/// settle), each over `scale` [m/s].
struct LawFollowed {
  double worst_before = 0.0, worst_after = 0.0;  ///< [-]
};
inline LawFollowed follow_along_y(Simulation& sim, int object,
                                  const std::function<double(double)>& law, double t_change,
                                  double after, double scale) {
  LawFollowed f;
  while (!sim.finished()) {
    sim.step();
    const double vy = motion_of(sim.particles(), object).velocity(1);
    if (sim.time() < t_change)
      f.worst_before = std::max(f.worst_before, std::abs(vy - law(sim.time())) / scale);
    else if (sim.time() > 1.05 * t_change)
      f.worst_after = std::max(f.worst_after, std::abs(vy - after) / scale);
  }
  return f;
}

/// What a body sliding to a stop along y booked, at the run's end: the kinetic energy it lost
/// from v0, 1/2 M (v0^2 - v_y^2) [J], the ledger's friction heat [J] and its energy_error [-].
struct SlideBooks {
  double lost = 0.0, heat = 0.0, energy_error = 0.0;
};
inline SlideBooks slide_books(const Simulation& sim, int object, double v0);

/// Steps a run to its end: the worst |energy_error| over every step, and the share of kinetic
/// plus strain energy held as strain energy over the steps after `from` [s] (an exact elastic
/// bounce holds 0.5 on average).
struct BounceBooks {
  double worst = 0.0, strain_share = 0.0;
};
inline BounceBooks bounce_books(Simulation& sim, double from) {
  BounceBooks b;
  double strain = 0.0, books = 0.0;
  while (!sim.finished()) {
    sim.step();
    const LedgerRow r = sim.ledger().row();
    b.worst = std::max(b.worst, std::abs(r.energy_error));
    if (sim.time() > from) {
      strain += r.strain_energy;
      books += r.strain_energy + r.kinetic_energy;
    }
  }
  b.strain_share = strain / books;
  return b;
}

/// The ledger's sink column `name` [J] (e.g. "friction_heat"); 0 when the scene has no such
/// column (nothing of that kind can be booked in it).
inline double ledger_sink(const Ledger& ledger, const std::string& name) {
  const auto& names = ledger.sink_names();
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? 0.0 : ledger.row().sinks[std::size_t(it - names.begin())];
}

inline SlideBooks slide_books(const Simulation& sim, int object, double v0) {
  const BodyMotion b = motion_of(sim.particles(), object);
  return {0.5 * b.mass * (v0 * v0 - b.velocity(1) * b.velocity(1)),
          ledger_sink(sim.ledger(), "friction_heat"), sim.ledger().row().energy_error};
}

}  // namespace impact::mpm::test
