// von Mises yield (report eq. 6) with a consistent radial return for a rate-dependent flow stress.
//
// Trial deviator s_tr with equivalent stress q_tr = sqrt(3/2 s_tr:s_tr). Elastic if
// q_tr <= sigma_y(ep_n, 0). Otherwise the plastic strain increment d solves (Simo & Hughes 1998,
// Computational Inelasticity, sec. 3.3, with the rate of the step d/dt as the plastic strain rate):
//   g(d) = q_tr - 3 mu d - sigma_y(ep_n + d, d / dt) = 0,
// and s_{n+1} = s_tr (1 - 3 mu d / q_tr). g is monotone decreasing with g(0) > 0 >= g(q_tr/(3 mu)),
// so the root is unique and bracketed: Newton steps that leave the bracket are replaced by
// bisection, and a result that has not met the tolerance is reported as not converged, never
// silently accepted.
//
// The report's 2004 code (reference_code_notes.md sec. 3) instead took d = sqrt(2/3 eta:eta) dt,
// treating all deviatoric strain rate eta as plastic, and rescaled s_tr onto sigma_y(ep_n + d,
// d/dt) in one shot: ReturnAlgorithm::report_2004 reproduces it for comparison.
#pragma once

#include <cmath>

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
  FlowStress flow;                    ///< flow stress and slopes at (ep_n + d, d/dt)
  int iterations = 0;
  bool plastic = false;
  bool converged = true;
};

/// `flow(ep, rate)` returns the FlowStress at the step's temperature. `deviatoric_rate_norm` is
/// sqrt(2/3 eta:eta), used only by ReturnAlgorithm::report_2004. `guess` is a first estimate of
/// the increment d (e.g. the previous step's plastic rate times dt); 0 or a value outside the
/// bracket selects the perfectly plastic estimate. It changes the iteration count, not the root.
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
  const auto residual = [&](double d, FlowStress& f) {
    f = flow(plastic_strain + d, d / dt);
    return q_trial - three_mu * d - f.value;
  };
  double lo = 0.0;                 // g(lo) > 0
  double hi = q_trial / three_mu;  // g(hi) <= 0
  // Perfectly plastic estimate: an upper bound, close to the root when hardening is small.
  double d = (q_trial - static_flow.value) / three_mu;
  if (guess > 0.0 && guess < d) d = guess;
  FlowStress f;
  out.converged = false;
  for (int it = 1; it <= tol.max_iterations; ++it) {
    const double g = residual(d, f);
    out.iterations = it;
    if (std::abs(g) <= tol.relative_residual * q_trial) {
      out.converged = true;
      break;
    }
    if (g > 0.0)
      lo = d;
    else
      hi = d;
    const double slope = -three_mu - f.d_plastic_strain - f.d_rate / dt;
    double next = d - g / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // also catches NaN
    if (hi - lo <= 1e-15 * hi) {  // bracket at round-off: the root is located
      d = next;
      residual(d, f);
      out.converged = true;
      break;
    }
    d = next;
  }
  out.delta_plastic_strain = d;
  out.flow = f;
  out.deviator = s_trial * (1.0 - three_mu * d / q_trial);
  return out;
}

}  // namespace impact
