#include "mpm/scene/seed_points.hpp"

namespace impact::mpm {

std::vector<Vec3> half_widths(const Scene& scene) {
  std::vector<Vec3> l;
  for (const SceneObject& o : scene.objects) {
    l.emplace_back(0.5 / o.particles_per_cell[0], 0.5 / o.particles_per_cell[1],
                   0.5 / o.particles_per_cell[2]);
  }
  return l;
}

std::size_t count_seed_points(const Scene& scene, std::size_t object, const Vec3& lower,
                              const Vec3& upper) {
  std::size_t n = 0;
  for_each_seed_point(scene, object, lower, upper,
                      [&](const Vec3& x, int) { n += in_box(x, lower, upper) ? 1 : 0; });
  return n;
}

bool seeds_a_point(const Scene& scene, std::size_t object) {
  // Stops at the first point: a body the run will seed costs a few cells, not its whole walk.
  bool found = false;
  const auto [lo, hi] = bounds(scene.objects[object].geometry);
  for_each_seed_point(scene, object, lo, hi, [&](const Vec3&, int) {
    found = true;
    return false;
  });
  return found;
}

}  // namespace impact::mpm
