#include "mpm/scene/object_overlap.hpp"

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
  constexpr int n = kOverlapLattice;
  const Vec3 step = (hi - lo) / n;
  std::vector<bool> holds(near.size(), false);
  std::size_t in_body = 0, claimed = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 x = lo + step.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
        if (!inside(body, x)) continue;
        ++in_body;
        bool any = false;
        for (std::size_t a = 0; a < near.size(); ++a)
          if (inside(scene.objects[near[a]].geometry, x)) {
            holds[a] = true;
            any = true;
          }
        if (any) ++claimed;
      }
  if (in_body == 0) return overlap;  // thinner than the lattice: left to the seed count
  overlap.claimed = double(claimed) / double(in_body);
  for (std::size_t a = 0; a < near.size(); ++a)
    if (holds[a]) overlap.by.push_back(near[a]);
  return overlap;
}

}  // namespace impact::mpm
