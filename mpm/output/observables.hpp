// Observables for accuracy-versus-cost studies, definitions in docs/mpm.md#output:
// - Gauges (output.gauges): history.csv columns `gauge_<name> [unit]`, each the mass-weighted
//   mean over a fixed set of particles (one object's, initial position in a box) of a velocity
//   component, a log-strain component or the pressure, read at every history row.
// - Observables: summary.json "observables": per object mass, mean velocity, kinetic energy and
//   the largest particle pressure seen at the history rows; the crater of output.crater
//   (mpm/output/crater.hpp).
// Both take their particle sets from the particles as seeded (t = 0) and keep only seed-index
// lists (and, for the crater, the initial positions of its face layer): a scene without gauges or
// crater stores nothing per particle and does no per-step work. On several ranks every rank
// holds the sets, reads the particles it holds and the partial sums and extrema are reduced
// (sums in rank order, mpm/parallel/communicator.hpp): every call that reads particles is then
// collective, and no rank ever needs another's particles.
#pragma once

#include <string>
#include <vector>

#include "mpm/ledger/extensive_units.hpp"
#include "mpm/output/crater.hpp"
#include "mpm/output/particle_sets.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"

namespace impact::mpm {

/// Log (Hencky) strain along axis c: ln of the stretch of F along c, 0.5 ln (F^T F)_cc [-].
inline double log_strain(const Mat3& F, int c) {
  return 0.5 * std::log(F.col(c).squaredNorm());
}

/// Pressure -tr(sigma)/3 [Pa] (the VTU field `pressure`; artificial viscosity not included).
inline double pressure(const Mat3& stress) {
  return -stress.trace() / 3.0;
}

class Gauges {
 public:
  /// `initial`: the particles as seeded (t = 0), those this rank holds; membership (initial
  /// position in the region, closed box) is fixed here. Throws std::logic_error for an empty
  /// gauge (read_scene rejects one).
  Gauges(const Scene& scene, const Particles& initial, const Communicator& comm);

  bool empty() const { return gauges_.empty(); }
  std::size_t size() const { return gauges_.size(); }
  /// "gauge_<name> [m/s]" (velocity), "[-]" (strain), "[Pa]" (pressure), in scene order (names
  /// sorted).
  std::vector<std::string> columns() const;
  /// Each gauge's unit, columns() order: "m/s", "-" or "Pa".
  std::vector<std::string> units() const;
  /// The current readings, columns() order (P: the particles this rank holds).
  std::vector<double> read(const Particles& P) const;
  /// The seed indices of gauge g's members, ascending.
  const std::vector<std::uint64_t>& members(std::size_t g) const { return members_.ids(g); }

 private:
  struct Gauge {
    std::string column;
    std::string unit;
    GaugeType type;
    int component;
  };
  std::vector<Gauge> gauges_;
  ParticleSets members_;  ///< set g: gauge g's members
  const Communicator& comm_;
};

class Observables {
 public:
  /// `initial`: the particles as seeded (t = 0), those this rank holds.
  Observables(const Scene& scene, const Particles& initial, const Communicator& comm);

  /// At every history row: the running maximum pressure per object (sampled there only).
  void sample(const Particles& P, double time);
  bool has_crater() const { return crater_.has_value(); }
  /// The crater now (output.crater must be set; collective on several ranks).
  Crater crater(const Particles& P) const { return crater_->measure(P); }
  /// summary.json "observables": {"objects": {name: {...}}, "crater": {...}}.
  Json summary(const Particles& P) const;
  /// The running maxima (max pressure and its time per object), for a checkpoint.
  std::vector<double> state() const;
  /// Throws std::invalid_argument when the size does not match this scene's objects.
  void restore(const std::vector<double>& state);

 private:
  std::vector<std::string> names_;
  std::vector<double> max_pressure_, max_pressure_time_;
  std::optional<CraterMeasure> crater_;
  std::string crater_object_;
  double crater_face_ = 0.0;
  /// The velocity components that are physical (1) or cancel by symmetry (0; an axisymmetric
  /// grid's radial and hoop ones: scene/grid_geometry.hpp kMomentumComponents).
  Vec3 momentum_components_ = Vec3::Ones();
  ExtensiveUnits units_;  ///< of the objects' mass and kinetic energy (plane strain: per metre)
  const Communicator& comm_;
};

}  // namespace impact::mpm
