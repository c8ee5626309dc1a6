// The seed points of a scene: the ppc^3 sub-cell centres of the grid cells inside each object's
// geometry and not inside an earlier object (the report's seeding). What a scene is (its bodies
// and grid) fixes them; mpm/particles/seeding.cpp creates particles at them, and the scene reader
// counts them to refuse a body that would get none.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// The cells, [begin, end) per axis, that can hold seed points of object `oi` inside the box
/// [lo, hi]: those the box overlaps within the object's bounding box and the grid.
struct SeedCells {
  std::array<int, 3> begin{}, end{};
};

inline SeedCells seed_cells(const Scene& scene, std::size_t oi, const Vec3& lo, const Vec3& hi) {
  const GridSpec& g = scene.grid;
  const Vec3 h = g.spacing();
  // Only the cells of the object's bounding box can hold its points: a gauge region that spans a
  // fine grid (or 1e300) costs what seeding the object costs, not a walk over the whole box.
  const auto [blo, bhi] = bounds(scene.objects[oi].geometry);
  const Vec3 box_lo = lo.cwiseMax(blo);
  const Vec3 box_hi = hi.cwiseMin(bhi);
  // Clamped in double before the conversion: a box far outside the grid (a scene's gauge region
  // of 1e300) would overflow int (undefined behaviour); NaN (inf / inf) gives an empty range.
  const auto cell = [&](double x, int d) {
    return x > 0.0 ? static_cast<int>(std::min(x, static_cast<double>(g.cells[d]))) : 0;
  };
  SeedCells c;
  for (int d = 0; d < 3; ++d) {
    if (g.graded()) {  // the cells whose span meets [box_lo, box_hi] (NaN: none)
      if (!(box_lo(d) <= box_hi(d)) || box_hi(d) < g.lower(d) || box_lo(d) > g.upper(d)) {
        c.begin[d] = c.end[d] = 0;
        continue;
      }
      c.begin[d] = g.cell_along(d, box_lo(d));
      c.end[d] = g.cell_along(d, box_hi(d)) + 1;
      continue;
    }
    c.begin[d] = cell(std::floor((box_lo(d) - g.lower(d)) / h(d)), d);
    c.end[d] = cell(std::ceil((box_hi(d) - g.lower(d)) / h(d)), d);
  }
  return c;
}

/// Calls add(x) for each seed point x of object `oi` in cell (i, j, k): the ppc^3 sub-cell
/// centres inside the object's geometry and not inside an earlier object, in a fixed order.
/// Returns false as soon as add does (the rest of the cell is not visited).
template <class Add>
inline bool seed_points_of_cell(const Scene& scene, std::size_t oi, int i, int j, int k,
                                Add&& add) {
  const GridSpec& g = scene.grid;
  const Vec3 h = g.spacing();
  const SceneObject& o = scene.objects[oi];
  const auto& ppc = o.particles_per_cell;
  for (int a = 0; a < ppc[0]; ++a)
    for (int b = 0; b < ppc[1]; ++b)
      for (int e = 0; e < ppc[2]; ++e) {
        const Vec3 x =
            g.graded()
                ? Vec3(g.node(0, i) + g.cell_size(0, i) * (a + 0.5) / ppc[0],
                       g.node(1, j) + g.cell_size(1, j) * (b + 0.5) / ppc[1],
                       g.node(2, k) + g.cell_size(2, k) * (e + 0.5) / ppc[2])
                : Vec3(g.lower + h.cwiseProduct(Vec3(i + (a + 0.5) / ppc[0], j + (b + 0.5) / ppc[1],
                                                     k + (e + 0.5) / ppc[2])));
        if (!inside(o.geometry, x)) continue;
        const bool claimed =
            std::any_of(scene.objects.begin(), scene.objects.begin() + oi,
                        [&](const SceneObject& earlier) { return inside(earlier.geometry, x); });
        if (claimed) continue;
        if (!add(x)) return false;
      }
  return true;
}

