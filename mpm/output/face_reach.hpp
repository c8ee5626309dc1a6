// Material that reaches an outer face of the grid that no material was near at the start
// (summary.json "material_reached_faces", a warning on stderr; docs/mpm.md#output). A mirror
// (symmetric), fixed or free face placed away from the bodies is meant as far field: a body that
// reaches it is confined (reflected, held) or about to leave, and the observables measured from
// then on are no longer those of the scene the user meant (a Taylor rod's mushroom splashing into
// a mirror face 2.2 R0 from its axis ends 18.6 % too long; issue 52). Walls are contact by design
// and the axis of an axisymmetric grid is no face: neither is watched. A face is watched only
// when no particle lies near it at the start (within one cell along its axis, or 5 % of the
// grid's extent along it when that is more, so that the choice does not change with the grid): a
// symmetry plane through a body, or a body placed against a face, is meant. Reached means a
// particle in its one-cell layer.
// Sampled at the history rows only (one pass over the particles per row); on several ranks the
// counts are summed, so every rank agrees.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

class FaceReach {
 public:
  /// `initial`: the particles as seeded (those this rank holds).
  FaceReach(const Scene& scene, const Particles& initial, const Communicator& comm);

  /// At a history row: the watched faces' layers are counted; returns the faces reached for the
  /// first time now (kFaceNames indices).
  std::vector<int> sample(const Particles& P, double time);
  /// {"face", "condition", "first_time [s]", "particles"} per face reached ("particles": the most
  /// particles seen in its layer at one history row); an empty array when none was.
  Json summary() const;
  /// The warning for face f reached at `time`: what it means and what to do.
  std::string warning(int face) const;

  /// first times (NaN: not reached) and counts, six each, for a checkpoint.
  std::vector<double> state() const;
  /// Throws std::invalid_argument for a state of another size.
  void restore(const std::vector<double>& state);

 private:
  std::array<bool, 6> watched_{};
  std::array<double, 6> first_time_{};
  std::array<double, 6> most_{};
  std::array<FaceCondition, 6> condition_{};
  std::array<double, 6> plane_{}, layer_{};  ///< the face's coordinate, one cell [m]
  std::array<double, 6> near_{};             ///< "near at the start": max(cell, 5 % extent) [m]
  const Communicator& comm_;
  /// Particles in each face's layer.
  std::array<double, 6> count(const Particles& P) const;
  /// Particles within `within` [m] of each watched face.
  std::array<double, 6> count(const Particles& P, const std::array<double, 6>& within) const;
};

}  // namespace impact::mpm
