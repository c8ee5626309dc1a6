#include "models/plasticity/johnson_cook_return_batch.hpp"

// Vectors are passed between the always-inlined templates only (see lane_math.hpp).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace impact {

namespace {

// The law with its rate form fixed, on one point or a vector; theta and its slope per lane.
// Structs with inlined calls, not lambdas: every call must be inlined into the instruction set's
// copy of the kernel, since a vector argument cannot cross into code compiled for another.
template <JohnsonCookRateForm Form, class V>
struct LawAt {
  const JohnsonCookParams& p;
  V theta, d_theta;
  [[gnu::always_inline]] BasicFlowStress<V> operator()(V ep, V rate) const {
    return johnson_cook_form<Form>(p, ep, rate, theta, d_theta);
  }
  [[gnu::always_inline]] V jump_increment(V dt) const {
    return johnson_cook_jump_increment<V>(p, dt);
  }
  [[gnu::always_inline]] V break_increment(V dt) const {
    return johnson_cook_break_increment<V>(p, dt);
  }
  [[gnu::always_inline]] double log_curvature_bound() const {
    return johnson_cook_log_curvature_bound(p);
  }
};
template <JohnsonCookRateForm Form, class V>
struct BoundAt {
  const JohnsonCookParams& p;
  V theta;
  [[gnu::always_inline]] V operator()(V ep, V overshoot, V dt) const {
    return johnson_cook_increment_bound_form<Form>(p, theta, ep, overshoot, dt);
  }
};

template <class V>
[[gnu::always_inline]] inline void return_on(const JohnsonCookParams& params,
                                             const ReturnTolerance& tol, ReturnValues<V>& b,
                                             V theta, V d_theta) {
  const JohnsonCookParams p = params;  // a local copy: its fields stay in registers
  constexpr auto report = JohnsonCookRateForm::report_2004;
  constexpr auto clamped = JohnsonCookRateForm::clamped;
  if (p.rate_form == report)
    return_values(b, LawAt<report, V>{p, theta, d_theta}, BoundAt<report, V>{p, theta}, tol);
  else
    return_values(b, LawAt<clamped, V>{p, theta, d_theta}, BoundAt<clamped, V>{p, theta}, tol);
}

}  // namespace

void JohnsonCookReturnBatch::clear(int k) {
  lanes.q_trial[k] = 0.0;
  lanes.three_mu[k] = 1.0;
  lanes.plastic_strain[k] = 0.0;
  lanes.dt[k] = 1.0;
  lanes.guess[k] = 0.0;
  thermal_factor[k] = 1.0;
  thermal_d_factor[k] = 0.0;
}

IMPACT_LANE_CLONES void johnson_cook_return_batch(const JohnsonCookParams& p,
                                                  const ReturnTolerance& tol,
                                                  JohnsonCookReturnBatch& batch) {
  return_on(p, tol, batch.lanes, batch.thermal_factor, batch.thermal_d_factor);
}

}  // namespace impact
