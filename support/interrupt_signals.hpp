// SIGINT and SIGTERM for the programs' long loops (`mpm run`, `pointdriver run`): the handler
// only records the signal (async-signal-safe); the loop looks at it between steps, closes or
// discards its outputs and exits with 128 + the signal number. Installed with SA_RESETHAND, so a
// second signal takes its default action (stops the program at once). Only the programs' .cpp
// files include it (mpm/run/interrupt.cpp, pointdriver/commands/run_command.cpp): <csignal>'s
// macros stay out of the libraries' headers.
#pragma once

#include <signal.h>

#include <csignal>

namespace impact::interrupt_signals {
inline volatile std::sig_atomic_t received = 0;
}  // namespace impact::interrupt_signals

extern "C" inline void impact_record_interrupt(int signal) {
  impact::interrupt_signals::received = signal;
}

namespace impact {

/// Installs the handlers for its lifetime (restoring the previous ones after) when `install`.
class InterruptSignals {
 public:
  explicit InterruptSignals(bool install = true) {
    if (!install) return;
    interrupt_signals::received = 0;
    struct sigaction action = {};
    action.sa_handler = impact_record_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // a second signal: the default action
    sigaction(SIGINT, &action, &previous_int_);
    sigaction(SIGTERM, &action, &previous_term_);
    installed_ = true;
  }
  ~InterruptSignals() {
    if (!installed_) return;
    sigaction(SIGINT, &previous_int_, nullptr);
    sigaction(SIGTERM, &previous_term_, nullptr);
    interrupt_signals::received = 0;
  }
  InterruptSignals(const InterruptSignals&) = delete;
  InterruptSignals& operator=(const InterruptSignals&) = delete;

  /// The signal received since the handlers were installed (SIGINT or SIGTERM), or 0.
  static int pending() { return interrupt_signals::received; }
  /// "SIGINT" or "SIGTERM" (or "a signal").
  static const char* name(int signal) {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    return "a signal";
  }

 private:
  bool installed_ = false;
  struct sigaction previous_int_ = {}, previous_term_ = {};
};

}  // namespace impact
