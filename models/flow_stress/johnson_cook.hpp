// Johnson-Cook flow stress: Johnson & Cook (1983), Proc. 7th Int. Symp. Ballistics, 541-547;
// report eq. (5):
//   sigma_y = [A + B ep^n] [rate factor] [1 - T*^m],   T* = (T - T_room)/(T_melt - T_room).
// Rate factor (rate* = rate / reference_strain_rate):
//   clamped (default):  1 + C ln(max(rate*, 1))   -- rates below the reference give no softening,
//                       continuous at rate* = 1 (as MFront's and LS-DYNA's JC do);
//   report_2004:        (1 + rate*)^C for rate* < 1, 1 + C ln rate* otherwise (the report's code;
//                       it drops from 2^C to 1 at rate* = 1, by 0.14 % for C = 0.002: the radial
//                       return then takes the smallest root, radial_return.hpp).
// Temperature factor: 1 for T* <= 0 (no hardening below room temperature: JC was fitted above it),
// 0 for T* >= 1 (molten: no deviatoric strength; melting is flagged by thermal/melting).
// T_room and T_melt come from the material (one source of truth), not from this block.
#pragma once

#include <algorithm>
#include <limits>

#include "models/core/input.hpp"
#include "models/core/lane_math.hpp"
#include "models/flow_stress/flow_stress.hpp"

// Vectors pass between always-inlined templates only (models/core/lane_math.hpp).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace impact {

enum class JohnsonCookRateForm { clamped, report_2004 };

struct JohnsonCookParams {
  double A = 0.0;                      ///< yield stress [Pa]
  double B = 0.0;                      ///< hardening modulus [Pa]
  double n = 1.0;                      ///< hardening exponent [-]
  double C = 0.0;                      ///< strain-rate coefficient [-]
  double m = 1.0;                      ///< thermal-softening exponent [-]
  double reference_strain_rate = 1.0;  ///< [1/s]
  double room_temperature = 294.0;     ///< [K]
  double melt_temperature = 925.0;     ///< [K]
  JohnsonCookRateForm rate_form = JohnsonCookRateForm::clamped;

  static constexpr std::string_view kType = "johnson_cook";
  static constexpr LawParameter<JohnsonCookParams> kParameters[] = {
      {"A", "Pa", &JohnsonCookParams::A, {1e6, 5e9}},
      {"B", "Pa", &JohnsonCookParams::B, {0.0, 5e9}},
      {"n", "-", &JohnsonCookParams::n, {0.01, 2.0}},
      {"C", "-", &JohnsonCookParams::C, {0.0, 0.5}},
      {"m", "-", &JohnsonCookParams::m, {0.05, 10.0}},
      {"reference_strain_rate", "1/s", &JohnsonCookParams::reference_strain_rate}};
};

/// The temperature factor 1 - T*^m and its slope d/dT [1/K]. A return mapping at fixed
/// temperature evaluates it once instead of once per Newton step (it holds a pow).
struct JohnsonCookThermal {
  double factor = 1.0;
  double d_factor = 0.0;
};
JohnsonCookThermal johnson_cook_thermal(const JohnsonCookParams& p, double temperature);

/// sigma_y(ep, rate, T) and its derivatives; ep >= 0, rate >= 0 [1/s], T [K].
FlowStress johnson_cook(const JohnsonCookParams& p, double plastic_strain,
                        double plastic_strain_rate, double temperature);

/// The same with the temperature factor evaluated beforehand (johnson_cook_thermal). Inline and
/// branch-free in the points' values, for one point (V = double) or a vector of them (V =
/// lane::Vec, the batched return of models/plasticity/johnson_cook_return_batch.hpp): one source
/// for both. Branches only on the parameters, which every lane shares; the rate form is a template
/// argument.
template <JohnsonCookRateForm Form, class V>
[[gnu::always_inline]] inline BasicFlowStress<V> johnson_cook_form(const JohnsonCookParams& p,
                                                                   V plastic_strain,
                                                                   V plastic_strain_rate,
                                                                   V thermal_factor,
                                                                   V thermal_d_factor) {
  using lane::select;
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Strain hardening A + B ep^n; its slope is unbounded at ep = 0 for n < 1.
  const auto strained = plastic_strain > 0.0;
  const V ep = select<V>(strained, plastic_strain, 1.0);  // 1: a harmless argument, not used
  const V ep_n = lane::pow(ep, p.n);
  const V hardening = select<V>(strained, p.A + p.B * ep_n, p.A);
  const double slope_at_zero = p.B == 0.0 ? 0.0 : (p.n < 1.0 ? inf : (p.n == 1.0 ? p.B : 0.0));
  const V d_hardening = select<V>(strained, p.B * p.n * ep_n / ep, slope_at_zero);

  // Rate factor: 1 + C ln rate* at and above the reference rate, below it 1 (clamped) or
  // (1 + rate*)^C (report_2004).
  const V rate_star = plastic_strain_rate / p.reference_strain_rate;
  const auto above = rate_star >= 1.0;
  V rate_factor = select<V>(above, 1.0 + p.C * lane::log(select<V>(above, rate_star, 1.0)), 1.0);
  V d_rate_factor = select<V>(above, p.C / plastic_strain_rate, 0.0);  // d factor / d rate
  if constexpr (Form == JohnsonCookRateForm::report_2004) {
    const auto below = (!above) & (rate_star > 0.0);
    const V power = lane::pow(V(1.0 + select<V>(below, rate_star, 0.0)), p.C);
    rate_factor = select<V>(below, power, rate_factor);
    d_rate_factor =
        select<V>(below, p.C * power / (1.0 + rate_star) / p.reference_strain_rate, d_rate_factor);
  }

  BasicFlowStress<V> f;
  f.value = hardening * rate_factor * thermal_factor;
  f.d_plastic_strain = select<V>((d_hardening == 0.0) | (rate_factor * thermal_factor == 0.0), 0.0,
                                 d_hardening * rate_factor * thermal_factor);
  f.d_rate = hardening * d_rate_factor * thermal_factor;
  f.d_temperature = hardening * rate_factor * thermal_d_factor;
  return f;
}

