#include "mpm/run/run_status.hpp"

#include "mpm/run/checkpoint.hpp"
#include "support/atomic_file.hpp"

namespace impact::mpm {

void RunStatus::write(const Simulation& sim, double wall, const std::string& status,
                      const std::string& message) const {
  Json j = {{"status", status},
            {"step", sim.steps()},
            {"time [s]", sim.time()},
            {"energy_error [-]", sim.ledger().row().energy_error},
            {"wall_time [s]", wall}};
  if (report_faulted_) j["faulted_particles"] = sim.faulted_particles();
  if (checkpoint_) {
    j["checkpoint"] = {
        {"file", kCheckpointFile}, {"step", checkpoint_->first}, {"time [s]", checkpoint_->second}};
  }
  if (status != "running") j["message"] = message;
  write_file_atomically(dir_ / "status.json", [&](std::ostream& o) { o << j.dump(2) << '\n'; });
}

}  // namespace impact::mpm
