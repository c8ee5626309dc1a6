#include "mpm/parallel/halo_exchange.hpp"

#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

namespace impact::mpm {

namespace {

constexpr int kSumTag = 1, kBeyondTag = 2, kMomentumTag = 3;

// Every entry (all fields) of the stored nodes whose index along `axis` lies in [first, last],
// the other two axes over the whole stored box, in storage order. Two neighbours along `axis`
// store the same range on the other axes (the boxes are rectilinear), so their lists match.
template <class Visit>
void for_layers(const Grid& G, int axis, int first, int last, Visit&& visit) {
  const int nn = G.node_count();
  NodeBox box = G.stored();
  box.first[std::size_t(axis)] = first;
  box.last[std::size_t(axis)] = last;
  for (int f = 0; f < G.fields(); ++f)
    for (int i = box.first[0]; i <= box.last[0]; ++i)
      for (int j = box.first[1]; j <= box.last[1]; ++j)
        for (int k = box.first[2]; k <= box.last[2]; ++k)
          visit(f * nn + G.index(i, j, k), std::array{i, j, k});
}

template <class T>
std::vector<char> pack(const Grid& G, const T* data, int axis, int first, int last) {
  std::vector<char> out;
  for_layers(G, axis, first, last, [&](int e, const std::array<int, 3>&) {
    const char* bytes = reinterpret_cast<const char*>(data + e);
    out.insert(out.end(), bytes, bytes + sizeof(T));
  });
  return out;
}

template <class T>
T record(const std::vector<char>& in, std::size_t k) {
  T value;
  std::memcpy(static_cast<void*>(&value), in.data() + k * sizeof(T), sizeof(T));
  return value;
}

void add(NodeData& a, const NodeData& b) {
  a.mass += b.mass;
  a.mass_moment += b.mass_moment;
  for (int d = 0; d < 3; ++d) {
    a.momentum[d] += b.momentum[d];
    a.force[d] += b.force[d];
  }
}
void add(Vec3& a, const Vec3& b) {
  a += b;
}
void add(std::uint8_t& a, const std::uint8_t& b) {  // wall touch bits: a particle of either rank
  a |= b;
}

// A neighbour of a box along one axis: its rank, b the boundary cell between the two boxes, and
// whether it is the upper one.
struct Neighbour {
  int rank = 0;
  int b = 0;
  bool above = false;
};

// This rank's neighbours along `axis`, the lower first (none, one or two).
std::vector<Neighbour> neighbours_along(const BoxDecomposition& boxes, int rank, int axis) {
  const std::array<int, 3> c = boxes.coordinates(rank);
  const int p = boxes.axis(axis).ranks();
  std::vector<Neighbour> out;
  for (const int step : {-1, 1}) {
    std::array<int, 3> n = c;
    n[std::size_t(axis)] += step;
    if (n[std::size_t(axis)] < 0 || n[std::size_t(axis)] >= p) continue;
    const bool above = step > 0;
    const int b = boxes.axis(axis).first_cell(above ? n[std::size_t(axis)] : c[std::size_t(axis)]);
    out.push_back({boxes.rank_at(n), b, above});
  }
  return out;
}

// Packs `layers(n)` for each neighbour n along `axis`, sends them to both neighbours at once and
// returns what each sent back, in the same order (Communicator::exchange: no chain across the
// ranks of the axis).
template <class T, class Layers>
std::vector<std::vector<char>> exchange_layers(const Grid& G, const T* data,
                                               const Communicator& comm,
                                               const std::vector<Neighbour>& neighbours, int axis,
                                               int tag, Layers&& layers) {
  std::vector<int> ranks;
  std::vector<std::vector<char>> out;
  for (const Neighbour& n : neighbours) {
    const auto [first, last] = layers(n);
    ranks.push_back(n.rank);
    out.push_back(pack(G, data, axis, first, last));
  }
  return comm.exchange(ranks, out, tag);
}

// Along each axis in turn: sends this rank's partial sums at the layers [b - 1, b + 1] of each
// boundary b it shares and adds the neighbour's; `mark`: marks the blocks of the nodes whose
// received mass is nonzero. Both neighbours' layers are packed before either's part is added;
// a box at least SlabDecomposition::kMinCells = 3 cells wide keeps the two sets of layers apart,
// so each shared node adds one partial sum to its own, as when the ranks exchanged with their
// lower neighbour first and then with the upper one: the same bits.
template <class T>
void sum_shared(Grid& G, T* data, const Communicator& comm, const BoxDecomposition& boxes, int tag,
                bool mark) {
  char* const marks = mark && !G.dense() ? G.block_marks() : nullptr;
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<Neighbour> neighbours = neighbours_along(boxes, comm.rank(), axis);
    if (neighbours.empty()) continue;
    const std::vector<std::vector<char>> in =
        exchange_layers(G, data, comm, neighbours, axis, tag, [](const Neighbour& n) {
          return std::pair{n.b - 1, n.b + 1};
        });
    for (std::size_t i = 0; i < neighbours.size(); ++i) {
      const int b = neighbours[i].b;
      std::size_t k = 0;
      for_layers(G, axis, b - 1, b + 1, [&](int e, const std::array<int, 3>& ijk) {
        const T remote = record<T>(in[i], k++);
        add(data[e], remote);
        if constexpr (std::is_same_v<T, NodeData>) {
          if (marks && remote.mass != 0.0) G.mark_stencil(marks, ijk, 1, 1);
        }
      });
    }
  }
}

}  // namespace

