// Preston-Tonks-Wallace flow stress: Preston, Tonks & Wallace (2003), J. Appl. Phys. 93(1):211-220,
// eq. (5)-(12). In units of the shear modulus G, with T^ = T / T_melt, the plastic strain psi and
// the rate ratio r = rate / (gamma xi), xi = (1/2) (4 pi rho / (3 M))^(1/3) (G / rho)^(1/2) the
// atomic vibration frequency (M the mass of one atom):
//   saturation   tau_s = max(s0 - (s0 - s_inf) erf(kappa T^ ln(1/r)), s0 r^beta)
//   yield        tau_y = max(y0 - (y0 - y_inf) erf(kappa T^ ln(1/r)), min(y1 r^y2, s0 r^beta))
//   hardening    tau = tau_s + (s0 - tau_y)/p ln(1 - [1 - exp(-p (tau_s - tau_y)/(s0 - tau_y))]
//                      exp(-p theta psi / ((s0 - tau_y)(exp(p (tau_s - tau_y)/(s0 - tau_y)) - 1))))
//   (p -> 0: the Voce law tau = tau_s - (tau_s - tau_y) exp(-theta psi / (tau_s - tau_y))),
// and the von Mises flow stress sigma_y = 2 G tau (the paper's convention). The shear modulus is
// the paper's G = G0 (1 - alpha T^). T_melt is the paper's T_m(rho): in a material, the melting
// curve's at the step's start density (FlowConditions::melt_temperature: the constant T_m0, or
// Steinberg-Cochran-Guinan's, which compression raises), the one the melting check uses. The
// thermally activated branch covers quasi-static to ~1e4 /s, the power laws the overdriven shock
// regime up to 1e12 /s. Like Zerilli-Armstrong, the law has no rate-independent limit: the static
// yield check and slower steps use minimum_strain_rate (default 1e-6 /s). The derivatives come from
// forward-mode automatic differentiation of the same expressions (Eigen's AutoDiffScalar), so they
// cannot drift from the value.
#pragma once

#include "models/core/input.hpp"
#include "models/flow_stress/flow_stress.hpp"

namespace impact {

struct PrestonTonksWallaceParams {
  double theta = 0.0;                 ///< initial hardening rate [-]
  double p = 0.0;                     ///< hardening shape [-] (0: Voce)
  double s0 = 0.0;                    ///< saturation stress at 0 K [-] (units of G)
  double s_inf = 0.0;                 ///< saturation stress near melting [-]
  double kappa = 0.0;                 ///< temperature dependence [-]
  double gamma = 0.0;                 ///< rate dependence [-]
  double y0 = 0.0;                    ///< yield stress at 0 K [-]
  double y_inf = 0.0;                 ///< yield stress near melting [-]
  double y1 = 0.0;                    ///< overdriven-shock yield coefficient [-]
  double y2 = 0.0;                    ///< overdriven-shock yield exponent [-]
  double beta = 0.0;                  ///< overdriven-shock saturation exponent [-]
  double G0 = 0.0;                    ///< shear modulus at 0 K [Pa]
  double alpha = 0.0;                 ///< shear modulus softening G = G0 (1 - alpha T^) [-]
  double molar_mass = 0.0;            ///< M N_A [kg/mol]
  double melt_temperature = 0.0;      ///< T_m0 [K] (the material's; see ptw_melt_temperature)
  double minimum_strain_rate = 1e-6;  ///< [1/s]

  static constexpr std::string_view kType = "preston_tonks_wallace";
  using P = PrestonTonksWallaceParams;
  static constexpr LawParameter<P> kParameters[] = {
      {"theta", "-", &P::theta, {1e-4, 1.0}},
      {"p", "-", &P::p, {0.0, 20.0}},
      {"s0", "-", &P::s0, {1e-5, 0.2}},
      {"s_inf", "-", &P::s_inf, {1e-6, 0.2}},
      {"kappa", "-", &P::kappa, {0.01, 2.0}},
      {"gamma", "-", &P::gamma, {1e-10, 1e-2}},
      {"y0", "-", &P::y0, {1e-6, 0.2}},
      {"y_inf", "-", &P::y_inf, {1e-7, 0.2}},
      {"y1", "-", &P::y1},
      {"y2", "-", &P::y2},
      {"beta", "-", &P::beta},
      {"G0", "Pa", &P::G0},
      {"alpha", "-", &P::alpha},
      {"molar_mass", "kg/mol", &P::molar_mass},
      {"minimum_strain_rate", "1/s", &P::minimum_strain_rate}};
};

/// The T_m [K] of T^ = T / T_m: the conditions' melting temperature, or the law's own when they
/// carry none (0).
double ptw_melt_temperature(const PrestonTonksWallaceParams& p, const FlowConditions& c);

/// The law's shear modulus G0 (1 - alpha T / T_m) [Pa], floored at 0.
double ptw_shear_modulus(const PrestonTonksWallaceParams& p, double temperature,
                         double melt_temperature);

/// sigma_y = 2 G tau; conditions: T, the density rho (> 0) and T_m (ptw_melt_temperature).
FlowStress flow_stress(const PrestonTonksWallaceParams& p, double plastic_strain,
                       double plastic_strain_rate, const FlowConditions& c);

/// Reads the parameters above by name (the dimensionless ones as in the paper's Table I); the
/// melting temperature is the material's.
PrestonTonksWallaceParams read_law(JsonReader& r, const PrestonTonksWallaceParams*,
                                   double room_temperature, double melt_temperature);
Json to_json(const PrestonTonksWallaceParams& p);

}  // namespace impact
