// Memory estimate of a run (mpm check prints it; mpm run refuses to start when it exceeds the
// available memory; docs/mpm.md#memory-and-step-estimates), from the scene alone: nothing is
// seeded or allocated, so an absurd scene is refused in microseconds.
//   particles: count x (Particles::bytes_per_particle + q with artificial viscosity + fault
//              flag with fail_particle + the cached stencil: 112 B linear, 160 B GIMP + 8 B of
//              scatter order)
//   grid:      entries = fields x (cells_x + 3)(cells_y + 3)(cells_z + 3) times
//              (64 B node data + 24 B MUSL re-map + 48 B nodal stress with friction)
//              + 8 B mass + 4 x 24 B velocities + 8 B friction heat, plus 4 B per node for the
//              active-node list, the block marks and the boundary-node lists. One copy whatever
//              the thread count (mpm/step/scatter_order.hpp).
//   output:    one VTU snapshot held in memory while it is written (positions, connectivity,
//              offsets, types and the output.fields arrays) plus its largest array once more
//   program:   a fixed 16 MB (code, libraries, OpenMP threads; measured ~10 MB)
// The particle count is the exact seeded count when given, else the geometric estimate
// sum_objects min(volume, volume of its bounding box inside the grid) x ppc^3 / cell volume
// (an upper bound up to the shapes' overlap); on a 2D grid, with the area of the section it seeds
// (scene/grid_geometry.hpp estimated_seed_points) and of the bounding rectangle, ppc^2 and the
// cell's area.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

struct MemoryEstimate {
  double particles = 0.0;  ///< count (exact or geometric)
  bool exact_count = false;
  double particle_bytes = 0.0, grid_bytes = 0.0, output_bytes = 0.0, program_bytes = 0.0;
  double total() const { return particle_bytes + grid_bytes + output_bytes + program_bytes; }
  /// {"total [MB]", "particles [MB]", "grid [MB]", "output [MB]", "program [MB]", "particles"}.
  Json json() const;
};

/// `particles`: the exact count if known (seeded), else the geometric estimate is used. The
/// estimate does not depend on the thread count.
MemoryEstimate estimate_memory(const Scene& scene,
                               std::optional<std::size_t> particles = std::nullopt);
/// The geometric particle count estimate (above).
double estimated_particle_count(const Scene& scene);
/// Bytes of the grid as Grid allocates them (the grid term above).
double estimated_grid_bytes(const Scene& scene);

/// What this process may still allocate [bytes]: MemAvailable of /proc/meminfo, or less when a
/// cgroup (v2) memory.max, ulimit -v or ulimit -d leaves less; nullopt when none can be read.
std::optional<double> available_memory();
/// Peak resident set size of this process so far (VmHWM of /proc/self/status) [bytes].
std::optional<double> peak_resident_memory();

/// Why `mpm run` must not start this scene (the memory estimate, which does not depend on the
/// thread count, exceeds the available memory: both in the message), or empty. Allocates nothing.
std::string memory_refusal(const Scene& scene);

}  // namespace impact::mpm
