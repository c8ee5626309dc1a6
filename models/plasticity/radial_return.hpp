// von Mises yield (report eq. 6) with a consistent radial return for a rate-dependent flow stress.
//
// Trial deviator s_tr with equivalent stress q_tr = sqrt(3/2 s_tr:s_tr). Elastic if
// q_tr <= sigma_y(ep_n, 0). Otherwise the plastic strain increment d solves (Simo & Hughes 1998,
// Computational Inelasticity, sec. 3.3, with the rate of the step d/dt as the plastic strain rate):
//   g(d) = q_tr - 3 mu d - sigma_y(ep_n + d, d / dt) = 0,
// and s_{n+1} = s_tr (1 - 3 mu d / q_tr). g is monotone decreasing with g(0) > 0, so the root is
// unique.
//
// Solver (docs/theory.md sec. 4). Newton's method on g in u = ln d, started from an upper bound of
// the root: the smaller of the elastic bound overshoot / 3 mu (all of the overshoot taken by the
// elastic unloading) and the flow law's own bound (the increment its hardening, or its rate
// sensitivity, alone would need to absorb the overshoot: johnson_cook_increment_bound). For the
// usual laws g is concave in u (each hardening, rate and elastic term is convex in u: a power of d
// is an exponential of u, a logarithm of d is linear in u), so Newton's iterates from the right
// decrease monotonically to the root without overshooting, and a power law d^n is followed as
// well for n = 0.02 as for n = 1. The start and the variable are what make it converge in a few
// steps: Newton in d from the elastic bound, at zero plastic strain with a low exponent n, lies far
// to the right of a root whose slope is infinite at d = 0, and needed more than 60 steps. A step
// that leaves the bracket [lo, hi] falls back to a geometric bisection. A flow stress that jumps
// (the report's JC rate form at rate* = 1) has no root: the bracket then closes on the jump and
// the point sits on the set-valued yield surface there, q_{n+1} = q_tr - 3 mu d between the
// one-sided flow stresses, which is returned as the flow stress. A root below the smallest double
// (a tiny overshoot with a low n at ep = 0) is an increment of zero to double precision: the trial
// stress is on the yield surface of ep + d and is returned unchanged. A result that met neither
// test is reported as not converged, never silently accepted.
//
// The report's 2004 code (docs/report_code.md sec. 3) instead took d = sqrt(2/3 eta:eta) dt,
// treating all deviatoric strain rate eta as plastic, and rescaled s_tr onto sigma_y(ep_n + d,
// d/dt) in one shot: ReturnAlgorithm::report_2004 reproduces it for comparison.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>

#include "models/core/tensor.hpp"
#include "models/flow_stress/johnson_cook.hpp"

namespace impact {

enum class ReturnAlgorithm { newton, report_2004 };

struct ReturnTolerance {
  double relative_residual = 1e-12;  ///< |g| <= this * q_tr
  int max_iterations = 60;
};

struct ReturnResult {
  Mat3 deviator = Mat3::Zero();       ///< s_{n+1} [Pa]
  double delta_plastic_strain = 0.0;  ///< d [-]
  /// Flow stress and slopes at (ep_n + d, d/dt); when the bracket closed, value is the point's
  /// q_{n+1} on the set-valued surface (see above).
  FlowStress flow;
  int iterations = 0;
  bool plastic = false;
  bool converged = true;
  bool bracket_closed = false;  ///< converged by the bracket (a jump of sigma_y), not |g|
};

/// A flow law that can bound the increment: flow.increment_bound(ep, overshoot, dt) returns an
/// upper bound of d (johnson_cook_increment_bound), +inf when it knows none.
template <class Flow>
concept BoundedFlow = requires(const Flow& f) {
  { f.increment_bound(0.0, 0.0, 0.0) } -> std::convertible_to<double>;
};

/// `flow(ep, rate)` returns the FlowStress at the step's temperature (a BoundedFlow also bounds the
/// increment). `deviatoric_rate_norm` is sqrt(2/3 eta:eta), used only by
/// ReturnAlgorithm::report_2004. `guess` is a first estimate of the increment d (e.g. the previous
/// step's plastic rate times dt), used when it lies inside the bracket; it changes the iteration
/// count, not the root.
template <class Flow>
ReturnResult radial_return(const Mat3& s_trial, double shear_modulus, double plastic_strain,
                           double dt, const Flow& flow, ReturnAlgorithm algorithm,
                           double deviatoric_rate_norm = 0.0, const ReturnTolerance& tol = {},
                           double guess = 0.0) {
  ReturnResult out;
  const double q_trial = std::sqrt(1.5 * ddot(s_trial, s_trial));
  const FlowStress static_flow = flow(plastic_strain, 0.0);
  if (q_trial <= static_flow.value) {
    out.deviator = s_trial;
    out.flow = static_flow;
    return out;
  }
  out.plastic = true;

  if (algorithm == ReturnAlgorithm::report_2004) {
    const double d = deviatoric_rate_norm * dt;
    out.flow = flow(plastic_strain + d, deviatoric_rate_norm);
    out.delta_plastic_strain = d;
    out.deviator = s_trial * (out.flow.value / q_trial);
    out.iterations = 1;
    return out;
  }

  const double three_mu = 3.0 * shear_modulus;
  const double overshoot = q_trial - static_flow.value;
  double lo = 0.0;                   // g(lo) > 0
  double hi = overshoot / three_mu;  // g(hi) <= 0: the elastic bound
  if constexpr (BoundedFlow<Flow>)
    hi = std::min(hi, flow.increment_bound(plastic_strain, overshoot, dt));
  if (!(hi > 0.0)) {
    // The root lies below the smallest double: d = 0 to double precision, and the trial stress is
    // on the yield surface of ep_n + d.
    out.deviator = s_trial;
    out.flow = static_flow;
    out.flow.value = q_trial;
    out.iterations = 1;
    return out;
  }
  double d = (guess > 0.0 && guess < hi) ? guess : hi;
  bool from_guess = d < hi;  // the iteration started at a guess: hi not evaluated yet
  FlowStress f;
  out.converged = false;
  for (int it = 1; it <= tol.max_iterations; ++it) {
    f = flow(plastic_strain + d, d / dt);
    const double g = q_trial - three_mu * d - f.value;
    out.iterations = it;
    if (std::abs(g) <= tol.relative_residual * q_trial) {
      out.converged = true;
      break;
    }
    if (g > 0.0) {
      lo = d;
    } else {
      hi = d;
      from_guess = false;
    }
    if (hi - lo <= 1e-15 * hi) {  // the bracket closed without a root: a jump of sigma_y
      out.converged = true;
      out.bracket_closed = true;
      f.value = q_trial - three_mu * d;
      break;
    }
    // Newton in u = ln d: du = -g / (d dg/dd), dg/dd = -(3 mu + dsigma/dep + dsigma/drate / dt).
    const double slope = three_mu + f.d_plastic_strain + f.d_rate / dt;
    double next = d * std::exp(g / (slope * d));
    // Outside the bracket (also NaN): the upper bound if a guess below the root started the
    // iteration (from there Newton is monotone), else a geometric bisection.
    if (!(next > lo && next < hi)) {
      next = from_guess ? hi : (lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * hi);
      from_guess = false;
    }
    d = next;
  }
  out.delta_plastic_strain = d;
  out.flow = f;
  out.deviator = s_trial * (1.0 - three_mu * d / q_trial);
  return out;
}

}  // namespace impact
