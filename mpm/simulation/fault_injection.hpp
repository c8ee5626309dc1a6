// Faults planted on purpose (mpm run --inject-fault KIND:STEP[:PARTICLE], a developer option;
// docs/mpm.md#fault-injection): they show that the detection and the clean stop work. The
// Simulation applies them at the start of their step (Simulation::inject); the run loop raises the
// signals.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

struct FaultInjection {
  enum class Kind {
    nan,           ///< the stress PARTICLE's update returns in step STEP is replaced by NaN
    nan_velocity,  ///< PARTICLE's velocity is set to NaN at the start of step STEP
    outside,       ///< PARTICLE is moved one cell beyond the grid's x+ face at the start of STEP
    jacobian,      ///< PARTICLE's F gets det F < 0 (first column negated) at the start of STEP
    sigterm,       ///< SIGTERM is raised after step STEP (mpm run's handler: checkpoint, stop)
    sigint,        ///< SIGINT likewise
  };
  Kind kind = Kind::nan;
  long step = 1;
  std::size_t particle = 0;

  bool is_signal() const { return kind == Kind::sigterm || kind == Kind::sigint; }
};

/// Parses "nan:STEP:PARTICLE", "nan_velocity:..", "outside:..", "jacobian:..", "sigterm:STEP",
/// "sigint:STEP" (STEP >= 1); nullopt when malformed.
std::optional<FaultInjection> parse_fault_injection(const std::string& text);

/// Applies the faults of step `step` to this rank's particles (a fault's particle is its seed
/// index: P.id where it is kept, several ranks or a shuffled store, else the index itself; a rank
/// without it does nothing).
/// Returns the index whose stress update is to return NaN in this step, or -1.
std::ptrdiff_t apply_faults(const std::vector<FaultInjection>& faults, long step, Particles& P,
                            const GridSpec& grid);

}  // namespace impact::mpm
