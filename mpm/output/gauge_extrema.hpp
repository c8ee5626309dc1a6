// The extrema of every gauge over the history rows (summary.json "gauges": max, min, peak and the
// peak's time, docs/mpm.md#output): a gauge's history.csv column reduced as it is written, so a
// peak between two rows is missed exactly as the column misses it. The readings are the gauges'
// (already the same on every rank), so every rank keeps the same extrema; a checkpoint carries
// them (the rows before a restart are not read back).
#pragma once

#include <string>
#include <vector>

#include "models/core/input.hpp"

namespace impact::mpm {

class GaugeExtrema {
 public:
  /// `units`: per gauge, the unit of its history.csv column ("m/s", "-", "Pa").
  explicit GaugeExtrema(std::vector<std::string> units);

  /// One history row: the gauges' readings (Gauges::read order) at `time` [s]. A NaN reading (a
  /// gauge whose particles have all left the grid) is skipped.
  void sample(const std::vector<double>& readings, double time);

  /// Gauge g's {"max [U]", "min [U]", "peak [U]", "peak_time [s]"}: the largest and smallest
  /// reading, the signed reading of largest magnitude (ties: the first) and its time; null each
  /// while the gauge has no finite reading.
  Json json(std::size_t g) const;
  std::size_t size() const { return units_.size(); }

  /// For a checkpoint: per gauge max, min, peak, peak time, finite readings so far.
  std::vector<double> state() const;
  /// Throws std::invalid_argument when the size does not match this scene's gauges.
  void restore(const std::vector<double>& state);

 private:
  struct Extrema {
    double max = 0.0, min = 0.0, peak = 0.0, peak_time = 0.0;
    double samples = 0.0;  ///< finite readings so far (a double: the checkpoint's array)
  };
  static constexpr std::size_t kStateSize = 5;
  std::vector<std::string> units_;
  std::vector<Extrema> extrema_;
};

}  // namespace impact::mpm
