// How a scene would split over N ranks, without running it (`mpm check --ranks N`, docs/mpi.md):
// the boxes the run would make from the seed points, each box's particle count, and the halo
// traffic per step of the cost model (halo_traffic), so that a cluster run can be sized on a
// laptop and its balance judged before it is queued.
#pragma once

#include <array>
#include <functional>

#include "models/core/input.hpp"
#include "mpm/parallel/box_decomposition.hpp"
#include "mpm/parallel/split_search.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// The boxes per axis a run of `scene` on `ranks` ranks uses: solver.ranks_per_axis when given,
/// else the split cutting the fewest node faces, or with "least_loaded" the least loaded split,
/// whose box loads `count` fills (SplitLoads::add per particle; a run sums its ranks' shares);
/// `counts`: the particles per cell along each axis. Throws std::invalid_argument when nothing
/// fits (the message names the key or the grid).
std::array<int, 3> ranks_per_axis_of(const Scene& scene, int ranks, const AxisCounts& counts,
                                     const std::function<void(SplitLoads&)>& count);

/// The decomposition of `scene`'s seeded particles P on `ranks` ranks: ranks per axis, the boxes'
/// first cells, particles per rank (min, mean, max, their imbalance max / mean, empty ranks),
/// stored grid nodes per rank (max) and halo bytes and messages per step (min, mean, max); and of
/// every admissible split the one whose busiest box holds the fewest particles
/// ("least_loaded_split": what solver.ranks_per_axis "least_loaded" picks).
Json plan_decomposition(const Scene& scene, const Particles& P, int ranks);

}  // namespace impact::mpm
