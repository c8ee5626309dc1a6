// When the next history row and snapshot are due: the first time of the `output.interval` lattice
// after the step's time t. The interval is added once per row while few rows are due, as it always
// was (the same sums, so the same rows); when many are, the lattice is jumped to. A tiny interval
// had the adding run once per skipped row: 1e-18 s over a 4e-8 s step was 4e10 additions, a
// step took 150 s and SIGTERM waited for it (scenes.md#output: an interval below the step gives
// a row every step). An interval below the rounding of t leaves next at or before t: a row every
// step, with no endless loop.
#pragma once

#include <cmath>

namespace impact::mpm {

inline double next_output_after(double next, double t, double interval) {
  const double due = t * (1.0 + 1e-12);  // within round-off of a row's time: that row is done
  const double behind = (due - next) / interval;
  if (behind > 1024.0) next += std::floor(behind) * interval;
  for (int k = 0; next <= due && k < 2048; ++k) next += interval;
  return next;
}

}  // namespace impact::mpm
