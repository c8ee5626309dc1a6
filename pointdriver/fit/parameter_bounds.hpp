// The bounds of a fitted parameter: whether a value lies on one, and where a start value on or
// outside them goes. The solver's logistic transform (least_squares.hpp) never reaches a bound
// exactly, so "on" means within a tolerance of it: 1e-3 of the bound's magnitude (a relative
// distance, so that a range spanning decades, such as Cowper-Symonds' D in [1e-2, 1e8] 1/s, is
// judged at its own scale), or of the width upper - lower for a bound at 0.
//
// A fitted parameter on a bound was stopped by the bound, not by the data: the unconstrained
// optimum lies beyond it, and its standard error and correlations describe the bound, not the
// data. The fit reports flag it; a start value on or outside its bounds is moved inside, with a
// warning (move_inside_bounds).
#pragma once

#include <optional>
#include <string>

#include "pointdriver/fit/least_squares.hpp"

namespace impact::pointdriver::fit {

enum class BoundSide { none, lower, upper };

/// "lower", "upper" or "" (none).
std::string to_string(BoundSide side);

/// Distance from `bound` (p.lower or p.upper) within which a value is on it.
double bound_tolerance(const Parameter& p, double bound);

/// The bound `value` lies on or beyond (none when it is inside by more than the tolerance).
BoundSide at_bound(const Parameter& p, double value);

/// A start value on or beyond a bound, moved to 10 tolerances inside it; nothing when `value`
/// is already inside (it is then used as given, however close to the middle or a bound).
std::optional<double> move_inside_bounds(const Parameter& p, double value);

/// "A ended on its lower bound 1e+06 Pa (fitted 1e+06)": the report's and the warning's words.
std::string at_bound_message(const Parameter& p, BoundSide side, double fitted,
                             const std::string& unit);

}  // namespace impact::pointdriver::fit
