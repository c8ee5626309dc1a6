// SIGINT / SIGTERM: record the signal, nothing else (async-signal-safe).
#include "mpm/run/interrupt.hpp"

#include <signal.h>

namespace impact::mpm {

namespace {

volatile sig_atomic_t g_signal = 0;
struct sigaction g_previous_int, g_previous_term;

extern "C" void record_signal(int signal) {
  g_signal = signal;
}

}  // namespace

InterruptHandlers::InterruptHandlers(bool install) {
  if (!install) return;
  g_signal = 0;
  struct sigaction action = {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // a second signal: the default action
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
  installed_ = true;
}

InterruptHandlers::~InterruptHandlers() {
  if (!installed_) return;
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  g_signal = 0;
}

int pending_interrupt() {
  return g_signal;
}

const char* signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "a signal";
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
