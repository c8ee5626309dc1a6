// The node sums a box shares with its neighbours (docs/mpi.md). Rank r's particles lie in its
// cells [c0, c1) per axis and reach the nodes [c0 - 1, c1 + 1] (uGIMP; linear less), so two
// neighbours along an axis both scatter into the three node layers [b - 1, b + 1] around their
// common boundary b. After a scatter each sends its partial sums there and adds the other's, one
// axis after another (x, then y, then z), each layer over the whole stored box on the other two
// axes, to its lower and upper neighbour at once (no chain along the axis's ranks): a node near an
// edge or a corner of the box first gathers its x neighbour's part, then the y neighbours' (each
// already holding its own x neighbour's, the diagonal rank's), then the z neighbours'. Every shared
// node then holds the whole sum, the same bits on every rank that stores it (each addition is a + b
// = b + a on both sides), and the grid update, contact and faces run on every rank as on one.
// Contact's mass gradient at layer b + 1 also reads layer b + 2, which only the upper rank's
// particles fill: with contact the ranks also copy that layer (and b - 2 the other way), again one
// axis after another so that the corners arrive too. Each node's ledger terms are booked by one
// rank, the owner of its box (Grid::owns).
#pragma once

#include "mpm/grid/grid.hpp"
#include "mpm/parallel/box_decomposition.hpp"
#include "mpm/parallel/communicator.hpp"

namespace impact::mpm {

/// Node layers beyond its box's cells [c0, c1) that a rank's grid stores on each side, per axis:
/// its particles' uGIMP stencils reach c0 - 1 and c1 + 1, contact copies the layer c0 - 2
/// (c1 + 2) from the neighbour, and the mass gradient there reads one layer further.
constexpr int kHaloPlanes = 3;

/// The nodes rank `rank`'s grid stores: its box's cells [c0, c1) per axis widened by kHaloPlanes
/// on each side, clipped to the grid and its ghost layers [-1, cells + 1]; along z of a 2D grid
/// the one node plane k = 0 (Grid stores no other: scene/grid_geometry.hpp).
NodeBox stored_nodes(const BoxDecomposition& boxes, const GridSpec& grid, int rank);

/// What a rank sends by the node sums per step (docs/mpi.md, "Cost model"): per neighbour along
/// axis d, 3 node layers times its stored extents on the other two axes times the velocity fields,
/// each node 64 B (mass, momentum, force), 1 B more with `wall` faces (the walls a particle
/// touches: Grid::wall_touch) and 24 B more with the MUSL re-map's momentum; with several fields
/// (contact) also the layer beyond, 64 B per node. One message per neighbour and exchange (both
/// sides send the same length).
struct HaloTraffic {
  double bytes = 0.0;
  double messages = 0.0;
};
HaloTraffic halo_traffic(const BoxDecomposition& boxes, const GridSpec& grid, int rank, int fields,
                         bool walls, bool musl);

class HaloExchange {
 public:
  HaloExchange(const Communicator& comm, const BoxDecomposition& boxes)
      : comm_(comm), boxes_(boxes) {}

  const Communicator& comm() const { return comm_; }
  const BoxDecomposition& boxes() const { return boxes_; }

  /// After particles to grid, before Grid::activate: sums the shared layers' node data (and
  /// nodal stress), marks the blocks of nodes that received mass, and with `contact` copies the
  /// layers beyond.
  void sum_node_data(Grid& G, bool contact) const;
  /// After the MUSL re-map's scatter: sums the shared layers' momentum.
  void sum_momentum(Grid& G) const;

 private:
  const Communicator& comm_;
  const BoxDecomposition& boxes_;
};

}  // namespace impact::mpm
