// von Mises yield (report eq. 6) with a consistent radial return for a rate-dependent flow stress.
//
// Trial deviator s_tr with equivalent stress q_tr = sqrt(3/2 s_tr:s_tr). Elastic if
// q_tr <= sigma_y(ep_n, 0). Otherwise the plastic strain increment d solves (Simo & Hughes 1998,
// Computational Inelasticity, sec. 3.3, with the rate of the step d/dt as the plastic strain rate):
//   g(d) = q_tr - 3 mu d - sigma_y(ep_n + d, d / dt) = 0,
// and s_{n+1} = s_tr (1 - 3 mu d / q_tr). For a continuous flow stress g decreases from g(0) > 0
// and the root is unique. The report's 2004 Johnson-Cook rate form is not continuous: its factor
// drops from 2^C to 1 at rate* = 1, i.e. at d_j = reference_rate dt, where g jumps UP, and g can
// then have two roots (6061-T6 at ep 0.1, dt 1e-8: rate* 0.418 and 1.417). The return takes the
// smallest root, the first increment, growing from 0, at which the stress is back on the yield
// surface, whatever the guess: a law that knows where it jumps (JumpingFlow) reports d_j, g is
// evaluated just left of it, and the bracket is (0, d_j) if g <= 0 there (to the tolerance), else
// (d_j, h]. Inside either, g is continuous and decreasing, so its root is unique and a guess
// outside it is ignored. The sides are taken 8 eps away from d_j so that the law's own rounding of
// rate* = d / dt / reference_rate puts every iterate on the side the bracket is on.
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
// that leaves the bracket [lo, hi] falls back to a geometric bisection. A root below the smallest
// double (a tiny overshoot with a low n at ep = 0) is an increment of zero to double precision: the
// trial stress is on the yield surface of ep + d and is returned unchanged. A subnormal root
// (one step of d moves g by more than the tolerance) is taken once the iterations have closed the
// bracket to adjacent doubles. A result that met none of these tests (nor the stopping bound
// below) is reported as not converged, never silently accepted. (A bracket cannot close without a
// root: g(lo) > 0 >= g(hi) and g only jumps up, so a zero crossing lies between.)
//
// Stopping. An evaluated iterate with |g| <= tol q_tr is the root. A law that bounds the
// curvature of g in u (CurvatureBoundedFlow: |g''(u)| <= K |g'(u)| between the increments where it
// is not smooth; Johnson-Cook: K = max(1, n) + 2 C) also lets the return accept a Newton step
// without evaluating the law at its end: |g'| then varies by at most e^(K |s|) over a distance s,
// so the step x from u, with g(u) + g'(u) x = 0, ends at |g(u + x)| = |int_0^x (g'(u + s) -
// g'(u)) ds| <= |g'(u)| (e^y - 1 - y) / K = |g(u)| (e^y - 1 - y) / y <= |g(u)| y (1 + y) / 2, y =
// K |x| <= 1. The step is accepted when that is at most tol q_tr / 2 (the other half covers the
// rounding of g and of the step, a few eps q_tr), when it stays inside the bracket and on one side
// of every break, and when y <= 1e-6 (the slopes reported are the iterate's, within about 1e-6 of
// the accepted increment's; the flow stress reported is the surface's radius q_tr - 3 mu d, within
// tol q_tr / 2 of the law's). Under steady loading the previous increment is within e0 ~ 1e-4 of
// the root, Newton's first step within K e0^2 / 2 ~ 1e-8, and its second is accepted: two
// evaluations of the law instead of three, the third of which only confirmed the second. The
// accepted increment is the one the third evaluation would have confirmed, bit for bit.
//
// The report's 2004 code (docs/report_code.md sec. 3) instead took d = sqrt(2/3 eta:eta) dt,
// treating all deviatoric strain rate eta as plastic, and rescaled s_tr onto sigma_y(ep_n + d,
// d/dt) in one shot: ReturnAlgorithm::report_2004 reproduces it for comparison.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>

#include "models/core/lane_mat3.hpp"
#include "models/core/lane_math.hpp"
#include "models/core/tensor.hpp"
#include "models/flow_stress/johnson_cook.hpp"

// Vectors pass between always-inlined templates only (models/core/lane_math.hpp).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

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

/// A flow law that can bound the increment: flow.increment_bound(ep, overshoot, dt) returns an
/// upper bound of d (johnson_cook_increment_bound), +inf when it knows none.
template <class Flow>
concept BoundedFlow = requires(const Flow& f) {
  { f.increment_bound(0.0, 0.0, 0.0) } -> std::convertible_to<double>;
};

