#include "mpm/scene/seed_points.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

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

namespace {

// Whether object `object` has a seed point x in the cells `c` for which keep(x) holds, the cells
// visited in shells of growing Chebyshev distance from the middle one (each cell once).
template <class Keep>
bool finds_a_seed_point(const Scene& scene, std::size_t object, const SeedCells& c, Keep&& keep) {
  std::array<int, 3> mid{};
  int reach = 0;
  for (int d = 0; d < 3; ++d) {
    if (c.begin[d] >= c.end[d]) return false;
    mid[d] = (c.begin[d] + c.end[d] - 1) / 2;
    reach = std::max({reach, mid[d] - c.begin[d], c.end[d] - 1 - mid[d]});
  }
  const auto found_in = [&](int i, int j, int k) {
    return !seed_points_of_cell(scene, object, i, j, k, [&](const Vec3& x) { return !keep(x); });
  };
  for (int s = 0; s <= reach; ++s) {
    const int k_first = std::max(c.begin[2], mid[2] - s),
              k_last = std::min(c.end[2] - 1, mid[2] + s);
    for (int i = std::max(c.begin[0], mid[0] - s); i <= std::min(c.end[0] - 1, mid[0] + s); ++i)
      for (int j = std::max(c.begin[1], mid[1] - s); j <= std::min(c.end[1] - 1, mid[1] + s); ++j) {
        if (std::abs(i - mid[0]) == s || std::abs(j - mid[1]) == s) {  // on the shell: every k
          for (int k = k_first; k <= k_last; ++k)
            if (found_in(i, j, k)) return true;
        } else {  // inside it: the shell's two k faces
          if (mid[2] - s >= c.begin[2] && found_in(i, j, mid[2] - s)) return true;
          if (mid[2] + s < c.end[2] && found_in(i, j, mid[2] + s)) return true;
        }
      }
  }
  return false;
}

}  // namespace

bool seeds_a_point(const Scene& scene, std::size_t object) {
  const auto [lo, hi] = bounds(scene.objects[object].geometry);
  return finds_a_seed_point(scene, object, seed_cells(scene, object, lo, hi),
                            [](const Vec3&) { return true; });
}

bool seeds_a_point(const Scene& scene, std::size_t object, const Vec3& lower, const Vec3& upper) {
  return finds_a_seed_point(scene, object, seed_cells(scene, object, lower, upper),
                            [&](const Vec3& x) { return in_box(x, lower, upper); });
}

}  // namespace impact::mpm
