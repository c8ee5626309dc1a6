#include "mpm/run/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace impact::mpm {

std::string duration_text(double seconds) {
  if (!std::isfinite(seconds)) return "unknown";
  char text[64];
  const double s = std::max(seconds, 0.0);
  if (s < 59.5) {
    std::snprintf(text, sizeof text, "%.0f s", s);
  } else if (s < 3600.0 - 0.5) {
    const long whole = std::lround(s);
    std::snprintf(text, sizeof text, "%ld min %ld s", whole / 60, whole % 60);
  } else if (s < 100.0 * 3600.0) {
    const long minutes = std::lround(s / 60.0);
    std::snprintf(text, sizeof text, "%ld h %ld min", minutes / 60, minutes % 60);
  } else {
    std::snprintf(text, sizeof text, "%.1e s", s);
  }
  return text;
}

ProgressLine::ProgressLine(bool enabled)
    : enabled_(enabled), in_place_(isatty(STDERR_FILENO) != 0) {}

void ProgressLine::start() {
  start_ = last_ = std::chrono::steady_clock::now();
}

void ProgressLine::update(const Simulation& sim) {
  const auto now = std::chrono::steady_clock::now();
  if (!enabled_) return;
  const auto interval = in_place_ ? std::chrono::milliseconds(500) : std::chrono::seconds(10);
  // A log gets its first line at once (the run has started); a terminal after half a second.
  if ((shown_ || in_place_) && now - last_ <= interval) return;
  last_ = now;
  shown_ = true;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double eta = wall * (sim.scene().time.max_time - sim.time()) / sim.time();
  std::fprintf(stderr, "%sstep %ld  t %.4e s  dt %.3e s  energy_error %+.3e  ETA %s%s",
               in_place_ ? "\r" : "", sim.steps(), sim.time(), sim.next_dt(),
               sim.ledger().row().energy_error, duration_text(eta).c_str(),
               in_place_ ? "   " : "\n");
}

void ProgressLine::end() const {
  if (enabled_ && in_place_) std::fprintf(stderr, "\n");
}

void FaultReport::report(const Simulation& sim) {
  for (const Failure& f : sim.last_faults()) {
    if (reported_ < kLines) {
      std::cerr << progress_.break_line()
                << "mpm: warning: " << sim.describe(f, sim.steps(), sim.time())
                << ": particle flagged failed (physics.on_numerical_fault = fail_particle: "
                   "zero stress, no further update); the run goes on\n";
    } else if (reported_ == kLines) {
      std::cerr << "mpm: warning: further faulted particles are counted, not printed\n";
    }
    ++reported_;
  }
}

}  // namespace impact::mpm
