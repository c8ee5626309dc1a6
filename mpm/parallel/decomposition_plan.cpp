#include "mpm/parallel/decomposition_plan.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/parallel/migration.hpp"

namespace impact::mpm {

std::array<int, 3> ranks_per_axis_of(const Scene& scene, int ranks) {
  const std::array<int, 3>& p = scene.solver.ranks_per_axis;
  if (p[0] == 0) return BoxDecomposition::ranks_per_axis(scene.grid.cells, ranks);
  if (p[0] * p[1] * p[2] != ranks) {
    std::ostringstream m;
    m << scene.file << ": /solver/ranks_per_axis: [" << p[0] << ", " << p[1] << ", " << p[2]
      << "] makes " << p[0] * p[1] * p[2] << " boxes; expected their product to be the rank count "
      << ranks << " (or [0, 0, 0] for the automatic split)";
    throw std::invalid_argument(m.str());
  }
  return p;
}

namespace {

Json spread(const std::vector<double>& per_rank) {
  double sum = 0.0;
  for (const double v : per_rank) sum += v;
  return {{"min", *std::min_element(per_rank.begin(), per_rank.end())},
          {"mean", sum / double(per_rank.size())},
          {"max", *std::max_element(per_rank.begin(), per_rank.end())}};
}

// Particles per cell summed over the boxes [0, i) x [0, j) x [0, k) (a summed-volume table), so
// that any box's count is 8 lookups: every split of the rank count is then weighed in O(ranks).
class CellSums {
 public:
  CellSums(const Particles& P, const GridSpec& grid)
      : n_{grid.cells[0] + 1, grid.cells[1] + 1, grid.cells[2] + 1},
        sum_(std::size_t(n_[0]) * std::size_t(n_[1]) * std::size_t(n_[2]), 0.0) {
    for (const Vec3& x : P.x) {
      const std::array<int, 3> c = grid.cell_of(x);
      sum_[at(c[0] + 1, c[1] + 1, c[2] + 1)] += 1.0;
    }
    for (int i = 1; i < n_[0]; ++i)  // prefix sums along each axis in turn
      for (int j = 0; j < n_[1]; ++j)
        for (int k = 0; k < n_[2]; ++k) sum_[at(i, j, k)] += sum_[at(i - 1, j, k)];
    for (int i = 0; i < n_[0]; ++i)
      for (int j = 1; j < n_[1]; ++j)
        for (int k = 0; k < n_[2]; ++k) sum_[at(i, j, k)] += sum_[at(i, j - 1, k)];
    for (int i = 0; i < n_[0]; ++i)
      for (int j = 0; j < n_[1]; ++j)
        for (int k = 1; k < n_[2]; ++k) sum_[at(i, j, k)] += sum_[at(i, j, k - 1)];
  }
  /// Particles in the cells [lo, hi) per axis.
  double in(const std::array<int, 3>& lo, const std::array<int, 3>& hi) const {
    double s = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const int i = corner & 1 ? hi[0] : lo[0], j = corner & 2 ? hi[1] : lo[1],
                k = corner & 4 ? hi[2] : lo[2];
      const int lows = !(corner & 1) + !(corner & 2) + !(corner & 4);
      s += (lows % 2 ? -1.0 : 1.0) * sum_[at(i, j, k)];
    }
    return s;
  }

 private:
  std::size_t at(int i, int j, int k) const {
    return (std::size_t(i) * std::size_t(n_[1]) + std::size_t(j)) * std::size_t(n_[2]) +
           std::size_t(k);
  }
  std::array<int, 3> n_;
  std::vector<double> sum_;
};

// Above this many cells the table (8 B per cell) is not built.
constexpr double kMaxTableCells = 32e6;

// Of every admissible split of `ranks`, the one whose busiest box holds the fewest particles
// (fewer cut node faces on a tie), with the boxes balanced per axis as a run would balance them.
Json least_loaded_split(const Scene& scene, const Particles& P, const AxisCounts& counts,
                        int ranks) {
  const std::array<int, 3>& cells = scene.grid.cells;
  if (double(cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1) > kMaxTableCells)
    return "not searched: more than 32e6 cells";
  const CellSums sums(P, scene.grid);
  std::array<int, 3> best{0, 0, 0};
  double fewest = std::numeric_limits<double>::infinity(), best_cut = fewest;
  const std::vector<std::array<int, 3>> splits = BoxDecomposition::splits(cells, ranks);
  for (const std::array<int, 3>& p : splits) {
    const BoxDecomposition boxes = BoxDecomposition::balanced(counts, p);
    double busiest = 0.0;
    for (int r = 0; r < ranks; ++r)
      busiest = std::max(busiest, sums.in(boxes.first_cell(r), boxes.end_cell(r)));
    const double cut = BoxDecomposition::cut_faces(cells, p);
    if (busiest < fewest || (busiest == fewest && cut < best_cut)) {
      fewest = busiest;
      best_cut = cut;
      best = p;
    }
  }
  const double mean = double(P.size()) / ranks;
  return {{"ranks_per_axis", best},
          {"particles_per_rank_max", fewest},
          {"imbalance (max / mean)", mean > 0.0 ? fewest / mean : 1.0},
          {"splits_searched", splits.size()}};
}

}  // namespace

Json plan_decomposition(const Scene& scene, const Particles& P, int ranks) {
  const AxisCounts counts = axis_counts(P, scene.grid);
  const BoxDecomposition boxes =
      BoxDecomposition::balanced(counts, ranks_per_axis_of(scene, ranks));
  std::vector<double> held(std::size_t(ranks), 0.0), nodes(held), bytes(held), messages(held);
  for (const Vec3& x : P.x) held[std::size_t(boxes.owner_of_cell(scene.grid.cell_of(x)))] += 1.0;
  const int fields = scene.field_count();
  const bool stress = fields > 1 && scene.physics.contact.type == ContactType::friction;
  for (int r = 0; r < ranks; ++r) {
    const NodeBox box = stored_nodes(boxes, scene.grid.cells, r);
    nodes[std::size_t(r)] = double(box.last[0] - box.first[0] + 1) *
                            double(box.last[1] - box.first[1] + 1) *
                            double(box.last[2] - box.first[2] + 1);
    const HaloTraffic t = halo_traffic(boxes, scene.grid.cells, r, fields, stress,
                                       scene.solver.scheme == Scheme::musl);
    bytes[std::size_t(r)] = t.bytes;
    messages[std::size_t(r)] = t.messages;
  }
  const Json particles = spread(held);
  const double mean = particles["mean"].get<double>();
  return {{"ranks", ranks},
          {"ranks_per_axis", boxes.ranks_per_axis()},
          {"boxes",
           {{"x", boxes.axis(0).first_cells()},
            {"y", boxes.axis(1).first_cells()},
            {"z", boxes.axis(2).first_cells()}}},
          {"particles_per_rank", particles},
          {"imbalance (max / mean)", mean > 0.0 ? particles["max"].get<double>() / mean : 1.0},
          {"empty_ranks", std::count(held.begin(), held.end(), 0.0)},
          {"grid_nodes_per_rank", spread(nodes)},
          {"halo_bytes_sent_per_step [B]", spread(bytes)},
          {"halo_messages_sent_per_step", spread(messages)},
          {"least_loaded_split", least_loaded_split(scene, P, counts, ranks)}};
}

}  // namespace impact::mpm