inline FlowStress johnson_cook(const JohnsonCookParams& p, double plastic_strain,
                               double plastic_strain_rate, const JohnsonCookThermal& thermal) {
  constexpr auto report = JohnsonCookRateForm::report_2004;
  constexpr auto clamped = JohnsonCookRateForm::clamped;
  return p.rate_form == report ? johnson_cook_form<report>(p, plastic_strain, plastic_strain_rate,
                                                           thermal.factor, thermal.d_factor)
                               : johnson_cook_form<clamped>(p, plastic_strain, plastic_strain_rate,
                                                            thermal.factor, thermal.d_factor);
}

/// An upper bound of the radial return's plastic-strain increment d (models/plasticity/
/// radial_return.hpp) for a trial stress `overshoot` [Pa] above sigma_y(ep, 0, T): the smaller of
/// the increment the strain hardening alone and the one the rate factor alone would need to raise
/// the flow stress by the overshoot. Both are bounds because every factor of the law is >= its
/// static value: sigma_y(ep + d, d/dt) - sigma_y(ep, 0) >= B ((ep + d)^n - ep^n) theta and
/// >= (A + B ep^n) (rate factor - 1) theta. +inf when neither applies (B = 0 and C = 0, or molten);
/// 0 when the hardening bound is below the smallest double. For one point or a vector, like
/// johnson_cook_form.
template <JohnsonCookRateForm Form, class V>
[[gnu::always_inline]] inline V johnson_cook_increment_bound_form(const JohnsonCookParams& p,
                                                                  V thermal_factor,
                                                                  V plastic_strain, V overshoot,
                                                                  V dt) {
  using lane::select;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const auto applies = (thermal_factor > 0.0) & (overshoot > 0.0);
  const V theta = select<V>(applies, thermal_factor, 1.0);  // harmless where it does not apply
  const V over = select<V>(applies, overshoot, 1.0);
  const auto strained = plastic_strain > 0.0;
  const V ep = select<V>(strained, plastic_strain, 1.0);
  const V ep_n = lane::pow(ep, p.n);
  V bound = lane::splat<V>(inf);
  // Hardening: B ((ep + d)^n - ep^n) theta = overshoot, without cancellation for small d:
  // ep > 0: ep expm1(log1p(z / ep^n) / n); ep = 0: exp(log(z) / n), 0 when it underflows. One
  // log and one exponential serve both (a vector evaluates both sides of a select).
  if (p.B > 0.0) {
    const V z = over / (p.B * theta);
    const V x = z / ep_n;
    const V u = select<V>(strained, 1.0 + x, z);
    const V log_u = lane::log(u) + select<V>(strained, (x - (u - 1.0)) / u, 0.0);  // log1p(x)
    const lane::detail::ExpParts<V> e = lane::detail::exp_parts(V(log_u / p.n));
    const V from_strained = ep * ((e.q * e.a) * e.b + (e.a * e.b - 1.0));  // ep expm1
    const V from_zero = ((1.0 + e.q) * e.a) * e.b;                         // exp
    bound = select<V>(strained, from_strained, from_zero);
  }
  // Rate: (A + B ep^n) theta (factor(d / dt) - 1) = overshoot. The clamped factor 1 + C ln rate*
  // reaches 1 + y at rate* = e^(y / C); the 2004 form (1 + rate*)^C >= 1 + C rate* / (1 + rate*)
  // below rate* = 1 reaches 1 + y by rate* = y / (C - y) when y < C / 2 (and the log branch
  // above takes over otherwise).
  if (p.C > 0.0) {
    const V y = over / ((p.A + select<V>(strained, p.B * ep_n, 0.0)) * theta);
    const auto finite = y < 700.0 * p.C;
    V rate_star = select<V>(finite, lane::exp(V(select<V>(finite, y, 0.0) / p.C)), inf);
    if constexpr (Form == JohnsonCookRateForm::report_2004)
      rate_star = select<V>(2.0 * y < p.C, y / (p.C - y), rate_star);
    const V rate_bound = rate_star * p.reference_strain_rate * dt;
    bound = select<V>(rate_bound < bound, rate_bound, bound);
  }
  return select<V>(applies, bound, inf);
}