/// A flow law whose sigma_y(ep + d, d/dt) drops at one increment: flow.jump_increment(dt) returns
/// it (the 2004 Johnson-Cook rate form: reference_rate dt), +inf when the law is continuous.
template <class Flow, class V>
concept JumpingFlow = requires(const Flow& f, V dt) {
  { f.jump_increment(dt) } -> std::convertible_to<V>;
};

/// A flow law that bounds the curvature of the return's residual in u = ln d: between the
/// increments flow.break_increment(dt) where the law is not smooth (+inf: none), |g''(u)| <=
/// K |g'(u)| with K = flow.log_curvature_bound() (johnson_cook_log_curvature_bound). The return
/// may then accept a Newton step without evaluating the law at its end (header comment).
template <class Flow, class V>
concept CurvatureBoundedFlow = requires(const Flow& f, V dt) {
  { f.break_increment(dt) } -> std::convertible_to<V>;
  { f.log_curvature_bound() } -> std::convertible_to<double>;
};

/// How far from a jump the bracket's ends are taken, relative to it: more than the rounding of
/// rate* = d / dt / reference_rate (3 operations of 1/2 eps each).
inline constexpr double kJumpMargin = 8.0 * std::numeric_limits<double>::epsilon();
/// The spacing of doubles: at most kEpsilon x, and kSmallestStep below kSmallestNormal.
inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
inline constexpr double kSmallestStep = std::numeric_limits<double>::denorm_min();
inline constexpr double kSmallestNormal = std::numeric_limits<double>::min();

/// The inputs and outputs of the return for one point (V = double) or a vector of points (V =
/// lane::Vec, one per lane): fill the inputs, call return_values, read the outputs. A lane with
/// q_trial = 0 is elastic and costs nothing but its share of the vector instructions. Flags are
/// nonzero where set.
template <class V>
struct alignas(lane::kLaneBytes) ReturnValues {
  using Int = lane::IntOf<V>;
  // Inputs.
  V q_trial{};         ///< sqrt(3/2 s_tr:s_tr) [Pa]
  V three_mu{};        ///< 3 mu [Pa]
  V plastic_strain{};  ///< ep_n [-]
  V dt{};              ///< [s]
  V guess{};           ///< first estimate of d (0: none)
  // Outputs.
  V increment{};            ///< d [-]
  BasicFlowStress<V> flow;  ///< as ReturnResult::flow
  Int iterations{};
  Int plastic{};
  Int converged{};
};

