// What a run tells the terminal as it goes: a progress line (step, time, dt, energy error, ETA in
// duration_text's form;
// on a terminal rewritten in place at most twice a second; in a log (stderr not a terminal, the
// line asked for with --progress) one whole line after the first step and then every 10 s) and the
// particles flagged by numerical faults (physics.on_numerical_fault = fail_particle: the first 20
// printed, the rest counted).
#pragma once

#include <chrono>
#include <string>

#include "mpm/simulation/simulation.hpp"

namespace impact::mpm {

/// A duration for a person: "42 s", "12 min 5 s", "3 h 20 min", and from 100 h on two digits and
/// an exponent, "6.2e+301 s" (an estimate, not 300 digits); "unknown" when not finite.
std::string duration_text(double seconds);

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled);
  /// Starts the clock of the ETA (when the step loop starts).
  void start();
  /// Rewrites the line if half a second has passed since the last one.
  void update(const Simulation& sim);
  /// What a message on stderr starts with: a line break while the progress line is shown.
  const char* break_line() const { return enabled_ && in_place_ ? "\n" : ""; }
  /// Ends the line (a final line break).
  void end() const;

 private:
  bool enabled_;
  bool in_place_;       ///< stderr is a terminal: the line is rewritten with '\r'
  bool shown_ = false;  ///< a line was written
  std::chrono::steady_clock::time_point start_, last_;
};

class FaultReport {
 public:
  explicit FaultReport(const ProgressLine& progress) : progress_(progress) {}
  /// Warns on stderr about the particles the last step flagged.
  void report(const Simulation& sim);

 private:
  static constexpr long kLines = 20;  ///< faulted particles printed, then only counted
  const ProgressLine& progress_;
  long reported_ = 0;
};

}  // namespace impact::mpm
