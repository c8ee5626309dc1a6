#include "mpm/scene/grid_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace impact::mpm {

namespace {

bool in_grid(const GridSpec& grid, const Vec3& x) {
  return (x.array() >= grid.lower.array()).all() && (x.array() <= grid.upper.array()).all();
}

}  // namespace

GridCoverage grid_coverage(const Geometry& geometry, const GridSpec& spec) {
  // A 2D grid models the body's whole extent along z (its section, planar_form.hpp): unbounded.
  GridSpec grid = spec;
  if (spec.planar()) {
    grid.lower(2) = -std::numeric_limits<double>::infinity();
    grid.upper(2) = std::numeric_limits<double>::infinity();
  }
  // Rings about x (axisymmetric): a point of the body is modelled where its radius is, so it is
  // taken at (x, r, 0); the bound below sees the grid's radial range on both sides of the axis.
  const bool rings = spec.geometry_facts().rings;
  if (rings) grid.lower(1) = -grid.upper(1);
  const auto on_grid = [&](const Vec3& x) {
    return rings ? Vec3(x(0), std::hypot(x(1), x(2)), 0.0) : x;
  };
  GridCoverage c;
  const auto [lo, hi] = bounds(geometry);
  const Vec3 extent = hi - lo;
  const double box = extent.prod();
  const double v = std::min(volume(geometry), box);
  if (!lo.allFinite() || !hi.allFinite() || !(v > 0.0)) return c;  // nothing to measure
  if (in_grid(grid, lo) && in_grid(grid, hi)) return c;            // wholly inside
  const Vec3 overlap = hi.cwiseMin(grid.upper) - lo.cwiseMax(grid.lower);
  if (!(overlap.array() > 0.0).all()) {
    c.inside_bound = 0.0;
    c.disjoint = true;
    c.inside = 0.0;
    c.lost = 1.0;
    return c;
  }
  // vol(box inside) / v as the box's share per axis over the body's share of its box: a body of
  // 1e300 m has volumes beyond a double (inf / inf), its shares do not. One whose volume
  // overflows is taken to fill its box.
  const double fill = std::isfinite(box) ? v / box : 1.0;
  c.inside_bound = std::min(1.0, overlap.cwiseQuotient(extent).prod() / fill);
  // Cell centres of an n^3 lattice on the bounding box: each point of the body is inside, the
  // mirror image of a point inside (beyond symmetric faces only), or lost.
  std::size_t body = 0, in = 0, lost = 0;
  for_each_lattice_point(lo, hi, kCoverageLattice, [&](const Vec3& point) {
    if (!inside(geometry, point)) return;
    ++body;
    const Vec3 x = on_grid(point);
    if (in_grid(grid, x)) {
      ++in;
      return;
    }
    Vec3 mirror = x;
    std::array<bool, 6> beyond{};
    for (int d = 0; d < 3; ++d) {
      const int face = x(d) < grid.lower(d) ? 2 * d : x(d) > grid.upper(d) ? 2 * d + 1 : -1;
      if (face < 0) continue;
      beyond[std::size_t(face)] = true;
      const double plane = face % 2 == 0 ? grid.lower(d) : grid.upper(d);
      if (grid.faces[std::size_t(face)] == FaceCondition::symmetric) mirror(d) = 2.0 * plane - x(d);
    }
    // modelled by symmetry (a ring's mirror across the axis is itself: never reached)
    if (in_grid(grid, mirror) && inside(geometry, mirror)) return;
    ++lost;
    for (std::size_t f = 0; f < 6; ++f) c.lost_through[f] = c.lost_through[f] || beyond[f];
  });
  if (body == 0) return c;  // thinner than the lattice: left to the seed count (scene.cpp)
  c.sampled = true;
  c.inside = double(in) / double(body);
  c.lost = double(lost) / double(body);
  return c;
}

}  // namespace impact::mpm
