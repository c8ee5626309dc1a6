// How much of an object lies inside earlier objects: a seed point inside an earlier object is not
// seeded again (seed_points.hpp), so a body placed into another silently lost that part. The
// scene check warns when the share is above the seeding's own staircase
// (docs/scenes.md#objects). Geometric, so independent of the grid.
#pragma once

#include <cstddef>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

struct ObjectOverlap {
  /// The fraction of the object's volume inside earlier objects, sampled on grid_coverage.hpp's
  /// lattice (kCoverageLattice^3 points over its bounding box, 48^3) [-]
  double claimed = 0.0;
  /// The earlier objects (indices into Scene::objects) that hold part of it, ascending.
  std::vector<std::size_t> by;
};

ObjectOverlap object_overlap(const Scene& scene, std::size_t object);

}  // namespace impact::mpm
