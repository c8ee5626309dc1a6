#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "mpm/particles/particles.hpp"
#include "mpm/scene/initial_fields.hpp"

namespace impact::mpm {

void Particles::reserve(std::size_t n) {
  for_each_particle_array([&](const auto& a) {
    if (!a.optional) (this->*a.member).reserve(n);
  });
}

void Particles::keep_only(const std::vector<char>& keep) {
  const std::size_t n = size();
  for_each_array([&](auto& a) {
    if (a.size() != n) return;  // an optional array not in use
    std::size_t out = 0;
    for (std::size_t p = 0; p < n; ++p)
      if (keep[p]) a[out++] = a[p];
    a.resize(out);
  });
}

void Particles::permute(const std::vector<std::size_t>& order) {
  const std::size_t n = size();
  for_each_array([&](auto& a) {
    if (a.size() != n) return;  // an optional array not in use
    auto old = a;
    for (std::size_t p = 0; p < n; ++p) a[p] = old[order[p]];
  });
}

std::size_t Particles::bytes_per_particle() {
  std::size_t bytes = 0;
  for_each_particle_array([&](const auto& a) {
    if (!a.optional) bytes += sizeof(typename std::decay_t<decltype(a)>::Element);
  });
  return bytes;
}

namespace {

// Appends object oi's seed points in the cells the box [lo, hi] overlaps for which keep(x) holds
// to p, at rest in their initial state. keep sees every point, in seed order.
template <class Keep>
void seed_object(const Scene& scene, std::size_t oi, const Vec3& lo, const Vec3& hi, Particles& p,
                 Keep&& keep) {
  const SceneObject& o = scene.objects[oi];
  const ElasticPlastic& model = scene.materials[o.material].material.model;
  // A 2D grid's cell is 1 m along z: per metre of thickness (plane strain), or the ring the
  // sub-cell sweeps about the axis, 2 pi r times its area (axisymmetric; scene/grid_geometry.hpp).
  const auto particle_volume = visit_geometry(
      scene.grid.geometry, [](auto geometry) { return &decltype(geometry)::particle_volume; });
  const PointState s0 = model.initial_state(o.temperature);
  const double c = model.wave_speed(s0);
  InitialVelocity velocity(scene, oi);  // numbers, or expressions at the seed point
  for_each_seed_point(scene, oi, lo, hi, [&](const Vec3& x, int) {
    if (!keep(x)) return;
    const double v0 = particle_volume(x, seeded_cell_share(scene, oi, x));
    p.x.push_back(x);
    p.v.push_back(velocity.at(x));
    p.mass.push_back(model.params().density * v0);
    p.volume0.push_back(v0);
    p.volume.push_back(v0);
    p.L.push_back(Mat3::Zero());
    p.state.push_back(s0);
    p.wave_speed.push_back(c);
    p.material.push_back(static_cast<std::uint16_t>(o.material));
    p.object.push_back(static_cast<std::uint16_t>(oi));
    p.field.push_back(static_cast<std::uint16_t>(scene.parent_field(o.material)));
    if (scene.grid.graded()) p.half_width.push_back(seeded_half_width(scene, oi, x));
  });
}

void seed_object(const Scene& scene, std::size_t oi, const Vec3& lo, const Vec3& hi, Particles& p) {
  seed_object(scene, oi, lo, hi, p, [](const Vec3&) { return true; });
}

// Object oi's bounding box cut to the cell columns [first, end) along x, each bound half a cell
// inside so that rounding cannot add a column; empty (lo(0) > hi(0)) when they do not meet.
std::pair<Vec3, Vec3> columns_of(const Scene& scene, std::size_t oi, int first, int end) {
  const GridSpec& g = scene.grid;
  auto [lo, hi] = bounds(scene.objects[oi].geometry);
  if (g.graded()) {  // the middles of cells first and end - 1
    lo(0) = std::max(lo(0), g.node(0, first) + 0.5 * g.cell_size(0, first));
    hi(0) = std::min(hi(0), g.node(0, end - 1) + 0.5 * g.cell_size(0, end - 1));
    return {lo, hi};
  }
  const double h = g.spacing()(0);
  lo(0) = std::max(lo(0), g.lower(0) + (first + 0.5) * h);
  hi(0) = std::min(hi(0), g.lower(0) + (end - 0.5) * h);
  return {lo, hi};
}

}  // namespace

Particles seed_particles(const Scene& scene) {
  Particles p;
  // Count first and reserve exactly: push_back growth would leave up to twice the storage in
  // place for the whole run (and the memory estimate of mpm check assumes exact sizes).
  std::size_t count = 0;
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const auto [lo, hi] = bounds(scene.objects[oi].geometry);
    for_each_seed_point(scene, oi, lo, hi, [&](const Vec3&, int) { ++count; });
  }
  p.reserve(count);
  if (scene.grid.graded()) p.half_width.reserve(count);
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const auto [lo, hi] = bounds(scene.objects[oi].geometry);
    seed_object(scene, oi, lo, hi, p);
  }
  return p;
}

