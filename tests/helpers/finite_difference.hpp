// Central-difference helpers shared by the tests: every analytic derivative in the library is
// checked against one of these (NEML2's practice), so a new sub-model needs one line.
#pragma once

#include <cmath>
#include <functional>

namespace impact::testing {

/// d f / d x at x by the central difference with a step relative to |x| (absolute near zero).
inline double central_difference(const std::function<double(double)>& f, double x,
                                 double relative_step = 1e-6) {
  const double h = relative_step * std::max(std::abs(x), 1e-3);
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

/// Relative difference |a - b| / max(|a|, |b|, floor).
inline double relative_difference(double a, double b, double floor = 1e-300) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), floor});
}

}  // namespace impact::testing