/// The radial return of the header comment, one algorithm for one point or a vector of them:
/// each lane iterates until its own test is met, lanes that are done keep their values while the
/// others go on, and a lane's arithmetic is the same whatever the others do (selects, no branch
/// on a lane's value), so a point gets the same bits alone or in a vector.
/// `flow(ep, rate)` returns the lanes' BasicFlowStress<V>; `bound(ep, overshoot, dt)` an upper
/// bound of their increments (+inf when none is known).
template <class V, class Flow, class Bound>
[[gnu::always_inline]] inline void return_values(ReturnValues<V>& b, const Flow& flow,
                                                 const Bound& bound, const ReturnTolerance& tol) {
  using lane::select;
  using Int = lane::IntOf<V>;
  const V q = b.q_trial;
  const BasicFlowStress<V> f0 = flow(b.plastic_strain, lane::splat<V>(0.0));
  const auto plastic = q > f0.value;
  b.plastic = lane::flag<V>(plastic);
  b.converged = Int{} + 1;  // set: elastic lanes are done
  b.iterations = Int{};
  b.increment = lane::splat<V>(0.0);
  b.flow = f0;
  if (!lane::any(plastic)) return;  // all elastic: the common case, without the bound's cost

  const V overshoot = q - f0.value;
  const V elastic_bound = overshoot / b.three_mu;
  const V flow_bound = bound(b.plastic_strain, select<V>(plastic, overshoot, 0.0), b.dt);
  const V h = select<V>(flow_bound < elastic_bound, flow_bound, elastic_bound);
  // h <= 0: the root lies below the smallest double, d = 0 to double precision, and the trial
  // stress is on the yield surface of ep_n + d.
  const auto below_smallest = plastic & !(h > 0.0);
  auto active = plastic & !below_smallest;
  V lo = lane::splat<V>(0.0);  // g(lo) > 0
  V hi = h;                    // g(hi) <= 0
  if constexpr (JumpingFlow<Flow, V>) {
    // The smallest root (header comment): g just left of the jump says on which side it lies.
    const V jump = flow.jump_increment(b.dt);
    const V left = jump * (1.0 - kJumpMargin), right = jump * (1.0 + kJumpMargin);
    const auto inside = active & (left < h);
    if (lane::any(inside)) {
      const V at = select<V>(inside, left, h);  // harmless where the jump is outside
      const V g_left = q - b.three_mu * at - flow(V(b.plastic_strain + at), V(at / b.dt)).value;
      const auto on_left = g_left <= tol.relative_residual * q;
      hi = select<V>(inside & on_left, left, hi);
      // Right of the jump; if h lies within the margin, the root is at h to the tolerance.
      lo = select<V>(inside & !on_left, select<V>(right < h, right, left), lo);
    }
  }
  const V g0 = b.guess;
  V d = select<V>(active, select<V>((g0 > lo) & (g0 < hi), g0, hi), 0.0);
  auto from_guess = d < hi;  // the iteration started at a guess: hi not evaluated yet
  b.converged = lane::flag<V>(!active);
  b.iterations = lane::flag<V>(below_smallest) & 1;
  b.flow.value = select<V>(below_smallest, q, b.flow.value);

  // A Newton step is accepted unevaluated only between the law's breaks (with the jump's margin,
  // so that the law's rounding of rate* puts both ends on one side).
  V smooth_below = lane::splat<V>(0.0), smooth_above = lane::splat<V>(0.0), curvature{};
  if constexpr (CurvatureBoundedFlow<Flow, V>) {
    const V at = flow.break_increment(b.dt);
    smooth_below = at * (1.0 - kJumpMargin);
    smooth_above = at * (1.0 + kJumpMargin);
    curvature = lane::splat<V>(flow.log_curvature_bound());
  }

  for (int it = 1; it <= tol.max_iterations && lane::any(active); ++it) {
    const BasicFlowStress<V> f = flow(V(b.plastic_strain + d), V(d / b.dt));
    const V g = q - b.three_mu * d - f.value;
    const auto root = lane::abs(g) <= tol.relative_residual * q;
    const auto up = g > 0.0;
    const V lo1 = select<V>(up, d, lo);
    const V hi1 = select<V>(up, hi, d);
    const auto guess1 = up & from_guess;
    // Newton in u = ln d: du = -g / (d dg/dd), dg/dd = -(3 mu + dsigma/dep + dsigma/drate / dt).
    const V slope = b.three_mu + f.d_plastic_strain + f.d_rate / b.dt;
    const V step = g / (slope * d);
    const V newton = d * lane::exp(step);
    // Outside the bracket (also NaN): the upper bound if a guess below the root started the
    // iteration (from there Newton is monotone), else a geometric bisection.
    const auto outside = !((newton > lo1) & (newton < hi1));
    // sqrt(lo hi) as sqrt(lo) sqrt(hi) where the product underflows (a bracket among the
    // subnormals would otherwise bisect to 0 and never close); the same bits elsewhere.
    const V product = lo1 * hi1;
    const V geometric = select<V>(product >= kSmallestNormal, lane::sqrt(product),
                                  V(lane::sqrt(lo1) * lane::sqrt(hi1)));
    const V bisection = select<V>(lo1 > 0.0, geometric, 0.5 * hi1);
    const V next = select<V>(outside, select<V>(guess1, hi1, bisection), newton);
    b.iterations = select(active, Int{} + it, b.iterations);
    b.flow.value = select<V>(active, f.value, b.flow.value);
    b.flow.d_plastic_strain = select<V>(active, f.d_plastic_strain, b.flow.d_plastic_strain);
    b.flow.d_rate = select<V>(active, f.d_rate, b.flow.d_rate);
    b.flow.d_temperature = select<V>(active, f.d_temperature, b.flow.d_temperature);
    b.converged |= lane::flag<V>(active & root);
    auto go_on = active & !root;
    if constexpr (CurvatureBoundedFlow<Flow, V>) {
      // Accept the step's end unevaluated (header comment): with y = K |step|, its residual is at
      // most |g| (e^y - 1 - y) / y <= |g| y (1 + y) / 2, here within half the tolerance (the other
      // half covers the rounding of g and of the step, a few eps q_tr). y <= 1e-6 keeps the
      // slopes, those of this iterate, within about 1e-6 of the accepted increment's; its flow
      // stress is the surface's radius q_tr - 3 mu d.
      const V y = curvature * lane::abs(step);
      const auto smooth = ((d < smooth_below) & (newton < smooth_below)) |
                          ((d > smooth_above) & (newton > smooth_above));
      const auto accept = go_on & !outside & smooth & (y <= 1e-6) &
                          (lane::abs(g) * y * (1.0 + y) <= tol.relative_residual * q);
      b.converged |= lane::flag<V>(accept);
      b.flow.value = select<V>(accept, q - b.three_mu * newton, b.flow.value);
      d = select<V>(accept, newton, d);
      go_on = go_on & !accept;
    }
    lo = select<V>(go_on, lo1, lo);
    hi = select<V>(go_on, hi1, hi);
    from_guess = go_on ? (guess1 & !outside) : from_guess;
    d = select<V>(go_on, next, d);
    active = go_on;
  }
  // A subnormal root (ep_n = 0 with a low exponent: sigma_y rises as d^n, and one step of a
  // subnormal d, 5e-324, moves g by more than the tolerance, e.g. 39-80 Pa above A with n =
  // 0.02) cannot meet the residual test: the iterations end with the bracket closed to adjacent
  // doubles. The root is then known to double precision (the upper end is taken, g <= 0 there);
  // only lanes that would otherwise end not converged take this.
  const V spacing = select<V>(lo * kEpsilon > kSmallestStep, lo * kEpsilon, kSmallestStep);
  const auto closed = active & !(hi - lo > spacing);
  b.converged |= lane::flag<V>(closed);
  d = select<V>(closed, hi, d);
  b.increment = select<V>(plastic, d, 0.0);
}

