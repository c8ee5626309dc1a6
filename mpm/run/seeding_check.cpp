#include "mpm/run/seeding_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <sstream>

#include "models/core/input.hpp"
#include "mpm/scene/grid_geometry.hpp"

namespace impact::mpm {

namespace {

// The volume object `o`'s particles should fill, in their own measure: the part of the body inside
// the grid and outside every earlier object (a point there is seeded once, by the earlier one).
// Exact (the modelled volume) when the body lies wholly inside the grid and no earlier body's
// bounding box meets its own; otherwise sampled where the seeding seeds, at the cell centres of
// a lattice on the body's bounding box clipped to the grid: a 3D grid's box; on a 2D grid the
// section z = 0 that the seed points lie in (per metre of thickness), and for rings about x each
// point weighed by 2 pi r. At least 64 points per axis and two per seed spacing, 2^23 in all at
// most. (Measured as the body's share of its whole bounding box less a share claimed by earlier
// bodies anywhere, a quarter rod pushed into a plate, a body overlapping another outside the grid
// and a body mostly outside it were warned of falsely, up to 1.67: the trial of 6e8a976.)
double fill_volume(const Scene& scene, std::size_t o) {
  const GridSpec& g = scene.grid;
  const SceneObject& object = scene.objects[o];
  const bool planar = g.planar(), rings = g.geometry_facts().rings;
  auto [lo, hi] = bounds(object.geometry);
  std::vector<std::size_t> earlier;
  for (std::size_t e = 0; e < o; ++e)
    if (boxes_meet(bounds(scene.objects[e].geometry), {lo, hi})) earlier.push_back(e);
  // The grid's region in the body's coordinates: rings reach -r_max..r_max in y and z.
  Vec3 grid_lo = g.lower, grid_hi = g.upper;
  if (planar) {
    grid_lo(2) = -std::numeric_limits<double>::infinity();
    grid_hi(2) = std::numeric_limits<double>::infinity();
  }
  if (rings) grid_lo(1) = grid_lo(2) = -g.upper(1), grid_hi(2) = g.upper(1);
  const bool wholly_inside =
      (lo.array() >= grid_lo.array()).all() && (hi.array() <= grid_hi.array()).all();
  if (wholly_inside && earlier.empty())
    return visit_geometry(g.geometry, [&](auto geometry) {
      return decltype(geometry)::modelled_volume(object.geometry);
    });
  const int axes = planar ? 2 : 3;
  if (rings) lo(1) = 0.0;  // the meridian half-plane, r = y
  lo = lo.cwiseMax(g.lower);
  hi = hi.cwiseMin(g.upper);
  if (planar) lo(2) = hi(2) = 0.0;  // the seed points' section
  if (!((hi - lo).head(axes).array() > 0.0).all()) return 0.0;
  const Vec3 seed_spacing = g.smallest_cell().cwiseQuotient(Vec3(
      object.particles_per_cell[0], object.particles_per_cell[1], object.particles_per_cell[2]));
  std::array<long, 3> n{1, 1, 1};
  double total = 1.0;
  for (int d = 0; d < axes; ++d) {
    n[std::size_t(d)] =
        std::max(64L, static_cast<long>(std::ceil(2.0 * (hi(d) - lo(d)) / seed_spacing(d))));
    total *= double(n[std::size_t(d)]);
  }
  const double cap = double(1L << 23);
  if (total > cap)  // the same share off every axis
    for (int d = 0; d < axes; ++d)
      n[std::size_t(d)] =
          std::max(1L, static_cast<long>(n[std::size_t(d)] * std::pow(cap / total, 1.0 / axes)));
  double sum = 0.0;
  for_each_lattice_point(lo, hi, n, [&](const Vec3& x) {
    if (!inside(object.geometry, x)) return;
    for (const std::size_t e : earlier)
      if (inside(scene.objects[e].geometry, x)) return;
    sum += rings ? 2.0 * std::numbers::pi * x(1) : 1.0;
  });
  const Vec3 step = (hi - lo).cwiseQuotient(Vec3(double(n[0]), double(n[1]), double(n[2])));
  return sum * step.head(axes).prod();
}

}  // namespace

std::vector<std::string> seeding_warnings(const Scene& scene, const Particles& P,
                                          const Communicator& comm) {
  std::vector<double> seeded(scene.objects.size(), 0.0);
  for (std::size_t p = 0; p < P.size(); ++p) seeded[P.object[p]] += P.volume0[p];
  seeded = comm.sum(seeded);
  std::vector<std::string> warnings;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    const double expected = fill_volume(scene, o);
    if (!(expected > 0.0) || seeded[o] == 0.0) continue;  // refused or warned of when read
    const double ratio = seeded[o] / expected;
    if (std::abs(ratio - 1.0) <= kSeedingVolumeTolerance) continue;
    const Vec3 h = scene.grid.largest_cell();
    std::ostringstream m;
    m.precision(3);
    m << scene.file << ": /objects/" << pointer_token(object.name)
      << "/geometry: its particles hold " << std::setprecision(4) << ratio << std::setprecision(3)
      << " of the volume they should fill (" << seeded[o] << " of " << expected
      << (scene.grid.per_metre_of_thickness() ? " m^3 per m" : " m^3")
      << ", its part inside the grid and outside earlier objects): seeded at the sub-cell centres ("
      << object.particles_per_cell[0] << " x " << object.particles_per_cell[1] << " x "
      << object.particles_per_cell[2] << " per cell; cells up to [" << h(0) << ", " << h(1) << ", "
      << h(2)
      << "] m), its faces cut the cells; the mass is off by as much: align its faces with "
         "the cells, or raise particles_per_cell";
    warnings.push_back(m.str());
  }
  return warnings;
}

}  // namespace impact::mpm
