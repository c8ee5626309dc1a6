// SIGINT and SIGTERM for `mpm run`: the handler only records the signal; the step loop looks at
// it after every step, writes a checkpoint, closes its outputs and exits with 128 + the signal
// number (docs/mpm.md#checkpoint-and-restart). The handler is installed with SA_RESETHAND, so a
// second signal takes its default action (stops the program at once).
// Kept apart from the rest of the solver: <signal.h> defines macros (si_value, ...) that must not
// meet the project's headers.
#pragma once

#include <memory>

namespace impact {
class InterruptSignals;  // support/interrupt_signals.hpp
}

namespace impact::mpm {

/// Installs the handlers for its lifetime (restoring the previous ones after) when `install`.
class InterruptHandlers {
 public:
  explicit InterruptHandlers(bool install);
  ~InterruptHandlers();
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;

 private:
  std::shared_ptr<InterruptSignals> signals_;  // shared_ptr: deletes a type incomplete here
};

/// The signal received since the handlers were installed (SIGINT or SIGTERM), or 0.
int pending_interrupt();
/// "SIGINT" or "SIGTERM" (or "signal N").
const char* signal_name(int signal);
/// Signal numbers, for callers that must not include <signal.h>.
int sigint_number();
int sigterm_number();
/// raise(signal) (fault injection: a signal at a known step).
void raise_signal(int signal);

}  // namespace impact::mpm
