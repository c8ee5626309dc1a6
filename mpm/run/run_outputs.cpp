#include "mpm/run/run_outputs.hpp"

namespace impact::mpm {

RunOutputs::RunOutputs(const Scene& scene, const Simulation& seeded)
    : gauges_(scene, seeded.particles()),
      observables_(scene, seeded.particles()),
      faulted_column_(scene.physics.on_numerical_fault == NumericalFaultAction::fail_particle) {}

void RunOutputs::open(const Scene& scene, const std::filesystem::path& dir, const Simulation& sim,
                      const RunState* resumed) {
  paths_.emplace(scene, sim.particles());
  std::vector<std::string> columns = gauges_.columns();
  if (faulted_column_) columns.push_back("faulted_particles [-]");
  const std::string history_file = (dir / "history.csv").string();
  if (resumed) {
    observables_.restore(resumed->observables);
    history_.emplace(history_file, sim.ledger(), columns, resumed->history_bytes,
                     resumed->history_rows);
  } else {
    history_.emplace(history_file, sim.ledger(), columns);
  }
  if (scene.output.snapshots) {
    snapshots_.emplace(dir.string(), scene.output.fields);
    if (resumed) snapshots_->restore(resumed->snapshots);
  }
}

void RunOutputs::write_history(const Simulation& sim) {
  observables_.sample(sim.particles(), sim.time());  // max pressure: sampled at history rows
  std::vector<double> extra = gauges_.read(sim.particles());
  if (faulted_column_) extra.push_back(double(sim.faulted_particles()));
  history_->write(sim.ledger(), extra);
}

void RunOutputs::write_snapshot(const Simulation& sim, long index) {
  if (snapshots_) snapshots_->write(sim.particles(), index, sim.time());
}

RunState RunOutputs::state(double next_output, double wall) const {
  return RunState{next_output,
                  history_->bytes(),
                  history_->rows(),
                  observables_.state(),
                  snapshots_ ? snapshots_->entries() : decltype(RunState::snapshots){},
                  wall};
}

}  // namespace impact::mpm
