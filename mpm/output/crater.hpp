// The crater an impact along +x leaves in the face x = face of an object (output.crater;
// docs/mpm.md#output has the definition and a sketch), measured relative to the target's own
// motion so that depth and diameter are grid observables (issue 52: measured from initial
// positions, a plate that moved 0.8 mm added it to the depth, and once the grid's dx/2 fell below
// the plate's dishing every face particle counted as "displaced": a 53 mm "crater" in a 32 mm
// plate).
//   u_i     = (x - X0)_x of the face layer's particles (abs(X0_x - face) <= dx), into the target;
//   R_i     = a particle's current distance from the crater axis;
//   profile = the mean of u over rings of width w about the axis (w: the cell edge across the
//             face), at each ring's mean R: the azimuthal mean surface, smooth where the particle
//             scatter is not;
//   floor   = max_i u_i (the deepest particle);
//   far     = the median of u over the face layer: the target's rigid and far-field motion
//             (the crater covers less than half of the face; `crater_fraction` says when not);
//   rim     = the rim crest: going out from the deepest ring, the first ring below the half-depth
//             level (far + (floor - far)/2) whose outer neighbour lies lower, u(k+1) >= u(k);
//             its mean radius and mean u (to within a ring width, which shrinks with h);
//   depth    = floor - u_rim (rim-to-floor depth), diameter = 2 R_rim (rim-crest diameter),
//             as crater morphometry measures them (Pike 1977): both move with the surface around
//             the crater, not with the plate.
// Without a rim (the face rises to its edge) the diameter is null and the depth is measured
// below the far field, with a status saying so.
// The axis: output.crater's axis_y/axis_z, or the axis of symmetry (axisymmetric), or the mean
// current (y, z) of the particles below the half-depth level (the bowl's lower half).
// On several ranks the face layer is gathered on every rank (a few layers of cells): every rank
// computes the same crater.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "mpm/output/particle_sets.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

struct Crater {
  double depth = 0.0;                   ///< rim-to-floor, or below the far field without a rim [m]
  std::optional<double> diameter;       ///< rim-crest diameter [m]; none without a rim
  std::optional<double> rim_radius;     ///< [m]
  double floor_displacement = 0.0;      ///< max u [m]
  double rim_displacement = 0.0;        ///< u at the rim crest [m] (the far field without a rim)
  double far_field_displacement = 0.0;  ///< median u [m]: the target's rigid and far-field motion
  double axis_y = 0.0, axis_z = 0.0;    ///< the axis [m] (axisymmetric: 0, the axis of symmetry)
  double ring_width = 0.0;              ///< [m]
  double crater_fraction = 0.0;         ///< face particles inside the rim / all [-]
  std::size_t face_particles = 0;       ///< the face layer: abs(X0_x - face) <= dx
  std::string status;                   ///< "rim found", or why there is none
  /// summary.json "crater".
  Json json(const std::string& object, double face) const;
};

class CraterMeasure {
 public:
  /// `initial`: the particles as seeded (t = 0), those this rank holds; the face layer's seed
  /// indices and initial positions are kept (collective on several ranks).
  CraterMeasure(const Scene& scene, const CraterSpec& spec, const Particles& initial,
                const Communicator* comm);
  /// The crater now (collective on several ranks).
  Crater measure(const Particles& P) const;

 private:
  CraterSpec spec_;
  double dx_ = 0.0, ring_width_ = 0.0;
  bool axisymmetric_ = false;
  ParticleSets face_;          ///< set 0: the face layer
  std::vector<Vec3> face_x0_;  ///< their initial positions, in seed-index order
  const Communicator* comm_;
};

/// The crater of face particles given as (u, y, z) (current positions across the face), without
/// the particle bookkeeping: what CraterMeasure computes once the layer is gathered.
/// `axis`: the fixed axis if any; `axisymmetric`: y is the radius and the axis y = 0.
Crater crater_of(const std::vector<double>& u, const std::vector<double>& y,
                 const std::vector<double>& z, double ring_width,
                 const std::optional<std::array<double, 2>>& axis, bool axisymmetric);

}  // namespace impact::mpm
