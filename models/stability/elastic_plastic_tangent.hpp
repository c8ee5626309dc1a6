// Continuum elastic-plastic tangent of associated von Mises (J2) plasticity, the modulus that the
// Drucker (report eq. 10) and Becker (report eq. 11) stability checks evaluate. Hill (1958), J.
// Mech. Phys. Solids 6:236-249; Simo & Hughes (1998), Computational Inelasticity, sec. 2.3.
//
//   N = (3/2) s / sigma_eq        (flow direction, N:N = 3/2, N:sigma = sigma_eq),
//   D^p = eps_dot_p N,  consistency N:sigma_dot = H eps_dot_p  =>  eps_dot_p = 2 mu N:D / (3 mu +
//   H), C^ep = C^e - (2 mu)^2 N (x) N / (3 mu + H),     C^e = K I (x) I + 2 mu (I_sym - I (x) I /
//   3).
//
// H is the effective hardening slope d sigma_y / d eps_p along the loading process (see
// effective_hardening). The tangent is singular at H = -3 mu (softening as steep as the elastic
// shear response); callers must keep H > -3 mu, which any flow-stress law of a metal does by orders
// of magnitude (6061-T6: |H| < 0.1 GPa against 3 mu = 78 GPa). H = +inf (the Johnson-Cook slope at
// eps_p = 0 for n < 1) gives C^e, as it should: no plastic flow can start against infinite
// hardening.
//
// Difference from the 2004 code (docs/report_code.md sec. 7): it used the denominator
// f:C^e:f - f_q h_q with f = 3 s, f_q = d sigma_y/d eps_p and h_q = 2 sigma_eq^2/sigma_y; the terms
// have units Pa^3 and Pa^2, and the hardening term carried the wrong sign and was 1e-8..1e-12 of
// the first. Its C^ep was therefore that of ideal plasticity, whatever the hardening, and Drucker's
// check almost never fired. Written consistently, f:C^e:f + 2 sigma_y H h_q = (12 mu + 4 H)
// sigma_eq^2, which is (4/9) sigma_eq^2 times the (3 mu + H) used here.
#pragma once

#include "models/core/tensor.hpp"

namespace impact {

/// C^ep of associated J2 plasticity at `stress` [Pa] with hardening slope H [Pa]; K, mu [Pa].
/// Returns C^e when sigma_eq == 0 (no flow direction exists).
Tensor4 elastic_plastic_tangent(double bulk_modulus, double shear_modulus, const Mat3& stress,
                                double H);

// How the strain-rate sensitivity of the flow stress enters H.
//   constant_rate (default): along a process at constant plastic strain rate the rate term
//     contributes nothing, H = d sigma_y/d eps_p (+ thermal term). This is the classical
//     adiabatic-shear-band criterion (Recht 1964, J. Appl. Mech. 31:189-193; Culver 1973,
//     Metallurgical Effects at High Strain Rates, 519-530): instability when thermal softening
//     outweighs strain hardening at fixed rate.
//   algorithmic: H includes d sigma_y/d rate / dt, the slope that the discrete return map sees
//     because it takes the step's plastic strain rate as Delta eps_p / dt. For Johnson-Cook this
//     is C sigma_y0 / Delta eps_p per step: with 6061-T6 (C = 0.002) and Delta eps_p = 1e-4 per
//     MPM step it is ~6 GPa, 100 times the strain-hardening slope and 100 times any thermal
//     softening, so it suppresses every instability. Kept to show that effect (and to match a
//     Uintah-HEAD-style Newton tangent), not as the physical criterion.
enum class RateSlope { constant_rate, algorithmic };

/// Partial derivatives of the flow stress sigma_y(eps_p, rate, T) at the current state.
struct FlowSlopes {
  double d_plastic_strain = 0.0;  ///< d sigma_y / d eps_p [Pa]
  double d_rate = 0.0;            ///< d sigma_y / d eps_dot_p [Pa s]
  double d_temperature = 0.0;     ///< d sigma_y / d T [Pa/K]
};

/// Effective hardening slope H = d sigma_y / d eps_p along the process [Pa]:
///   H = d_plastic_strain
///     + (algorithmic ? d_rate / dt : 0)
///     + (adiabatic ? d_temperature * chi * flow_stress / (rho cp) : 0),
/// the last term because adiabatic heating (report eq. 8) raises T by chi sigma_y / (rho cp) per
/// unit plastic strain. flow_stress [Pa], dt [s] (> 0 for algorithmic), density [kg/m^3],
/// specific_heat [J/(kg K)].
double effective_hardening(const FlowSlopes& slopes, double flow_stress, double dt,
                           RateSlope rate_slope, bool adiabatic, double taylor_quinney,
                           double density, double specific_heat);

}  // namespace impact
