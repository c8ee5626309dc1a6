#include "mpm/run/memory.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/grid_geometry.hpp"
#include "mpm/shape/shape.hpp"
#include "support/system_resources.hpp"

namespace impact::mpm {

namespace {

constexpr double kProgramBytes = 16e6;
constexpr double kMB = 1e6;

// The cells of graded axis d across [lo, hi], fractions of the end cells counted.
double cells_across(const GridSpec& g, int d, double lo, double hi) {
  if (!(hi > lo)) return 0.0;
  const int first = g.cell_along(d, lo), last = g.cell_along(d, hi);
  double n = 0.0;
  for (int i = first; i <= last; ++i) {
    const double a = std::max(lo, g.node(d, i)), b = std::min(hi, g.node(d, i + 1));
    n += std::max(0.0, b - a) / g.cell_size(d, i);
  }
  return n;
}

}  // namespace

double estimated_particle_count(const Scene& scene) {
  const GridSpec& g = scene.grid;
  double n = 0.0;
  for (const SceneObject& o : scene.objects) {
    const auto [lo, hi] = bounds(o.geometry);
    const Vec3 extent = (hi.cwiseMin(g.upper) - lo.cwiseMax(g.lower)).cwiseMax(0.0);
    // On a graded grid, the mean cell over the body's bounding box: the cells it spans per axis.
    Vec3 h = g.spacing();
    if (g.graded())
      for (int d = 0; d < 3; ++d) {
        const double cells =
            cells_across(g, d, std::max(lo(d), g.lower(d)), std::min(hi(d), g.upper(d)));
        if (cells > 0.0) h(d) = extent(d) / cells;
      }
    const auto& ppc = o.particles_per_cell;
    n += visit_geometry(g.geometry, [&](auto geometry) {
      return decltype(geometry)::estimated_seed_points(o.geometry, extent, h, ppc);
    });
  }
  return n;
}

double estimated_grid_bytes(const Scene& scene) {
  const GridSpec g = scene.grid.at_the_nodes();  // walls at the particles are free faces there
  // A 2D grid stores one node plane along z (grid/grid.hpp).
  const double nx = g.cells[0] + 3.0, ny = g.cells[1] + 3.0,
               nz = g.planar() ? 1.0 : g.cells[2] + 3.0;
  const double nodes = nx * ny * nz;
  const double fields = scene.field_count();
  const bool contact_heat = scene.contact_friction();
  const bool musl = scene.solver.scheme == Scheme::musl;
  double per_entry = 64.0 + 8.0 + 4.0 * 24.0;                   // NodeData, mass, 4 velocities
  if (musl) per_entry += 24.0;                                  // re-map momentum
  if (contact_heat || g.has_wall_friction()) per_entry += 8.0;  // friction heat
  if (g.has_walls()) per_entry += 1.0;                          // wall touch bits
  if (fields > 1) per_entry += 1.0;  // what contact's step held (Grid::contact_held)
  double bytes = fields * nodes * per_entry;
  bytes += nodes * 4.0;  // active-node list (dense: every node; blocks: reserved for all)
  if (g.active_blocks) {
    const double k = Grid::kBlock;
    bytes += std::ceil(nx / k) * std::ceil(ny / k) * std::ceil(nz / k);  // block marks
  }
  // Boundary nodes (constrained faces: face and ghost layers), their free increments, the active
  // subset's positions and the mirror's writes (all and active: Grid::apply_mirror).
  // A wall's face layer is a list of its own (all and active), its ghost layer none
  // (grid/wall.cpp).
  double boundary = 0.0, mirrored = 0.0, walled = 0.0;
  const double n[3] = {nx, ny, nz};
  for (int face = 0; face < 6; ++face) {
    if (g.faces[face] == FaceCondition::free) continue;
    const int axis = face / 2;
    const double layer = n[(axis + 1) % 3] * n[(axis + 2) % 3];
    boundary += 2.0 * layer;
    (g.faces[face] == FaceCondition::wall ? walled : mirrored) += layer;
  }
  bytes += boundary * (4.0 + 4.0 + fields * 24.0) + 2.0 * mirrored * 2.0 * sizeof(MirrorWrite) +
           walled * 2.0 * sizeof(WallNode);
  return bytes;
}

MemoryEstimate estimate_memory(const Scene& scene, std::optional<std::size_t> particles) {
  MemoryEstimate e;
  e.exact_count = particles.has_value();
  e.particles = particles ? double(*particles) : estimated_particle_count(scene);
  double per_particle = double(Particles::bytes_per_particle());
  if (scene.physics.artificial_viscosity.enabled) per_particle += sizeof(double);
  if (scene.physics.on_numerical_fault == NumericalFaultAction::fail_particle) per_particle += 1;
  if (scene.grid.outflow == Outflow::remove) per_particle += 1;
  if (scene.needs_reference_positions()) per_particle += sizeof(Vec3);             // X_p
  if (scene.grid.graded()) per_particle += sizeof(Vec3);                           // half_width_p
  if (scene.solver.shuffle_particles != 0) per_particle += sizeof(std::uint64_t);  // id_p
  if (scene.has_body_force()) per_particle += sizeof(Vec3);  // b_p (step/body_force.hpp)
  // f_p, the rigid objects' and walls' contact force (contact/rigid_particle_contact.hpp)
  if (scene.contact_at_particles()) per_particle += sizeof(Vec3);
  // a_p, its friction's stick-spring anchor
  if (scene.friction_at_particles()) per_particle += sizeof(Vec3);
  // the dashpots' forces, where they act from and the velocities they damp
  // (contact.penalty_damping, grid.wall_penalty_damping)
  if (scene.damping_at_particles()) per_particle += 3 * sizeof(Vec3);
  per_particle += stencil_bytes(scene.solver.interpolation);
  per_particle += 2 * sizeof(int);  // scatter order: index and tile (mpm/step/scatter_order.hpp)
  e.particle_bytes = e.particles * per_particle;
  e.grid_bytes = estimated_grid_bytes(scene);
  if (scene.output.snapshots) {
    // Every array is kept (with an 8-byte size) until the file is written; the largest is
    // allocated once more while it is copied in.
    double per = 24.0 + 8.0 + 8.0 + 1.0, largest = 24.0;
    for (const std::string& f : scene.output.fields) {
      const double b = f == "velocity" ? 24.0 : f == "stress" ? 48.0 : 8.0;
      per += b;
      largest = std::max(largest, b);
    }
    e.output_bytes = e.particles * (per + largest);
  }
  e.program_bytes = kProgramBytes;
  return e;
}

Json MemoryEstimate::json() const {
  return {{"total [MB]", total() / kMB},
          {"particles [MB]", particle_bytes / kMB},
          {"grid [MB]", grid_bytes / kMB},
          {"output [MB]", output_bytes / kMB},
          {"program [MB]", program_bytes / kMB},
          {"particles", particles},
          {"particle_count", exact_count ? "seeded" : "estimated from the geometry"}};
}

std::optional<double> available_memory() {
  return impact::available_memory();
}

std::optional<double> peak_resident_memory() {
  return impact::peak_resident_memory();
}

std::string memory_refusal(const Scene& scene) {
  const MemoryEstimate e = estimate_memory(scene);
  const std::optional<double> available = available_memory();
  if (!available || e.total() <= *available) return {};
  std::ostringstream m;
  m.precision(4);
  m << "refusing to start: estimated memory " << e.total() / 1e6 << " MB (particles "
    << e.particle_bytes / 1e6 << " MB for " << e.particles
    << " particles estimated from the geometry, grid " << e.grid_bytes / 1e6 << " MB for "
    << scene.grid.cells[0] << " x " << scene.grid.cells[1] << " x " << scene.grid.cells[2]
    << " cells and " << scene.field_count() << " velocity field(s), output " << e.output_bytes / 1e6
    << " MB, program " << e.program_bytes / 1e6 << " MB) exceeds the available memory "
    << *available / 1e6
    << " MB (MemAvailable in /proc/meminfo, or less under the cgroup's memory.max or ulimit -v); "
       "coarsen grid.cells"
    << scene.grid.refinement_advice() << " or objects.*.particles_per_cell";
  return m.str();
}

}  // namespace impact::mpm
