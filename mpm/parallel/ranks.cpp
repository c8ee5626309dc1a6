#include "mpm/parallel/ranks.hpp"

#include <functional>

#include "mpm/parallel/decomposition_plan.hpp"
#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/parallel/migration.hpp"

namespace impact::mpm {

namespace {

bool least_loaded(const Scene& scene) {
  return scene.solver.split == SplitRule::least_loaded && scene.solver.ranks_per_axis[0] == 0;
}

}  // namespace

Ranks::SeedCensus Ranks::census(const Scene& scene) const {
  if (!several()) return {};
  // Each rank counts an equal block of cell columns and the counts (whole numbers) are summed:
  // no rank walks every seed point of the scene.
  const long columns = scene.grid.cells[0], ranks = comm_.size(), r = comm_.rank();
  SeedCensus c;
  c.columns = seed_counts_per_column(
      scene, &c.per_axis, int(columns * r / ranks), int(columns * (r + 1) / ranks),
      least_loaded(scene) ? std::function<void(const std::array<int, 3>&)>(
                                [&](const std::array<int, 3>& cell) { count_cell(c.cells, cell); })
                          : nullptr);
  std::vector<double> table;  // each object's columns, then the cells along each axis
  for (const auto& object : c.columns)
    for (const std::size_t n : object) table.push_back(double(n));
  for (const auto& axis : c.per_axis)
    for (const std::size_t n : axis) table.push_back(double(n));
  table = comm_.sum_counts(table);
  std::size_t k = 0;
  for (auto& object : c.columns)
    for (std::size_t& n : object) n = std::size_t(table[k++]);
  for (auto& axis : c.per_axis)
    for (std::size_t& n : axis) n = std::size_t(table[k++]);
  return c;
}

BoxDecomposition Ranks::split(const Scene& scene, const SeedCensus& census) const {
  if (!several()) return BoxDecomposition(scene.grid.cells);
  // "least_loaded": the census counted this rank's block's points per cell; the tables the
  // search builds from them are summed over the ranks.
  return initial_boxes(
      scene, comm_.size(), census.per_axis, [&] { return census.cells; },
      [&](const std::vector<double>& table) { return comm_.sum_counts(table); });
}

Particles Ranks::seed(const Scene& scene, const BoxDecomposition& boxes,
                      const SeedCensus& census) const {
  // On several ranks every rank seeds and stores only its box: no rank ever holds the whole
  // scene or the whole grid.
  if (!several()) return seed_particles(scene);
  return seed_box(scene, boxes.first_cell(rank()), boxes.end_cell(rank()), census.columns);
}

std::optional<NodeBox> Ranks::stored_box(const BoxDecomposition& boxes,
                                         const GridSpec& grid) const {
  if (!several()) return std::nullopt;
  return stored_nodes(boxes, grid, rank());
}

NodeBox Ranks::owned_box(const BoxDecomposition& boxes, const std::array<int, 3>& cells) const {
  const std::array<int, 3> coordinates = boxes.coordinates(rank());
  NodeBox owned;
  for (std::size_t d = 0; d < 3; ++d) {
    const SlabDecomposition& axis = boxes.axis(int(d));
    const int c = coordinates[d];
    owned.first[d] = c == 0 ? -1 : axis.first_cell(c);
    owned.last[d] = c + 1 == axis.ranks() ? cells[d] + 1 : axis.first_cell(c + 1) - 1;
  }
  return owned;
}

std::optional<std::string> Ranks::first_failure(const std::optional<std::string>& mine) const {
  if (!several()) return mine;
  const std::vector<double> failed = comm_.gather_all(mine ? 1.0 : 0.0);
  for (int r = 0; r < comm_.size(); ++r)
    if (failed[std::size_t(r)] != 0.0) return comm_.broadcast(mine.value_or(""), r);
  return std::nullopt;
}

long Ranks::sum(long n) const {
  return static_cast<long>(comm_.sum(static_cast<std::int64_t>(n)));
}

std::size_t Ranks::migrate(Particles& P, const BoxDecomposition& boxes,
                           const GridSpec& grid) const {
  return several() ? mpm::migrate(P, boxes, grid, comm_).sent : 0;
}

std::optional<BoxDecomposition> Ranks::rebalanced(const Particles& P, const BoxDecomposition& boxes,
                                                  const Scene& scene) const {
  if (!several()) return std::nullopt;
  const std::vector<double> held = comm_.gather_all(double(P.size()));
  double total = 0.0, largest = 0.0;
  for (const double n : held) {
    total += n;
    largest = std::max(largest, n);
  }
  if (!(largest > scene.solver.rebalance_above * total / comm_.size())) return std::nullopt;
  BoxDecomposition next =
      BoxDecomposition::balanced(axis_counts(P, scene.grid, comm_), boxes.ranks_per_axis());
  if (least_loaded(scene)) {
    std::vector<CellCount> counted;  // this rank's particles, summed over the ranks per table
    for (const Vec3& x : P.x) count_cell(counted, scene.grid.cell_of(x));
    next = refine_boundaries(
        next, counted, [&](const std::vector<double>& t) { return comm_.sum_counts(t); }, nullptr);
  }
  if (next == boxes) return std::nullopt;  // already as balanced as boxes can be
  return next;
}

}  // namespace impact::mpm
