#include "mpm/run/run_outputs.hpp"

namespace impact::mpm {

RunOutputs::RunOutputs(const Scene& scene, const Particles& seeded, const Communicator& comm)
    : gauges_(scene, seeded, comm),
      gauge_extrema_(gauges_.units()),
      observables_(scene, seeded, comm),
      face_reach_(scene, seeded, comm),
      paths_(std::in_place, scene, seeded, comm),
      displacement_error_(scene.output.exact_displacement
                              ? std::optional<DisplacementError>(std::in_place, scene, comm)
                              : std::nullopt),
      faulted_column_(scene.physics.on_numerical_fault == NumericalFaultAction::fail_particle),
      comm_(comm) {}

void RunOutputs::open(const Scene& scene, const std::filesystem::path& dir, const Particles& P,
                      const Ledger& ledger, const RunState* resumed) {
  if (resumed) paths_->begin_at(P);  // the particles chosen as seeded, from their state now
  std::vector<std::string> columns = gauges_.columns();
  if (displacement_error_)
    for (const std::string& c : DisplacementError::columns()) columns.push_back(c);
  if (faulted_column_) columns.push_back("faulted_particles [-]");
  const std::string history_file = (dir / "history.csv").string();
  if (resumed) {
    observables_.restore(resumed->observables);
    gauge_extrema_.restore(resumed->gauge_extrema);
    face_reach_.restore(resumed->faces_reached);
  }
  const bool root = comm_.root();
  if (root && resumed) {
    history_.emplace(history_file, ledger, columns, resumed->history_bytes, resumed->history_rows);
  } else if (root) {
    history_.emplace(history_file, ledger, columns);
  }
  if (scene.output.snapshots) {
    snapshots_.emplace(dir.string(), scene.output.fields, comm_);
    if (resumed) snapshots_->restore(resumed->snapshots);
  }
}

std::vector<int> RunOutputs::write_history(const Simulation& sim, const Particles& P) {
  observables_.sample(P, sim.time());  // max pressure: sampled at history rows
  std::vector<double> extra = gauges_.read(P);
  gauge_extrema_.sample(extra, sim.time());  // the gauges' columns of this row
  if (displacement_error_)
    for (const double e : displacement_error_->read(P, sim.time())) extra.push_back(e);
  if (faulted_column_) extra.push_back(double(sim.faulted_particles()));
  if (history_) history_->write(sim.ledger(), extra);
  return face_reach_.sample(P, sim.time());
}

void RunOutputs::write_snapshot(const Particles& P, long index, double time) {
  if (snapshots_) snapshots_->write(P, index, time);
}

RunState RunOutputs::state(double next_output, double wall) const {
  return RunState{next_output,
                  history_ ? history_->bytes() : 0,
                  history_ ? history_->rows() : 0,
                  observables_.state(),
                  gauge_extrema_.state(),
                  face_reach_.state(),
                  snapshots_ ? snapshots_->entries() : decltype(RunState::snapshots){},
                  wall};
}

}  // namespace impact::mpm
