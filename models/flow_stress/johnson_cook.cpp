#include "models/flow_stress/johnson_cook.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact {

JohnsonCookThermal johnson_cook_thermal(const JohnsonCookParams& p, double temperature) {
  const double t_star = homologous_temperature(temperature, p.room_temperature, p.melt_temperature);
  JohnsonCookThermal th;
  if (t_star >= 1.0) {
    th.factor = 0.0;
  } else if (t_star > 0.0) {
    const double t_m = std::pow(t_star, p.m);
    th.factor = 1.0 - t_m;
    th.d_factor = -p.m * t_m / t_star / (p.melt_temperature - p.room_temperature);
  }
  return th;
}

FlowStress johnson_cook(const JohnsonCookParams& p, double plastic_strain,
                        double plastic_strain_rate, double temperature) {
  return johnson_cook(p, plastic_strain, plastic_strain_rate, johnson_cook_thermal(p, temperature));
}

FlowStress johnson_cook(const JohnsonCookParams& p, double plastic_strain,
                        double plastic_strain_rate, const JohnsonCookThermal& thermal) {
  // Strain hardening A + B ep^n; its slope is unbounded at ep = 0 for n < 1.
  const double ep = plastic_strain > 0.0 ? plastic_strain : 0.0;
  double hardening = p.A;
  double d_hardening = 0.0;
  if (ep > 0.0) {
    const double ep_n = std::pow(ep, p.n);
    hardening += p.B * ep_n;
    d_hardening = p.B * p.n * ep_n / ep;
  } else if (p.B != 0.0) {
    d_hardening = p.n < 1.0 ? std::numeric_limits<double>::infinity() : (p.n == 1.0 ? p.B : 0.0);
  }

  // Rate factor.
  const double rate_star = plastic_strain_rate / p.reference_strain_rate;
  double rate_factor = 1.0;
  double d_rate_factor = 0.0;  // d factor / d rate
  if (rate_star >= 1.0) {
    rate_factor = 1.0 + p.C * std::log(rate_star);
    d_rate_factor = p.C / plastic_strain_rate;
  } else if (p.rate_form == JohnsonCookRateForm::report_2004 && rate_star > 0.0) {
    rate_factor = std::pow(1.0 + rate_star, p.C);
    d_rate_factor = p.C * rate_factor / (1.0 + rate_star) / p.reference_strain_rate;
  }

  const double thermal_factor = thermal.factor;
  const double d_thermal_factor = thermal.d_factor;  // d factor / d T

  FlowStress f;
  f.value = hardening * rate_factor * thermal_factor;
  f.d_plastic_strain = (d_hardening == 0.0 || rate_factor * thermal_factor == 0.0)
                           ? 0.0
                           : d_hardening * rate_factor * thermal_factor;
  f.d_rate = hardening * d_rate_factor * thermal_factor;
  f.d_temperature = hardening * rate_factor * d_thermal_factor;
  return f;
}

double johnson_cook_increment_bound(const JohnsonCookParams& p, const JohnsonCookThermal& thermal,
                                    double plastic_strain, double overshoot, double dt) {
  double bound = std::numeric_limits<double>::infinity();
  const double theta = thermal.factor;
  if (!(theta > 0.0) || !(overshoot > 0.0)) return bound;
  const double ep = plastic_strain > 0.0 ? plastic_strain : 0.0;
  // Hardening: B ((ep + d)^n - ep^n) theta = overshoot, without cancellation for small d.
  if (p.B > 0.0) {
    const double z = overshoot / (p.B * theta);
    bound = ep > 0.0 ? ep * std::expm1(std::log1p(z / std::pow(ep, p.n)) / p.n)
                     : std::exp(std::log(z) / p.n);  // 0 when it underflows
  }
  // Rate: (A + B ep^n) theta (factor(d / dt) - 1) = overshoot. The clamped factor 1 + C ln rate*
  // reaches 1 + y at rate* = e^(y / C); the 2004 form (1 + rate*)^C >= 1 + C rate* / (1 + rate*)
  // below rate* = 1 reaches 1 + y by rate* = y / (C - y) when y < C / 2 (and the log branch
  // above takes over otherwise).
  if (p.C > 0.0) {
    const double y = overshoot / ((p.A + p.B * std::pow(ep, p.n)) * theta);
    double rate_star = std::numeric_limits<double>::infinity();
    if (y < 700.0 * p.C) rate_star = std::exp(y / p.C);
    if (p.rate_form == JohnsonCookRateForm::report_2004 && 2.0 * y < p.C) rate_star = y / (p.C - y);
    bound = std::min(bound, rate_star * p.reference_strain_rate * dt);
  }
  return bound;
}

JohnsonCookParams read_johnson_cook(JsonReader& r, double room_temperature,
                                    double melt_temperature) {
  JohnsonCookParams p;
  r.ignore("type");
  p.A = r.quantity("A", Quantity::stress, Range::positive(), "Johnson-Cook yield stress A [Pa]");
  p.B = r.quantity("B", Quantity::stress, Range::non_negative(),
                   "Johnson-Cook hardening modulus B [Pa]");
  p.n = r.number("n", Range::open_closed(0.0, 1.5), "Johnson-Cook hardening exponent n [-]");
  p.C = r.number("C", Range::closed(0.0, 1.0), "Johnson-Cook strain-rate coefficient C [-]");
  p.m = r.number("m", Range::open(0.0, 10.0), "Johnson-Cook thermal-softening exponent m [-]");
  p.reference_strain_rate = r.number_or("reference_strain_rate", 1.0, Range::positive(),
                                        "reference plastic strain rate [1/s]");
  const std::string form = r.choice("rate_form", {"clamped", "report_2004"},
                                    "rate factor below the reference rate", "clamped");
  p.rate_form =
      form == "report_2004" ? JohnsonCookRateForm::report_2004 : JohnsonCookRateForm::clamped;
  p.room_temperature = room_temperature;
  p.melt_temperature = melt_temperature;
  r.reject_unknown_keys();
  return p;
}

}  // namespace impact
