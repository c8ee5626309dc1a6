#include "mpm/parallel/halo_exchange.hpp"

#include <cstring>

namespace impact::mpm {

namespace {

constexpr int kSumTag = 1, kBeyondTag = 2, kMomentumTag = 3;

// Every entry (all fields) of the node planes [first, last] along x, in storage order.
template <class Visit>
void for_planes(const Grid& G, int first, int last, Visit&& visit) {
  const int nn = G.node_count();
  const auto& c = G.cells();
  for (int f = 0; f < G.fields(); ++f)
    for (int i = first; i <= last; ++i)
      for (int j = -1; j <= c[1] + 1; ++j)
        for (int k = -1; k <= c[2] + 1; ++k) visit(f * nn + G.index(i, j, k), std::array{i, j, k});
}

template <class T>
std::vector<char> pack(const Grid& G, const T* data, int first, int last) {
  std::vector<char> out;
  for_planes(G, first, last, [&](int e, const std::array<int, 3>&) {
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
  for (int d = 0; d < 3; ++d) {
    a.momentum[d] += b.momentum[d];
    a.force[d] += b.force[d];
  }
}
void add(NodeStress& a, const NodeStress& b) {
  for (int c = 0; c < 6; ++c) a.s[c] += b.s[c];
}
void add(Vec3& a, const Vec3& b) {
  a += b;
}

// Sends this rank's partial sums at the planes [b - 1, b + 1] of each boundary b it shares and
// adds the neighbour's; `mark`: marks the blocks of the nodes whose received mass is nonzero.
template <class T>
void sum_shared(Grid& G, T* data, const Communicator& comm, const SlabDecomposition& slabs, int tag,
                bool mark) {
  const int r = comm.rank();
  char* const marks = mark && !G.dense() ? G.block_marks() : nullptr;
  for (const int neighbour : {r - 1, r + 1}) {
    if (neighbour < 0 || neighbour >= comm.size()) continue;
    const int b = slabs.first_cell(neighbour < r ? r : neighbour);
    const std::vector<char> in = comm.exchange(neighbour, pack(G, data, b - 1, b + 1), tag);
    std::size_t k = 0;
    for_planes(G, b - 1, b + 1, [&](int e, const std::array<int, 3>& ijk) {
      const T remote = record<T>(in, k++);
      add(data[e], remote);
      if constexpr (std::is_same_v<T, NodeData>) {
        if (marks && remote.mass != 0.0) G.mark_stencil(marks, ijk, 1);
      }
    });
  }
}

}  // namespace

void HaloExchange::sum_node_data(Grid& G, bool contact) const {
  if (comm_.size() == 1) return;
  sum_shared(G, G.node_buffer(), comm_, slabs_, kSumTag, /*mark=*/true);
  if (G.has_nodal_stress()) sum_shared(G, G.stress_buffer(), comm_, slabs_, kSumTag, false);
  if (!contact) return;
  // The plane beyond the shared ones, whole on the neighbour: b + 2 from above, b - 2 from below.
  const int r = comm_.rank();
  char* const marks = G.dense() ? nullptr : G.block_marks();
  for (const int neighbour : {r - 1, r + 1}) {
    if (neighbour < 0 || neighbour >= comm_.size()) continue;
    const bool above = neighbour > r;
    const int b = slabs_.first_cell(above ? neighbour : r);
    const int mine = above ? b - 2 : b + 2, theirs = above ? b + 2 : b - 2;
    const std::vector<char> in =
        comm_.exchange(neighbour, pack(G, G.node_buffer(), mine, mine), kBeyondTag);
    std::size_t k = 0;
    NodeData* const data = G.node_buffer();
    for_planes(G, theirs, theirs, [&](int e, const std::array<int, 3>& ijk) {
      data[e] = record<NodeData>(in, k++);
      if (marks && data[e].mass != 0.0) G.mark_stencil(marks, ijk, 1);
    });
  }
}

void HaloExchange::sum_momentum(Grid& G) const {
  if (comm_.size() == 1) return;
  sum_shared(G, G.momentum_buffer(), comm_, slabs_, kMomentumTag, false);
}

}  // namespace impact::mpm