/// A point's outcome (lane k of a vector) as a ReturnResult, with s_{n+1} = s_tr (1 - 3 mu d /
/// q_tr).
template <class V>
ReturnResult finish_return(const Mat3& s_trial, const ReturnValues<V>& b, int k) {
  using lane::get;
  ReturnResult out;
  out.plastic = get(b.plastic, k) != 0;
  out.converged = get(b.converged, k) != 0;
  out.iterations = static_cast<int>(get(b.iterations, k));
  out.delta_plastic_strain = get(b.increment, k);
  out.flow = FlowStress{get(b.flow.value, k), get(b.flow.d_plastic_strain, k),
                        get(b.flow.d_rate, k), get(b.flow.d_temperature, k)};
  const bool scaled = out.plastic && out.delta_plastic_strain > 0.0;
  out.deviator = scaled ? Mat3(s_trial * (1.0 - get(b.three_mu, k) * out.delta_plastic_strain /
                                                    get(b.q_trial, k)))
                        : s_trial;
  return out;
}

/// `flow(ep, rate)` returns the FlowStress at the step's temperature (a BoundedFlow also bounds the
/// increment). `deviatoric_rate_norm` is sqrt(2/3 eta:eta), used only by
/// ReturnAlgorithm::report_2004. `guess` is a first estimate of the increment d (e.g. the previous
/// step's plastic rate times dt), used when it lies inside the bracket; it changes the iteration
/// count, not the root. Newton's return is return_values on one point.
template <class Flow>
ReturnResult radial_return(const Mat3& s_trial, double shear_modulus, double plastic_strain,
                           double dt, const Flow& flow, ReturnAlgorithm algorithm,
                           double deviatoric_rate_norm = 0.0, const ReturnTolerance& tol = {},
                           double guess = 0.0) {
  ReturnResult out;
  // The batched update's expression (elastic_plastic_lanes.hpp): the same bits.
  const double q_trial = lane_algebra::equivalent_of_deviator(to_lanes(s_trial));
  if (algorithm == ReturnAlgorithm::report_2004) {
    const FlowStress static_flow = flow(plastic_strain, 0.0);
    if (q_trial <= static_flow.value) {
      out.deviator = s_trial;
      out.flow = static_flow;
      return out;
    }
    out.plastic = true;
    const double d = deviatoric_rate_norm * dt;
    out.flow = flow(plastic_strain + d, deviatoric_rate_norm);
    out.delta_plastic_strain = d;
    out.deviator = s_trial * (out.flow.value / q_trial);
    out.iterations = 1;
    return out;
  }
  ReturnValues<double> b;
  b.q_trial = q_trial;
  b.three_mu = 3.0 * shear_modulus;
  b.plastic_strain = plastic_strain;
  b.dt = dt;
  b.guess = guess;
  const auto bound = [&](double ep, double overshoot, double step) {
    if constexpr (BoundedFlow<Flow>)
      return flow.increment_bound(ep, overshoot, step);
    else
      return std::numeric_limits<double>::infinity();
  };
  return_values(b, flow, bound, tol);
  return finish_return(s_trial, b, 0);
}

}  // namespace impact

#pragma GCC diagnostic pop
