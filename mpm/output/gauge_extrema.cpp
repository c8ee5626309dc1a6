#include "mpm/output/gauge_extrema.hpp"

#include <cmath>
#include <stdexcept>

namespace impact::mpm {

GaugeExtrema::GaugeExtrema(std::vector<std::string> units)
    : units_(std::move(units)), extrema_(units_.size()) {}

void GaugeExtrema::sample(const std::vector<double>& readings, double time) {
  if (readings.size() != extrema_.size()) {
    throw std::logic_error("gauge extrema: " + std::to_string(readings.size()) + " readings for " +
                           std::to_string(extrema_.size()) + " gauges");
  }
  for (std::size_t g = 0; g < readings.size(); ++g) {
    const double r = readings[g];
    if (std::isnan(r)) continue;
    Extrema& e = extrema_[g];
    if (e.samples == 0.0) {
      e = {r, r, r, time, 1.0};
      continue;
    }
    e.max = std::max(e.max, r);
    e.min = std::min(e.min, r);
    if (std::abs(r) > std::abs(e.peak)) {  // strictly larger: a tie keeps the first
      e.peak = r;
      e.peak_time = time;
    }
    e.samples += 1.0;
  }
}

Json GaugeExtrema::json(std::size_t g) const {
  const Extrema& e = extrema_.at(g);
  const std::string u = " [" + units_[g] + "]";
  const bool any = e.samples > 0.0;
  const auto value = [&](double v) { return any ? Json(v) : Json(nullptr); };
  return {{"max" + u, value(e.max)},
          {"min" + u, value(e.min)},
          {"peak" + u, value(e.peak)},
          {"peak_time [s]", value(e.peak_time)}};
}

std::vector<double> GaugeExtrema::state() const {
  std::vector<double> s;
  s.reserve(kStateSize * extrema_.size());
  for (const Extrema& e : extrema_)
    s.insert(s.end(), {e.max, e.min, e.peak, e.peak_time, e.samples});
  return s;
}

void GaugeExtrema::restore(const std::vector<double>& state) {
  if (state.size() != kStateSize * extrema_.size()) {
    throw std::invalid_argument("gauge extrema: " + std::to_string(state.size()) + " values for " +
                                std::to_string(extrema_.size()) + " gauges");
  }
  for (std::size_t g = 0; g < extrema_.size(); ++g) {
    const double* s = &state[kStateSize * g];
    extrema_[g] = {s[0], s[1], s[2], s[3], s[4]};
  }
}

}  // namespace impact::mpm
