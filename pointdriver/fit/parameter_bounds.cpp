#include "pointdriver/fit/parameter_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "pointdriver/format/text_format.hpp"

namespace impact::pointdriver::fit {

std::string to_string(BoundSide side) {
  return side == BoundSide::lower ? "lower" : side == BoundSide::upper ? "upper" : "";
}

double bound_tolerance(const Parameter& p, double bound) {
  const double width = p.upper - p.lower;
  const double scale = bound != 0.0 ? std::min(std::abs(bound), width) : width;
  return 1e-3 * scale;
}

BoundSide at_bound(const Parameter& p, double value) {
  if (value <= p.lower + bound_tolerance(p, p.lower)) return BoundSide::lower;
  if (value >= p.upper - bound_tolerance(p, p.upper)) return BoundSide::upper;
  return BoundSide::none;
}

std::optional<double> move_inside_bounds(const Parameter& p, double value) {
  // NaN (a failed staged stage) is neither inside nor on a bound: the middle is the honest start.
  if (std::isnan(value)) return 0.5 * (p.lower + p.upper);
  switch (at_bound(p, value)) {
    case BoundSide::lower:
      return p.lower + 10.0 * bound_tolerance(p, p.lower);
    case BoundSide::upper:
      return p.upper - 10.0 * bound_tolerance(p, p.upper);
    case BoundSide::none:
      break;
  }
  return std::nullopt;
}

std::string at_bound_message(const Parameter& p, BoundSide side, double fitted,
                             const std::string& unit) {
  const double bound = side == BoundSide::lower ? p.lower : p.upper;
  const std::string u = unit == "-" ? "" : " " + unit;
  return p.name + " ended on its " + to_string(side) + " bound " + format_number(bound) + u +
         " (fitted " + format_number(fitted) + u +
         "): the bound stopped it, not the data; its standard error and correlations are not "
         "meaningful. Fix it (\"free\": false with a \"start\") or revise the bound "
         "(docs/fitting.md)";
}

}  // namespace impact::pointdriver::fit
