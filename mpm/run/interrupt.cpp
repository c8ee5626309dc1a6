// SIGINT / SIGTERM: the programs' one handler (support/interrupt_signals.hpp) behind the solver's
// signal-free header.
#include "mpm/run/interrupt.hpp"

#include <memory>

#include "support/interrupt_signals.hpp"

namespace impact::mpm {

InterruptHandlers::InterruptHandlers(bool install)
    : signals_(install ? std::make_shared<InterruptSignals>() : nullptr) {}

InterruptHandlers::~InterruptHandlers() = default;

int pending_interrupt() {
  return InterruptSignals::pending();
}

const char* signal_name(int signal) {
  return InterruptSignals::name(signal);
}

int sigint_number() {
  return SIGINT;
}

int sigterm_number() {
  return SIGTERM;
}

void raise_signal(int signal) {
  raise(signal);
}

}  // namespace impact::mpm
