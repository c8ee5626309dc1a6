// The least loaded boxes (docs/mpi.md, solver.ranks_per_axis "least_loaded"). Boxes balanced by
// their axes' projections (BoxDecomposition::balanced) leave the boxes inside a hollow target
// nearly empty and overload the others: on the 6x sphere-cylinder grid the busiest box holds
// 1.47 / 3.39 / 11.0 times the mean on 64 / 512 / 4 096 ranks with the split cutting the fewest
// node faces. Here the boxes stay rectilinear (the halo sums stay axis by axis), but each axis's
// boundaries are then moved to minimise the busiest box with the other two axes held, axis after
// axis (a rectilinear partition refined by exact one-axis min-max steps; Nicol 1994, "Rectilinear
// partitioning of irregular data parallel computations", J. Parallel Distrib. Comput. 23), and of
// every split of the ranks into ranks per axis the least loaded is taken: 1.05 / 1.47 / 2.92
// there. Everything is counted from integers summed over the ranks, so every rank makes the same
// boxes.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "mpm/parallel/box_decomposition.hpp"

namespace impact::mpm {

/// Particles in one occupied cell (i, j, k).
struct CellCount {
  std::array<int, 3> cell;
  double count;
};
/// Adds one particle in `cell` to `counted` (one entry per run of equal cells: seed points come
/// cell by cell).
inline void count_cell(std::vector<CellCount>& counted, const std::array<int, 3>& cell) {
  if (!counted.empty() && counted.back().cell == cell)
    counted.back().count += 1.0;
  else
    counted.push_back({cell, 1.0});
}

/// Sums a table of counts over the ranks, element by element (Communicator::sum_counts; the
/// identity on one process).
using TableSum = std::function<std::vector<double>(const std::vector<double>&)>;

/// `boxes` with each axis's boundaries moved in turn, the other two axes' held, to the cuts that
/// minimise the busiest box (the exact one-axis min-max partition, boxes at least kMinCells wide
/// along a split axis), sweeping x, y, z until a sweep moves nothing. Never busier than `boxes`.
/// `counted`: this process's particles; *busiest: the particles of the busiest box.
BoxDecomposition refine_boundaries(const BoxDecomposition& boxes,
                                   const std::vector<CellCount>& counted, const TableSum& sum,
                                   double* busiest);

struct SplitChoice {
  BoxDecomposition boxes;
  double busiest;               ///< particles in its busiest box
  std::size_t splits_searched;  ///< the admissible splits weighed
};
/// Of every admissible split of `ranks` on a grid of `cells` (BoxDecomposition::splits), its boxes
/// balanced per axis by `counts` and refined (refine_boundaries), the one whose busiest box holds
/// the fewest particles; fewer cut node faces on a tie. Throws std::invalid_argument
/// (BoxDecomposition::ranks_per_axis's message) when no split fits.
SplitChoice least_loaded_split(const std::array<int, 3>& cells, const AxisCounts& counts, int ranks,
                               const std::vector<CellCount>& counted, const TableSum& sum);

}  // namespace impact::mpm
