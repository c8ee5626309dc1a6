#include "mpm/parallel/decomposition_plan.hpp"

#include <algorithm>
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

}  // namespace

Json plan_decomposition(const Scene& scene, const Particles& P, int ranks) {
  const BoxDecomposition boxes =
      BoxDecomposition::balanced(axis_counts(P, scene.grid), ranks_per_axis_of(scene, ranks));
  std::vector<double> held(std::size_t(ranks), 0.0), nodes(held), bytes(held), messages(held);
  for (const Vec3& x : P.x) held[std::size_t(boxes.owner_of_cell(cell_of(scene.grid, x)))] += 1.0;
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
          {"halo_messages_sent_per_step", spread(messages)}};
}

}  // namespace impact::mpm