inline double johnson_cook_increment_bound(const JohnsonCookParams& p,
                                           const JohnsonCookThermal& thermal, double plastic_strain,
                                           double overshoot, double dt) {
  constexpr auto report = JohnsonCookRateForm::report_2004;
  constexpr auto clamped = JohnsonCookRateForm::clamped;
  return p.rate_form == report ? johnson_cook_increment_bound_form<report>(
                                     p, thermal.factor, plastic_strain, overshoot, dt)
                               : johnson_cook_increment_bound_form<clamped>(
                                     p, thermal.factor, plastic_strain, overshoot, dt);
}

/// The plastic-strain increment over dt at which the flow stress drops (rate* = 1 of the 2004 rate
/// form, when C > 0): reference_strain_rate dt; +inf for a continuous law.
template <class V>
[[gnu::always_inline]] inline V johnson_cook_jump_increment(const JohnsonCookParams& p, V dt) {
  const bool jumps = p.rate_form == JohnsonCookRateForm::report_2004 && p.C > 0.0;
  return jumps ? V(p.reference_strain_rate * dt)
               : lane::splat<V>(std::numeric_limits<double>::infinity());
}

/// The increment at which the rate factor is not smooth (rate* = 1: the clamped form's kink, the
/// 2004 form's jump), reference_rate dt, when C > 0; +inf when the factor is smooth everywhere.
template <class V>
[[gnu::always_inline]] inline V johnson_cook_break_increment(const JohnsonCookParams& p, V dt) {
  return p.C > 0.0 ? V(p.reference_strain_rate * dt)
                   : lane::splat<V>(std::numeric_limits<double>::infinity());
}

/// K such that the radial return's residual g(u) = q_tr - 3 mu e^u - sigma_y(ep + e^u, e^u / dt)
/// (u = ln d, models/plasticity/radial_return.hpp) has |g''(u)| <= K |g'(u)| between the rate
/// factor's breaks: max(1, n) + 2 C (docs/theory.md sec. 4). Each factor of the law is positive,
/// increasing and convex in u, with h''/h' = (ep + n d)/(ep + d) <= max(1, n) for the hardening
/// h = A + B (ep + d)^n; the rate factor r has r'' <= r' and r' <= C r (both forms, C <= 1); so
/// sigma'' = theta (h'' r + 2 h' r' + h r'') <= (max(1, n) + 2 C) sigma', and the elastic term
/// 3 mu e^u has ratio 1. +inf (no bound claimed) outside A >= 0, B >= 0, n > 0, 0 <= C <= 1.
inline double johnson_cook_log_curvature_bound(const JohnsonCookParams& p) {
  const bool covered = p.A >= 0.0 && p.B >= 0.0 && p.n > 0.0 && p.C >= 0.0 && p.C <= 1.0;
  return covered ? std::max(1.0, p.n) + 2.0 * p.C : std::numeric_limits<double>::infinity();
}

/// The law at one temperature, as the radial return calls it: flow(ep, rate), the increment's
/// upper bound, its jump, its breaks and its curvature bound (models/plasticity/radial_return.hpp,
/// BoundedFlow, JumpingFlow, CurvatureBoundedFlow).
struct JohnsonCookAtTemperature {
  const JohnsonCookParams& params;
  JohnsonCookThermal thermal;
  FlowStress operator()(double plastic_strain, double plastic_strain_rate) const {
    return johnson_cook(params, plastic_strain, plastic_strain_rate, thermal);
  }
  double increment_bound(double plastic_strain, double overshoot, double dt) const {
    return johnson_cook_increment_bound(params, thermal, plastic_strain, overshoot, dt);
  }
  double jump_increment(double dt) const { return johnson_cook_jump_increment<double>(params, dt); }
  double break_increment(double dt) const {
    return johnson_cook_break_increment<double>(params, dt);
  }
  double log_curvature_bound() const { return johnson_cook_log_curvature_bound(params); }
};

/// Homologous temperature T* = (T - T_room)/(T_melt - T_room), unclamped.
inline double homologous_temperature(double temperature, double room, double melt) {
  return (temperature - room) / (melt - room);
}

/// Reads {"A", "B", "n", "C", "m", "reference_strain_rate", "rate_form"}; temperatures are the
/// material's.
JohnsonCookParams read_johnson_cook(JsonReader& r, double room_temperature,
                                    double melt_temperature);

/// The catalogue's interface (flow_stress_law.hpp): the law at (ep, rate, conditions), its reader
/// and its writer (with "type").
inline FlowStress flow_stress(const JohnsonCookParams& p, double plastic_strain,
                              double plastic_strain_rate, const FlowConditions& c) {
  return johnson_cook(p, plastic_strain, plastic_strain_rate, c.temperature);
}
inline JohnsonCookParams read_law(JsonReader& r, const JohnsonCookParams*, double room_temperature,
                                  double melt_temperature) {
  return read_johnson_cook(r, room_temperature, melt_temperature);
}
Json to_json(const JohnsonCookParams& p);

}  // namespace impact

#pragma GCC diagnostic pop