// Calls add(x, i) for every seed point x of object `oi` in the grid cells that the box [lo, hi]
// overlaps, i its cell column along x: the ppc^3 sub-cell centres inside the object's geometry and
// not inside an earlier object, columns outermost. The points of a cell do not depend on the box,
// so a smaller box gives a subset of the same doubles in the same order. An add that returns bool
// stops the walk by returning false.
template <class Add>
inline void for_each_seed_point(const Scene& scene, std::size_t oi, const Vec3& lo, const Vec3& hi,
                                Add&& add) {
  const SeedCells c = seed_cells(scene, oi, lo, hi);
  for (int i = c.begin[0]; i < c.end[0]; ++i)
    for (int j = c.begin[1]; j < c.end[1]; ++j)
      for (int k = c.begin[2]; k < c.end[2]; ++k) {
        const bool go_on = seed_points_of_cell(scene, oi, i, j, k, [&](const Vec3& x) {
          if constexpr (std::is_same_v<std::invoke_result_t<Add&, const Vec3&, int>, bool>) {
            return add(x, i);
          } else {
            add(x, i);
            return true;
          }
        });
        if (!go_on) return;
      }
}

/// The number of seed points of object `object` (what seed_particles() would create) inside the
/// closed box [lower, upper]: seeds only the cells the box overlaps (a gauge's particle count in
/// mpm check's report and summary.json).
std::size_t count_seed_points(const Scene& scene, std::size_t object, const Vec3& lower,
                              const Vec3& upper);

/// Whether seed_particles() gives object `object` at least one particle (the scene check refuses
/// a body that would get none). Looks from the middle cell of its bounding box outwards, one
/// shell of cells after another, and stops at the first point found: a body's points lie about
/// its middle, so a scene the memory estimate will refuse costs a few cells here, not a sweep
/// (a sphere on 1200^3 cells at 16^3 particles per cell: 15 s in column order).
bool seeds_a_point(const Scene& scene, std::size_t object);
/// Whether object `object` has a seed point inside the closed box [lower, upper] (the reader's
/// check of a gauge region and a crater face), looked for in the same order (a crater face
/// within one cell of a sphere's tip: the tip's cells first).
bool seeds_a_point(const Scene& scene, std::size_t object, const Vec3& lower, const Vec3& upper);

/// x inside the closed box [lower, upper] (the gauges' and the seed count's membership test).
inline bool in_box(const Vec3& x, const Vec3& lower, const Vec3& upper) {
  return (x.array() >= lower.array()).all() && (x.array() <= upper.array()).all();
}

/// Per object: GIMP half-width l_d = 1/(2 ppc_d) in cells (fixed at creation, as in the report).
std::vector<Vec3> half_widths(const Scene& scene);

/// The share of its cell a particle of object `oi` seeded at x takes: the cell's volume over
/// ppc^3 [m^3; a 2D grid's cell is 1 m along z]. On a graded grid, the cell x lies in.
inline double seeded_cell_share(const Scene& scene, std::size_t oi, const Vec3& x) {
  const GridSpec& g = scene.grid;
  const auto& ppc = scene.objects[oi].particles_per_cell;
  if (!g.graded()) return g.spacing().prod() / (ppc[0] * ppc[1] * ppc[2]);
  const std::array<int, 3> c = g.cell_of(x);
  return g.cell_size(0, c[0]) * g.cell_size(1, c[1]) * g.cell_size(2, c[2]) /
         (ppc[0] * ppc[1] * ppc[2]);
}

/// On a graded grid, the uGIMP half-width [m] of a particle of object `oi` seeded at x: half its
/// sub-cell, size_d / (2 ppc_d) of the cell it is seeded in (Nairn's tartan GIMP), fixed then.
inline Vec3 seeded_half_width(const Scene& scene, std::size_t oi, const Vec3& x) {
  const GridSpec& g = scene.grid;
  const auto& ppc = scene.objects[oi].particles_per_cell;
  const std::array<int, 3> c = g.cell_of(x);
  return {g.cell_size(0, c[0]) / (2.0 * ppc[0]), g.cell_size(1, c[1]) / (2.0 * ppc[1]),
          g.cell_size(2, c[2]) / (2.0 * ppc[2])};
}

}  // namespace impact::mpm