NodeBox stored_nodes(const BoxDecomposition& boxes, const GridSpec& grid, int rank) {
  NodeBox box{boxes.first_cell(rank), boxes.end_cell(rank)};
  for (std::size_t d = 0; d < 3; ++d) {
    box.first[d] = std::max(box.first[d] - kHaloPlanes, -1);
    box.last[d] = std::min(box.last[d] + kHaloPlanes, grid.cells[d] + 1);
  }
  if (grid.planar()) box.first[2] = box.last[2] = 0;
  return box;
}

HaloTraffic halo_traffic(const BoxDecomposition& boxes, const GridSpec& grid, int rank, int fields,
                         bool walls, bool musl) {
  const NodeBox box = stored_nodes(boxes, grid, rank);
  const double per_node =
      double(sizeof(NodeData)) + (walls ? sizeof(std::uint8_t) : 0.0) + (musl ? sizeof(Vec3) : 0.0);
  const int exchanges_per_neighbour = 1 + (walls ? 1 : 0) + (musl ? 1 : 0);
  HaloTraffic t;
  for (int axis = 0; axis < 3; ++axis) {
    const int e = (axis + 1) % 3, f = (axis + 2) % 3;
    const double layer = double(box.last[std::size_t(e)] - box.first[std::size_t(e)] + 1) *
                         double(box.last[std::size_t(f)] - box.first[std::size_t(f)] + 1) * fields;
    for (std::size_t n = neighbours_along(boxes, rank, axis).size(); n > 0; --n) {
      t.bytes += 3.0 * layer * per_node;
      t.messages += exchanges_per_neighbour;
      if (fields > 1) {  // contact: the layer beyond
        t.bytes += layer * double(sizeof(NodeData));
        t.messages += 1.0;
      }
    }
  }
  return t;
}

void HaloExchange::sum_node_data(Grid& G, bool contact) const {
  if (comm_.size() == 1) return;
  sum_shared(G, G.node_buffer(), comm_, boxes_, kSumTag, /*mark=*/true);
  if (!G.wall_touch.empty()) sum_shared(G, G.wall_touch.data(), comm_, boxes_, kSumTag, false);
  if (!contact) return;
  // The layer beyond the shared ones, whole on the neighbour: b + 2 from above, b - 2 from below.
  char* const marks = G.dense() ? nullptr : G.block_marks();
  NodeData* const data = G.node_buffer();
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<Neighbour> neighbours = neighbours_along(boxes_, comm_.rank(), axis);
    if (neighbours.empty()) continue;
    // The layers sent (c0 + 2, c1 - 2) lie inside a box at least 3 cells wide and those received
    // (c0 - 2, c1 + 2) outside it: packing both before writing either copies what the chain did.
    const std::vector<std::vector<char>> in =
        exchange_layers(G, data, comm_, neighbours, axis, kBeyondTag, [](const Neighbour& n) {
          const int mine = n.above ? n.b - 2 : n.b + 2;
          return std::pair{mine, mine};
        });
    for (std::size_t i = 0; i < neighbours.size(); ++i) {
      const int theirs = neighbours[i].above ? neighbours[i].b + 2 : neighbours[i].b - 2;
      std::size_t k = 0;
      for_layers(G, axis, theirs, theirs, [&](int e, const std::array<int, 3>& ijk) {
        data[e] = record<NodeData>(in[i], k++);
        if (marks && data[e].mass != 0.0) G.mark_stencil(marks, ijk, 1, 1);
      });
    }
  }
}

void HaloExchange::sum_momentum(Grid& G) const {
  if (comm_.size() == 1) return;
  sum_shared(G, G.momentum_buffer(), comm_, boxes_, kMomentumTag, false);
}

}  // namespace impact::mpm
