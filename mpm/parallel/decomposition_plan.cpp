#include "mpm/parallel/decomposition_plan.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/parallel/migration.hpp"

namespace impact::mpm {

BoxDecomposition initial_boxes(const Scene& scene, int ranks, const AxisCounts& counts,
                               const std::function<std::vector<CellCount>()>& count_cells,
                               const TableSum& sum) {
  const std::array<int, 3>& p = scene.solver.ranks_per_axis;
  // A grid too small for the ranks is the scene's key and the rank count's: an input error.
  const auto refuse = [&](const std::string& key, const std::string& why) {
    return InputError(
        {scene.file + ": " + key + ": " + why + " (on " + std::to_string(ranks) + " MPI ranks)"});
  };
  if (p[0] == 0) {
    try {
      if (scene.solver.split == SplitRule::least_loaded)
        return least_loaded_split(scene.grid.cells, counts, ranks, count_cells(), sum).boxes;
      return BoxDecomposition::balanced(counts,
                                        BoxDecomposition::ranks_per_axis(scene.grid.cells, ranks));
    } catch (const std::invalid_argument& e) {
      throw refuse("/grid/cells", e.what());
    }
  }
  if (p[0] * p[1] * p[2] != ranks) {
    std::ostringstream m;
    m << "[" << p[0] << ", " << p[1] << ", " << p[2] << "] makes " << p[0] * p[1] * p[2]
      << " boxes; expected their product to be the rank count " << ranks
      << " (or [0, 0, 0] or \"least_loaded\" for an automatic split)";
    throw refuse("/solver/ranks_per_axis", m.str());
  }
  try {
    return BoxDecomposition::balanced(counts, p);
  } catch (const std::invalid_argument& e) {
    throw refuse("/solver/ranks_per_axis", e.what());
  }
}

namespace {

Json spread(const std::vector<double>& per_rank) {
  double sum = 0.0;
  for (const double v : per_rank) sum += v;
  return {{"min", *std::min_element(per_rank.begin(), per_rank.end())},
          {"mean", sum / double(per_rank.size())},
          {"max", *std::max_element(per_rank.begin(), per_rank.end())}};
}

// The particles per cell (one process: the sums are the identity).
std::vector<CellCount> count_cells(const Particles& P, const GridSpec& grid) {
  std::vector<CellCount> counted;
  for (const Vec3& x : P.x) count_cell(counted, grid.cell_of(x));
  return counted;
}

std::vector<double> on_one_process(const std::vector<double>& table) {
  return table;
}

// Of every admissible split of `ranks`, the least loaded boxes (split_search.hpp).
Json least_loaded(const Scene& scene, const Particles& P, const AxisCounts& counts, int ranks) {
  const SplitChoice best = least_loaded_split(scene.grid.cells, counts, ranks,
                                              count_cells(P, scene.grid), on_one_process);
  const double mean = double(P.size()) / ranks;
  return {{"ranks_per_axis", best.boxes.ranks_per_axis()},
          {"boxes",
           {{"x", best.boxes.axis(0).first_cells()},
            {"y", best.boxes.axis(1).first_cells()},
            {"z", best.boxes.axis(2).first_cells()}}},
          {"particles_per_rank_max", best.busiest},
          {"imbalance (max / mean)", mean > 0.0 ? best.busiest / mean : 1.0},
          {"splits_searched", best.splits_searched}};
}

}  // namespace

Json plan_decomposition(const Scene& scene, const Particles& P, int ranks) {
  const AxisCounts counts = axis_counts(P, scene.grid, Communicator());  // every particle here
  const BoxDecomposition boxes = initial_boxes(
      scene, ranks, counts, [&] { return count_cells(P, scene.grid); }, on_one_process);
  std::vector<double> held(std::size_t(ranks), 0.0), nodes(held), bytes(held), messages(held);
  for (const Vec3& x : P.x) held[std::size_t(boxes.owner_of_cell(scene.grid.cell_of(x)))] += 1.0;
  const int fields = scene.field_count();
  for (int r = 0; r < ranks; ++r) {
    const NodeBox box = stored_nodes(boxes, scene.grid, r);
    nodes[std::size_t(r)] = double(box.last[0] - box.first[0] + 1) *
                            double(box.last[1] - box.first[1] + 1) *
                            double(box.last[2] - box.first[2] + 1);
    const HaloTraffic t = halo_traffic(boxes, scene.grid, r, fields, scene.grid.has_walls(),
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
          {"least_loaded_split", least_loaded(scene, P, counts, ranks)}};
}

}  // namespace impact::mpm
