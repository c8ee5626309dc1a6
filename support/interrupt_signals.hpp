// SIGINT and SIGTERM for the programs' long loops (`mpm run`, `pointdriver run`): the handler
// only records the signal (async-signal-safe); the loop looks at it between steps, closes or
// discards its outputs and exits with 128 + the signal number. A second signal a second or more
// after the first takes its default action (a person pressing Ctrl-C again stops the program at
// once); one within the same second is the same request delivered twice and is ignored: `timeout
// -s INT` signals the child and then its process group, and the copy killed mpm in the middle of
// its checkpoint (status.json left "running", only checkpoint.bin.tmp; issue 52's second trial,
// about 1 in 24 tries). clock_gettime, signal and raise are async-signal-safe. Only the programs'
// .cpp files include it (mpm/run/interrupt.cpp, pointdriver/commands/run_command.cpp): <csignal>'s
// macros stay out of the libraries' headers.
#pragma once

#include <signal.h>

#include <time.h>

#include <csignal>

namespace impact::interrupt_signals {
inline volatile std::sig_atomic_t received = 0;
inline volatile std::sig_atomic_t first_second = 0;  ///< CLOCK_MONOTONIC seconds of the first
}  // namespace impact::interrupt_signals

extern "C" inline void impact_record_interrupt(int signal) {
  namespace is = impact::interrupt_signals;
  struct timespec now = {};
  clock_gettime(CLOCK_MONOTONIC, &now);
  if (is::received == 0) {
    is::received = signal;
    is::first_second = static_cast<std::sig_atomic_t>(now.tv_sec);
    return;
  }
  if (now.tv_sec - is::first_second < 1) return;  // the same request delivered twice
  ::signal(signal, SIG_DFL);                      // a second request: the default action, at once
  raise(signal);
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
    action.sa_flags = 0;  // a second signal a second later: the default action (the handler)
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
