// How much of an object's geometry lies inside the grid: only that part is seeded. The scene check
// (scene.cpp) refuses a body with (almost) nothing inside and warns on one the grid clips
// (docs/scenes.md#objects-and-the-grid). Geometric, so independent of the seeding's staircase.
#pragma once

#include <array>

#include "mpm/geometry/geometry.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

struct GridCoverage {
  /// vol(bounding box inside the grid) / volume(geometry), at most 1: no more of the body can lie
  /// inside the grid (exact) [-]
  double inside_bound = 1.0;
  /// The bounding box misses the grid: nothing of the body lies inside (exact)
  bool disjoint = false;
  /// Whether `inside` and `lost` were sampled (the bounding box crosses the grid's boundary and
  /// the lattice hit the body); otherwise they are exact (box inside: 1 and 0) or unknown.
  bool sampled = false;
  /// The fraction of the body's volume inside the grid [-]
  double inside = 1.0;
  /// The fraction outside the grid that is not the mirror image, across a symmetric face, of a
  /// part inside (a half or quarter model is clipped on purpose): the volume lost [-]
  double lost = 0.0;
  /// The faces (kFaceNames order) that the lost part lies beyond.
  std::array<bool, 6> lost_through{};
};

/// Lattice points per axis over the body's bounding box when it crosses the grid's boundary:
/// 48^3 = 110592 inside() tests, a few ms; a sphere cut by a face then measures 0.8442 inside
/// against the exact 0.84375 (tests/mpm/scene/grid_coverage_test.cpp).
inline constexpr int kCoverageLattice = 48;

GridCoverage grid_coverage(const Geometry& geometry, const GridSpec& grid);

}  // namespace impact::mpm
