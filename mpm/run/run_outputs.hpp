// What a run writes as it goes: history.csv (the ledger and the gauges, with the observables
// sampled at every row), the particle snapshots (.vtu and .pvd) and the particle paths; and what
// of them a checkpoint must keep so that a restart continues every file where it stopped.
#pragma once

#include <filesystem>
#include <optional>

#include "mpm/output/displacement_error.hpp"
#include "mpm/output/face_reach.hpp"
#include "mpm/output/gauge_extrema.hpp"
#include "mpm/output/observables.hpp"
#include "mpm/output/output.hpp"
#include "mpm/output/particle_paths.hpp"
#include "mpm/run/checkpoint.hpp"
#include "mpm/simulation/simulation.hpp"

namespace impact::mpm {

class RunOutputs {
 public:
  /// The gauge and crater particle sets, from the particles as seeded (before a checkpoint is
  /// loaded). On several ranks (`comm`) every rank makes one from the particles it holds, and
  /// every call below that takes particles is collective: the gauges, observables and snapshots
  /// reduce or write per rank, rank 0 alone writes history.csv and the .pvd.
  RunOutputs(const Scene& scene, const Particles& seeded, const Communicator& comm);
  /// Opens the files in `dir` for the particles as the run starts: as seeded, or, with `resumed`,
  /// as restored from a checkpoint (history.csv is then truncated to the checkpoint's rows and
  /// continued, the observables and the snapshot collection continue, the particle paths begin
  /// here).
  void open(const Scene& scene, const std::filesystem::path& dir, const Particles& P,
            const Ledger& ledger, const RunState* resumed);

  /// Around Simulation::step(): the particle paths record the step.
  void before_step(const Particles& P) { paths_->before_step(P); }
  void after_step(const Particles& P, double time, double dt) { paths_->after_step(P, time, dt); }

  /// A history row of sim's ledger with the gauges of P (the observables, the gauges' extrema and
  /// the faces material reached are sampled with it); P: the particles this rank holds. Returns
  /// the faces reached for the first time at this row (FaceReach::sample).
  std::vector<int> write_history(const Simulation& sim, const Particles& P);
  /// A snapshot of P numbered `index` (the step, or step + 1 for the state a failure left).
  void write_snapshot(const Particles& P, long index, double time);

  /// The files' positions for a checkpoint, with the next output time and the wall time so far.
  RunState state(double next_output, double wall) const;

  /// The particle paths' files (also after a failure: the path up to it); `start` is the time
  /// they begin at (0, or the restart's time).
  void write_paths(const std::filesystem::path& dir, const Scene& scene, double start) const {
    paths_->write(dir, scene, scene.file, start);
  }
  const Observables& observables() const { return observables_; }
  /// The gauges' extrema over the history rows so far (summary.json "gauges").
  const GaugeExtrema& gauge_extrema() const { return gauge_extrema_; }
  /// The outer faces material reached (summary.json "material_reached_faces").
  const FaceReach& face_reach() const { return face_reach_; }
  const ParticlePaths& paths() const { return *paths_; }

 private:
  Gauges gauges_;
  GaugeExtrema gauge_extrema_;
  Observables observables_;
  FaceReach face_reach_;
  std::optional<ParticlePaths> paths_;
  std::optional<DisplacementError> displacement_error_;  ///< output.exact_displacement
  bool faulted_column_;
  const Communicator& comm_;
  std::optional<HistoryCsv> history_;
  std::optional<SnapshotWriter> snapshots_;
};

}  // namespace impact::mpm
