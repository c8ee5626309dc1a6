#include "models/flow_stress/preston_tonks_wallace.hpp"

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impact {

namespace {

// A number with its derivatives by (plastic strain, rate, temperature).
using Dual = Eigen::AutoDiffScalar<Eigen::Vector3d>;

Dual variable(double value, int index) {
  return Dual(value, 3, index);
}
Dual constant(double value) {
  return Dual(value, Eigen::Vector3d::Zero());
}
// The larger or smaller of two, with its derivatives (PTW's max and min pick a branch).
Dual larger(const Dual& a, const Dual& b) {
  return a.value() >= b.value() ? a : b;
}
Dual smaller(const Dual& a, const Dual& b) {
  return a.value() <= b.value() ? a : b;
}
// erf with its derivative 2/sqrt(pi) exp(-x^2) (Eigen's AutoDiffScalar has none).
Dual erf(const Dual& x) {
  const double v = x.value();
  return Dual(std::erf(v),
              x.derivatives() * (2.0 / std::sqrt(std::numbers::pi) * std::exp(-v * v)));
}

constexpr double kAvogadro = 6.02214076e23;  // [1/mol]

}  // namespace

double ptw_melt_temperature(const PrestonTonksWallaceParams& p, const FlowConditions& c) {
  return c.melt_temperature > 0.0 ? c.melt_temperature : p.melt_temperature;
}

double ptw_shear_modulus(const PrestonTonksWallaceParams& p, double temperature,
                         double melt_temperature) {
  return std::max(p.G0 * (1.0 - p.alpha * temperature / melt_temperature), 0.0);
}

FlowStress flow_stress(const PrestonTonksWallaceParams& p, double plastic_strain,
                       double plastic_strain_rate, const FlowConditions& c) {
  using std::exp;
  using std::log;
  using std::pow;
  using std::sqrt;
  const Dual psi = variable(plastic_strain, 0);
  const Dual rate = plastic_strain_rate < p.minimum_strain_rate ? constant(p.minimum_strain_rate)
                                                                : variable(plastic_strain_rate, 1);
  const Dual T_hat = variable(c.temperature, 2) / ptw_melt_temperature(p, c);
  const Dual G = p.G0 * (1.0 - p.alpha * T_hat);
  FlowStress f;
  if (G.value() <= 0.0) return f;  // no strength left (beyond the modulus' zero)
  // xi = (1/2) (4 pi n / 3)^(1/3) sqrt(G / rho), n = rho N_A / M atoms per m^3.
  const double atoms = c.density * kAvogadro / p.molar_mass;
  const Dual xi = 0.5 * std::cbrt(4.0 * std::numbers::pi * atoms / 3.0) * sqrt(G / c.density);
  const Dual r = rate / (p.gamma * xi);
  const Dual activation = erf(-p.kappa * T_hat * log(r));  // erf(kappa T^ ln(1 / r))
  const Dual shock_s = p.s0 * pow(r, p.beta);
  const Dual tau_s = larger(p.s0 - (p.s0 - p.s_inf) * activation, shock_s);
  const Dual tau_y =
      larger(p.y0 - (p.y0 - p.y_inf) * activation, smaller(p.y1 * pow(r, p.y2), shock_s));
  Dual tau;
  const Dual span = tau_s - tau_y;
  if (span.value() <= 0.0) {
    tau = larger(tau_s, tau_y);  // no hardening left (the overdriven regime)
  } else if (p.p > 0.0) {
    const Dual a = p.s0 - tau_y;
    const Dual x = p.p * span / a;
    tau = tau_s +
          a / p.p * log(1.0 - (1.0 - exp(-x)) * exp(-p.p * p.theta * psi / (a * (exp(x) - 1.0))));
  } else {
    tau = tau_s - span * exp(-p.theta * psi / span);
  }
  const Dual sigma = 2.0 * G * tau;
  f.value = sigma.value();
  f.d_plastic_strain = sigma.derivatives()(0);
  f.d_rate = sigma.derivatives()(1);
  f.d_temperature = sigma.derivatives()(2);
  return f;
}

PrestonTonksWallaceParams read_law(JsonReader& r, const PrestonTonksWallaceParams*, double,
                                   double melt_temperature) {
  PrestonTonksWallaceParams p;
  r.ignore("type");
  const auto dimensionless = [&](std::string_view key, Range range, std::string_view meaning) {
    return r.number(key, range, meaning);
  };
  p.theta = dimensionless("theta", Range::non_negative(), "PTW initial hardening rate theta [-]");
  p.p = dimensionless("p", Range::non_negative(), "PTW hardening shape p [-]");
  p.s0 = dimensionless("s0", Range::open(0.0, 1.0), "PTW saturation stress at 0 K s0 [-]");
  p.s_inf =
      dimensionless("s_inf", Range::open(0.0, 1.0), "PTW saturation stress near melting s_inf [-]");
  p.kappa = dimensionless("kappa", Range::positive(), "PTW temperature dependence kappa [-]");
  p.gamma = dimensionless("gamma", Range::positive(), "PTW rate dependence gamma [-]");
  p.y0 = dimensionless("y0", Range::open(0.0, 1.0), "PTW yield stress at 0 K y0 [-]");
  p.y_inf =
      dimensionless("y_inf", Range::open(0.0, 1.0), "PTW yield stress near melting y_inf [-]");
  p.y1 = dimensionless("y1", Range::non_negative(), "PTW overdriven yield coefficient y1 [-]");
  p.y2 = dimensionless("y2", Range::non_negative(), "PTW overdriven yield exponent y2 [-]");
  p.beta = dimensionless("beta", Range::non_negative(), "PTW overdriven saturation exponent [-]");
  p.G0 = r.quantity("G0", Quantity::elastic_modulus, Range::positive(),
                    "PTW shear modulus at 0 K G0 [Pa]");
  p.alpha = r.number("alpha", Range::closed(0.0, 1.0), "PTW shear modulus softening alpha [-]");
  p.molar_mass = r.number("molar_mass", Range::open(1e-3, 1.0), "molar mass [kg/mol]");
  p.minimum_strain_rate = r.number_or("minimum_strain_rate", 1e-6, Range::positive(),
                                      "slowest rate the law is evaluated at [1/s]");
  p.melt_temperature = melt_temperature;
  r.reject_unknown_keys();
  for (const auto& [lower, upper, name] :
       {std::tuple{p.s_inf, p.s0, "s_inf <= s0"}, std::tuple{p.y_inf, p.y0, "y_inf <= y0"},
        std::tuple{p.y0, p.s0, "y0 <= s0"}, std::tuple{p.y_inf, p.s_inf, "y_inf <= s_inf"}}) {
    if (lower > upper)
      r.problems().add(r.path(), std::string("expected ") + name +
                                     " (PTW's ordering of the "
                                     "yield and saturation stresses), got " +
                                     std::to_string(lower) + " > " + std::to_string(upper));
  }
  return p;
}

Json to_json(const PrestonTonksWallaceParams& p) {
  return parameters_to_json(p);
}

}  // namespace impact
