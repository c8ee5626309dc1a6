// status.json: where a run is (rewritten at every history row) and how it ended; the last file a
// run writes, so a "completed" status means every other file is in place.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "mpm/simulation/simulation.hpp"

namespace impact::mpm {

class RunStatus {
 public:
  RunStatus(std::filesystem::path dir, bool report_faulted)
      : dir_(std::move(dir)), report_faulted_(report_faulted) {}

  /// Records the step and time of the last checkpoint (named in every later status).
  void checkpointed(long step, double time) { checkpoint_ = std::pair{step, time}; }
  /// The step of the last checkpoint, if any.
  std::optional<long> checkpoint_step() const {
    return checkpoint_ ? std::optional<long>(checkpoint_->first) : std::nullopt;
  }

  /// Writes status.json: "running", "completed", "failed" or "interrupted" (with `message` unless
  /// running), the step, time, energy error and `wall` time [s].
  void write(const Simulation& sim, double wall, const std::string& status,
             const std::string& message = "") const;

 private:
  std::filesystem::path dir_;
  bool report_faulted_;
  std::optional<std::pair<long, double>> checkpoint_;
};

}  // namespace impact::mpm
