// Stable time step (docs/report_code.md sec. 16): dt = multiplier * min_d dx_d (the mesh axes: x
// and y on a 2D grid) / max_p (c_p + |v_p|), c_p the longitudinal wave speed of the particle's
// current state; and the body-force step, sqrt(multiplier dx / abs(g)), where gravity alone
// would outrun it (a particle released at rest under 1e12 m/s^2 crossed a wall in its first step).
#include <cmath>
#include <limits>

#include "mpm/step/step.hpp"

namespace impact::mpm {

double stable_time_step(double min_spacing, double max_signal_speed, double multiplier) {
  if (!(max_signal_speed > 0.0)) return std::numeric_limits<double>::infinity();
  return multiplier * min_spacing / max_signal_speed;
}

double body_force_time_step(double min_spacing, double gravity, double multiplier) {
  if (!(gravity > 0.0)) return std::numeric_limits<double>::infinity();
  return std::sqrt(multiplier * min_spacing / gravity);
}

double max_signal_speed(const Particles& P) {
  double s = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) s = std::max(s, P.wave_speed[p] + P.v[p].norm());
  return s;
}

}  // namespace impact::mpm
