// The ranks of a run as one service to the Simulation (docs/mpi.md): which box and which particles
// each rank starts with, the agreement that one rank's failure stops every rank, the sums of a
// step's totals, and the particles that change box. On one rank every call is the identity and
// makes no MPI call, so the step loop reads the same on one rank and on many.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/ledger/totals.hpp"
#include "mpm/parallel/box_decomposition.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/parallel/split_search.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

class Ranks {
 public:
  /// The ranks of `comm` (one rank: this process alone).
  explicit Ranks(const Communicator& comm) : comm_(comm) {}

  bool several() const { return comm_.several(); }
  int rank() const { return comm_.rank(); }
  int size() const { return comm_.size(); }
  const Communicator& communicator() const { return comm_; }

  /// The seed points per cell column of each object (ids) and per cell along each axis (balance):
  /// what several ranks split the grid and seed their boxes from (empty on one rank).
  struct SeedCensus {
    SeedCounts columns;
    SeedAxisCounts per_axis;
    /// This rank's block's points per cell, for the "least_loaded" search (else empty).
    std::vector<CellCount> cells;
  };
  SeedCensus census(const Scene& scene) const;
  /// The boxes of the ranks (solver.ranks_per_axis) balanced by the census; one rank: one box.
  BoxDecomposition split(const Scene& scene, const SeedCensus& census) const;
  /// This rank's particles: its box's seed points (one rank: every seed point).
  Particles seed(const Scene& scene, const BoxDecomposition& boxes, const SeedCensus& census) const;
  /// The nodes this rank's grid stores: its box's cells [c0, c1) per axis and the halo its
  /// particles' stencils, the shared-layer sums and the contact gradients reach,
  /// [c0 - kHaloPlanes, c1 + kHaloPlanes]; nullopt (the whole grid) on one rank.
  std::optional<NodeBox> stored_box(const BoxDecomposition& boxes, const GridSpec& grid) const;
  /// The nodes this rank owns for the ledger (the end boxes also own the ghost layer and the
  /// last node layer outside their cells).
  NodeBox owned_box(const BoxDecomposition& boxes, const std::array<int, 3>& cells) const;

  /// The failure every rank stops with: the lowest failing rank's message, on every rank (one
  /// rank: `mine`). Collective: every rank calls it at the same point of the step.
  std::optional<std::string> first_failure(const std::optional<std::string>& mine) const;
  /// Sums (and maxima) of totals over the ranks: one reduction of every summed field and one of
  /// every largest, in table order (mpm/ledger/totals.hpp); nothing on one rank.
  template <class... Totals>
  void reduce(Totals&... totals) const {
    if (!several()) return;
    for (const Merge merge : {Merge::sum, Merge::max}) {
      std::vector<double> v;
      (append_fields(totals, merge, v), ...);
      v = merge == Merge::sum ? comm_.sum(v) : comm_.max(v);
      std::size_t k = 0;
      (extract_fields(totals, merge, v, k), ...);
    }
  }
  /// A count, values, the least and the largest over the ranks (rank order: the same bits on
  /// every rank).
  long sum(long n) const;
  std::vector<double> sum(const std::vector<double>& v) const { return comm_.sum(v); }
  double min(double x) const { return comm_.min(x); }
  double max(double x) const { return comm_.max(x); }

  /// Particles that left this rank's box go to their owner; returns how many this rank sent.
  std::size_t migrate(Particles& P, const BoxDecomposition& boxes, const GridSpec& grid) const;
  /// Boxes balanced by the current particle counts when the largest rank holds more than
  /// solver.rebalance_above times the mean and the balance can improve; else nullopt (always
  /// on one rank). Decided from particle counts only: the same on every rank and in every run.
  std::optional<BoxDecomposition> rebalanced(const Particles& P, const BoxDecomposition& boxes,
                                             const Scene& scene) const;

 private:
  const Communicator& comm_;
};

}  // namespace impact::mpm
