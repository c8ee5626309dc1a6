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

/// The boxes a run of `scene` on `ranks` ranks starts from, each axis balanced by `counts` (the
/// particles per cell along it): solver.ranks_per_axis when given, else the split cutting the
/// fewest node faces; with "least_loaded" the least loaded split with refined boundaries
/// (least_loaded_split) from this process's particles per cell, `count_cells()`, summed over the
/// ranks by `sum`. Throws InputError when nothing fits, naming the scene file, the key
/// (/grid/cells for an automatic split, else /solver/ranks_per_axis), the axis and the ranks.
BoxDecomposition initial_boxes(const Scene& scene, int ranks, const AxisCounts& counts,
                               const std::function<std::vector<CellCount>()>& count_cells,
                               const TableSum& sum);

/// The decomposition of `scene`'s seeded particles P on `ranks` ranks: ranks per axis, the boxes'
/// first cells, particles per rank (min, mean, max, their imbalance max / mean, empty ranks),
/// stored grid nodes per rank (max) and halo bytes and messages per step (min, mean, max); and of
/// every admissible split the one whose busiest box holds the fewest particles
/// with its boundaries refined ("least_loaded_split": what solver.ranks_per_axis "least_loaded"
/// makes).
Json plan_decomposition(const Scene& scene, const Particles& P, int ranks);

}  // namespace impact::mpm
