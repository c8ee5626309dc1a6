// The node sums a slab shares with its neighbours (docs/mpi.md). Rank r's particles lie in its
// cells [c0, c1) and reach the node planes [c0 - 1, c1 + 1] (uGIMP; linear less), so two
// neighbours both scatter into the three planes [b - 1, b + 1] around their common boundary b.
// After a scatter each sends its partial sums there and adds the other's: every shared node then
// holds the whole sum, the same bits on both ranks (a + b = b + a), and the grid update, contact
// and faces run on both as on one rank. Contact's mass gradient at plane b + 1 also reads plane
// b + 2, which only the upper rank's particles fill: with contact the ranks also copy that plane
// (and b - 2 the other way). Each node's ledger terms are booked by one rank, the owner of its
// plane (Grid::owns).
#pragma once

#include "mpm/grid/grid.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/parallel/slab_decomposition.hpp"

namespace impact::mpm {

/// Node planes beyond its slab's cells [c0, c1) that a rank's grid stores on each side: its
/// particles' uGIMP stencils reach c0 - 1 and c1 + 1, contact copies the plane c0 - 2 (c1 + 2)
/// from the neighbour, and the mass gradient there reads one plane further (Grid's NodePlanes).
constexpr int kHaloPlanes = 3;

class HaloExchange {
 public:
  HaloExchange(const Communicator& comm, const SlabDecomposition& slabs)
      : comm_(comm), slabs_(slabs) {}

  const Communicator& comm() const { return comm_; }
  const SlabDecomposition& slabs() const { return slabs_; }

  /// After particles to grid, before Grid::activate: sums the shared planes' node data (and nodal
  /// stress), marks the blocks of nodes that received mass, and with `contact` copies the planes
  /// beyond.
  void sum_node_data(Grid& G, bool contact) const;
  /// After the MUSL re-map's scatter: sums the shared planes' momentum.
  void sum_momentum(Grid& G) const;

 private:
  const Communicator& comm_;
  const SlabDecomposition& slabs_;
};

}  // namespace impact::mpm
