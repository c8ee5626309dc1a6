// The crater an impact along +x leaves in the face x = face of an object (output.crater;
// docs/mpm.md#the-crater has the definition and a sketch), measured relative to the target's own
// motion so that depth and diameter are grid observables (issue 52: measured from initial
// positions, a plate that moved 0.8 mm added it to the depth, and once the grid's dx/2 fell below
// the plate's dishing every face particle counted as "displaced": a 53 mm "crater" in a 32 mm
// plate).
//   u_i      = (x - X0)_x of the face layer's particles (abs(X0_x - face) <= dx), into the target,
//              each weighted by its volume (an axisymmetric particle is a ring: its weight grows
//              with its radius, so weighted statistics are the revolved face's, as in 3D);
//   R_i      = a particle's current distance from the crater axis;
//   profile  = the weighted mean of u over rings of width w about the axis (w: the cell edge
//              across the face) at each ring's mean R, from (0, floor) outwards: the azimuthal
//              mean surface, smooth where the particle scatter is not;
//   floor    = max_i u_i (the deepest particle);
//   far      = the weighted median of u: the target's rigid and far-field motion, the surface's
//              level away from the crater while the crater covers less than half of the face
//              (`crater_fraction` says when not; a plate that dishes has no such level);
//   depth    = floor - far: how deep the crater goes below the surface as the target's own
//              motion has moved it (the apparent depth below the original surface);
//   half_depth_diameter = 2 R_half: the bowl's width at half its depth, where the profile first
//              rises to far + (floor - far)/2 going out from the axis (linear between the
//              profile's points): defined for every crater, with or without a rim, and the one
//              that converges with the grid; a hemispherical bowl's is 0.87, a cone's 0.5 of the
//              surface diameter;
//   surface_diameter = 2 R_surface: where the profile first rises back to the far field (the
//              apparent diameter at the original surface, as impact correlations give it); less
//              grid-stable (the profile meets the far field at a shallow angle);
//   rim      = a raised rim crest: the highest ring from R_half out to 3 R_half, if a ring
//              further out lies lower and it stands above the far field by more than 5 % of the
//              depth (lower: the particle scatter's): rim_diameter 2 R_rim (the rim-crest
//              diameter D_r of crater morphometry, Pike 1977), rim_to_floor_depth floor - u_rim,
//              rim_height far - u_rim; none otherwise;
//   crater_fraction = the face's weight within the crater (R_rim, else R_surface, else R_half);
//   perforated: floor - far reaches the target's thickness along x from the deepest particle's
//              initial position: the numbers then measure a plug, and the status says so.
// Particles with a non-finite position are left out. The face layer is Lagrangian: with
// erosion or jetting the original face no longer lines the crater, the floor is one particle's
// displacement, and ejecta of the face layer pull the ring means outwards.
// The axis: output.crater's axis_y/axis_z, or the axis of symmetry (axisymmetric), or the
// weighted mean current (y, z) of the particles below the half-depth level (the bowl's lower half).
// On several ranks the face layer is gathered on every rank (a few layers of cells) in seed-index
// order: every rank computes the one-rank crater.
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
  double depth = 0.0;                         ///< the floor below the far field [m]
  std::optional<double> half_depth_diameter;  ///< the bowl's width at half its depth [m]
  std::optional<double> surface_diameter;     ///< its width at the far field's level [m]
  std::optional<double> rim_diameter;         ///< a raised rim's crest diameter [m]
  std::optional<double> rim_to_floor;         ///< floor - u_rim [m]
  std::optional<double> rim_height;           ///< far - u_rim > 0: how far the rim stands out [m]
  double floor_displacement = 0.0;            ///< max u [m]
  double far_field_displacement = 0.0;        ///< weighted median u [m]: rigid, far-field motion
  std::optional<double> thickness;            ///< along x from the deepest particle's X0 [m]
  double axis_y = 0.0, axis_z = 0.0;  ///< the axis [m] (axisymmetric: 0, the axis of symmetry)
  double ring_width = 0.0;            ///< [m]
  double crater_fraction = 0.0;       ///< of the face's weight inside the crater [-]
  std::size_t face_particles = 0;     ///< the face layer: abs(X0_x - face) <= dx
  std::string status;                 ///< what was found, and what the numbers mean
  /// summary.json "crater".
  Json json(const std::string& object, double face) const;
};

/// One face particle: its axial displacement into the target u, its current position across the
/// face (y, z) and its weight (volume) [m, m, m, any].
struct FacePoint {
  double u, y, z, weight;
};

class CraterMeasure {
 public:
  /// `initial`: the particles as seeded (t = 0), those this rank holds; the face layer's seed
  /// indices and initial positions are kept (collective on several ranks).
  CraterMeasure(const Scene& scene, const CraterSpec& spec, const Particles& initial,
                const Communicator& comm);
  /// The crater now (collective on several ranks).
  Crater measure(const Particles& P) const;

 private:
  CraterSpec spec_;
  Geometry geometry_;  ///< the target's (its thickness along x)
  double dx_ = 0.0, ring_width_ = 0.0, grid_upper_x_ = 0.0;
  bool rings_ = false;  ///< the particles are rings about the x axis (scene/grid_geometry.hpp)
  ParticleSets face_;   ///< set 0: the face layer
  std::vector<Vec3> face_x0_;  ///< their initial positions, in seed-index order
  const Communicator& comm_;
};

/// The crater of face particles (current positions across the face), without the particle
/// bookkeeping: what CraterMeasure computes once the layer is gathered. `axis`: the fixed axis if
/// any; `revolved`: the particles are rings about x (axisymmetric), y is the radius and the axis y
/// = 0; `thickness`: the target's along x at the floor, for the perforation test (nullopt: not
/// tested).
Crater crater_of(const std::vector<FacePoint>& face, double ring_width,
                 const std::optional<std::array<double, 2>>& axis, bool revolved,
                 std::optional<double> thickness = std::nullopt);

}  // namespace impact::mpm
