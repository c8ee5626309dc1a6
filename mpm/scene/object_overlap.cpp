#include "mpm/scene/object_overlap.hpp"

#include "mpm/scene/grid_coverage.hpp"

namespace impact::mpm {

ObjectOverlap object_overlap(const Scene& scene, std::size_t object) {
  ObjectOverlap overlap;
  const Geometry& body = scene.objects[object].geometry;
  const auto [lo, hi] = bounds(body);
  if (!lo.allFinite() || !hi.allFinite()) return overlap;
  // Only earlier objects whose bounding boxes meet this one's can hold part of it.
  std::vector<std::size_t> near;
  for (std::size_t e = 0; e < object; ++e) {
    const auto [elo, ehi] = bounds(scene.objects[e].geometry);
    if ((elo.array() < hi.array()).all() && (ehi.array() > lo.array()).all()) near.push_back(e);
  }
  if (near.empty()) return overlap;
  std::vector<bool> holds(near.size(), false);
  std::size_t in_body = 0, claimed = 0;
  for_each_lattice_point(lo, hi, kCoverageLattice, [&](const Vec3& x) {
    if (!inside(body, x)) return;
    ++in_body;
    bool any = false;
    for (std::size_t a = 0; a < near.size(); ++a)
      if (inside(scene.objects[near[a]].geometry, x)) {
        holds[a] = true;
        any = true;
      }
    if (any) ++claimed;
  });
  if (in_body == 0) return overlap;  // thinner than the lattice: left to the seed count
  overlap.claimed = double(claimed) / double(in_body);
  for (std::size_t a = 0; a < near.size(); ++a)
    if (holds[a]) overlap.by.push_back(near[a]);
  return overlap;
}

}  // namespace impact::mpm
