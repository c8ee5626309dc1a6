#include "mpm/parallel/migration.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace impact::mpm {

namespace {

// Which of Particles' arrays are in use, agreed by every rank: a rank may hold no particle, and
// an optional array is in use for the whole scene or not at all.
std::vector<bool> arrays_in_use(const Particles& P, const Communicator& comm) {
  const std::size_t n = P.size();
  std::vector<double> use;
  P.for_each_array([&](const auto& a) { use.push_back(n > 0 && a.size() == n ? 1.0 : 0.0); });
  std::vector<bool> in_use;
  for (const double users : comm.sum(use)) in_use.push_back(users > 0.0);
  return in_use;
}

void pack(const Particles& P, std::size_t p, std::vector<char>& out) {
  const std::size_t n = P.size();
  P.for_each_array([&](auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    // Plain values: numbers, flags, and Eigen fixed-size matrices and PointState, which are arrays
    // of doubles and flags without pointers (mpm/run/checkpoint.cpp writes them as stored).
    static_assert(std::is_standard_layout_v<T>);
    if (a.size() != n) return;
    const char* bytes = reinterpret_cast<const char*>(&a[p]);
    out.insert(out.end(), bytes, bytes + sizeof(T));
  });
}

// Appends the particles of `in` (whole records); `in_use` says which arrays the records carry.
void unpack(Particles& P, const std::vector<char>& in, const std::vector<bool>& in_use) {
  std::size_t offset = 0;
  while (offset < in.size()) {
    std::size_t k = 0;
    P.for_each_array([&](auto& a) {
      using T = typename std::decay_t<decltype(a)>::value_type;
      if (!in_use[k++]) return;
      T value;
      std::memcpy(static_cast<void*>(&value), in.data() + offset, sizeof(T));
      offset += sizeof(T);
      a.push_back(value);
    });
  }
}

}  // namespace

AxisCounts axis_counts(const Particles& P, const GridSpec& grid, const Communicator& comm) {
  std::vector<double> local(std::size_t(grid.cells[0] + grid.cells[1] + grid.cells[2]), 0.0);
  for (const Vec3& x : P.x) {
    std::size_t offset = 0;
    for (int d = 0; d < 3; ++d) {
      local[offset + std::size_t(grid.cell_along(d, x(d)))] += 1.0;
      offset += std::size_t(grid.cells[std::size_t(d)]);
    }
  }
  const std::vector<double> all = comm.sum_counts(local);
  AxisCounts counts;
  std::size_t offset = 0;
  for (int d = 0; d < 3; ++d) {
    for (int c = 0; c < grid.cells[std::size_t(d)]; ++c)
      counts[std::size_t(d)].push_back(static_cast<std::size_t>(all[offset + std::size_t(c)]));
    offset += std::size_t(grid.cells[std::size_t(d)]);
  }
  return counts;
}

MigrationCounts migrate(Particles& P, const BoxDecomposition& boxes, const GridSpec& grid,
                        const Communicator& comm) {
  MigrationCounts counts;
  const std::size_t n = P.size();
  const std::vector<bool> in_use = arrays_in_use(P, comm);
  std::vector<std::vector<char>> to(static_cast<std::size_t>(comm.size()));
  std::vector<char> keep(n, 1);
  for (std::size_t p = 0; p < n; ++p) {
    const int owner = boxes.owner_of_cell(grid.cell_of(P.x[p]));
    if (owner == comm.rank()) continue;
    pack(P, p, to[static_cast<std::size_t>(owner)]);
    keep[p] = 0;
    ++counts.sent;
  }
  if (!comm.any(counts.sent > 0)) return counts;
  if (counts.sent > 0) P.keep_only(keep);
  const std::size_t before = P.size();
  const std::vector<std::vector<char>> from = comm.all_to_all(to);
  for (const std::vector<char>& bytes : from) unpack(P, bytes, in_use);
  counts.received = P.size() - before;
  return counts;
}

Particles gather_particles(const Particles& local, const Communicator& comm) {
  if (comm.size() == 1) return local;
  const std::size_t n = local.size();
  const std::vector<bool> in_use = arrays_in_use(local, comm);
  std::vector<std::vector<char>> to(static_cast<std::size_t>(comm.size()));
  for (std::size_t p = 0; p < n; ++p) pack(local, p, to[0]);
  const std::vector<std::vector<char>> from = comm.all_to_all(to);
  Particles all;
  if (!comm.root()) return all;
  for (const std::vector<char>& bytes : from) unpack(all, bytes, in_use);
  // Seed order: the permutation that sorts by id, applied to every array.
  std::vector<std::size_t> order(all.size());
  for (std::size_t p = 0; p < order.size(); ++p) order[p] = p;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return all.id[a] < all.id[b]; });
  all.permute(order);
  all.id.clear();  // the index is the id again
  return all;
}

}  // namespace impact::mpm