SeedCounts seed_counts_per_column(const Scene& scene) {
  return seed_counts_per_column(scene, nullptr);
}

SeedCounts seed_counts_per_column(const Scene& scene, SeedAxisCounts* per_axis) {
  return seed_counts_per_column(scene, per_axis, 0, scene.grid.cells[0]);
}

SeedCounts seed_counts_per_column(const Scene& scene, SeedAxisCounts* per_axis, int first, int end,
                                  const std::function<void(const std::array<int, 3>&)>& each) {
  const GridSpec& g = scene.grid;
  std::vector<std::vector<std::size_t>> counts(scene.objects.size(),
                                               std::vector<std::size_t>(g.cells[0], 0));
  if (per_axis)
    for (int d = 0; d < 3; ++d) (*per_axis)[std::size_t(d)].assign(std::size_t(g.cells[d]), 0);
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const auto [lo, hi] = columns_of(scene, oi, first, end);
    if (lo(0) > hi(0)) continue;
    for_each_seed_point(scene, oi, lo, hi, [&](const Vec3& x, int i) {
      ++counts[oi][i];
      if (each) each(g.cell_of(x));
      if (!per_axis) return;
      ++(*per_axis)[0][std::size_t(i)];
      for (int d = 1; d < 3; ++d) ++(*per_axis)[std::size_t(d)][std::size_t(g.cell_along(d, x(d)))];
    });
  }
  return counts;
}

Particles seed_columns(const Scene& scene, int first, int end, const SeedCounts& counts) {
  const GridSpec& g = scene.grid;
  return seed_box(scene, {first, 0, 0}, {end, g.cells[1], g.cells[2]}, counts);
}

// A box seeds its own points only: it walks every seed point of its x range's cell columns, to
// give each its seed index (the columns' points are numbered j, then k, within a column), but
// stores those inside its y and z ranges alone. Storing the whole x range and trimming it after
// held p_y p_z times the box's share at once (0.3-0.5 GB more per rank on the 6x grid split
// 2 x 2 x 1, docs/mpi.md).
Particles seed_box(const Scene& scene, const std::array<int, 3>& first,
                   const std::array<int, 3>& end, const SeedCounts& counts) {
  const GridSpec& g = scene.grid;
  const auto in_box = [&](const Vec3& x) {
    for (int d = 1; d < 3; ++d) {
      const int c = g.cell_along(d, x(d));
      if (c < first[std::size_t(d)] || c >= end[std::size_t(d)]) return false;
    }
    return true;
  };
  const bool whole_columns =
      first[1] <= 0 && first[2] <= 0 && end[1] >= g.cells[1] && end[2] >= g.cells[2];
  // Reserve exactly (as seed_particles()): the columns' counts give it for whole columns; a box
  // counts its points in a pass that stores nothing.
  std::size_t n = 0;
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    if (whole_columns) {
      for (int i = first[0]; i < end[0]; ++i) n += counts[oi][std::size_t(i)];
      continue;
    }
    const auto [lo, hi] = columns_of(scene, oi, first[0], end[0]);
    if (lo(0) <= hi(0))
      for_each_seed_point(scene, oi, lo, hi, [&](const Vec3& x, int) { n += in_box(x) ? 1 : 0; });
  }
  Particles p;
  p.reserve(n);
  if (scene.grid.graded()) p.half_width.reserve(n);
  p.id.reserve(n);
  std::size_t object_start = 0;  // the seed index of the object's first point
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    std::size_t index = object_start;  // the seed index of the next point walked
    for (int i = 0; i < first[0]; ++i) index += counts[oi][std::size_t(i)];
    const auto [lo, hi] = columns_of(scene, oi, first[0], end[0]);
    if (lo(0) <= hi(0))
      seed_object(scene, oi, lo, hi, p, [&](const Vec3& x) {
        const std::size_t id = index++;
        if (!in_box(x)) return false;
        p.id.push_back(id);
        return true;
      });
    for (const std::size_t column : counts[oi]) object_start += column;
  }
  return p;
}

}  // namespace impact::mpm
