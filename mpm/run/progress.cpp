#include "mpm/run/progress.hpp"

#include <cstdio>
#include <iostream>

namespace impact::mpm {

void ProgressLine::start() {
  start_ = last_ = std::chrono::steady_clock::now();
}

void ProgressLine::update(const Simulation& sim) {
  const auto now = std::chrono::steady_clock::now();
  if (!enabled_ || now - last_ <= std::chrono::milliseconds(500)) return;
  last_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double eta = wall * (sim.scene().time.max_time - sim.time()) / sim.time();
  std::fprintf(stderr, "\rstep %ld  t %.4e s  dt %.3e s  energy_error %+.3e  ETA %.0f s   ",
               sim.steps(), sim.time(), sim.next_dt(), sim.ledger().row().energy_error, eta);
}

void ProgressLine::end() const {
  if (enabled_) std::fprintf(stderr, "\n");
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
