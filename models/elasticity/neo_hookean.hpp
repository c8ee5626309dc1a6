// The compressible neo-Hookean solid: hyperelastic, its stress a function of F alone (no rate, no
// history). Stored energy per unit reference volume (Simo & Pister 1984, Comput. Methods Appl.
// Mech. Eng. 46:201; the form of Wallstedt & Guilkey 2008, J. Comput. Phys. 227:9628, sec. 4, and
// of Bonet & Wood 2008, Nonlinear Continuum Mechanics for FEA, 2nd ed., sec. 6.4.3):
//   W(F) = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,   C = F^T F, J = det F,
// whose Cauchy stress is (Bonet & Wood eq. 6.29)
//   sigma = [mu (b - I) + lambda ln(J) I] / J,               b = F F^T,
// and first Piola-Kirchhoff stress P = J sigma F^-T = mu (F - F^-T) + lambda ln(J) F^-T.
// mu is the material's shear_modulus and lambda = K - 2 mu / 3 from its bulk_modulus, so at small
// strain the law is the linear isotropic solid the hypoelastic update starts from.
//
// Its spatial elasticity tensor is c = lambda' I (x) I + 2 mu' II with lambda' = lambda / J and
// mu' = (mu - lambda ln J) / J (Bonet & Wood eq. 6.40). With the geometric (initial-stress) term
// the acoustic tensor of a direction n in the current configuration, Q(n) = c_ijkl n_j n_l + (n .
// sigma n) delta_ik, is for this law
//   Q(n) = (mu b_nn / J) I + (a / J) n (x) n,   a = lambda + mu - lambda ln J,  b_nn = n . b n,
// whose eigenvalues rho c^2 (rho = rho0 / J) give plane waves at
//   rho0 c^2 = mu b_nn + a  (longitudinal)  and  mu b_nn  (transverse).
// The fastest wave over all n: rho0 c^2 = mu b_max + max(0, a), b_max the largest eigenvalue of b
// (exact, not only a bound: the largest is along b's principal direction). The law is strongly
// elliptic while the smallest, mu b_min + min(0, a), is positive: always in compression when
// lambda >= 0 (the reader refuses lambda < 0), since a > 0 there; in a stretch only once a < 0
// (ln J > 1 + mu / lambda) outweighs mu b_min. Beyond it there is no wave speed: NaN.
#pragma once

#include "models/core/tensor.hpp"

namespace impact {

struct NeoHookeanModuli {
  double mu = 0.0;      ///< shear modulus [Pa]
  double lambda = 0.0;  ///< Lame's first parameter, K - 2 mu / 3 [Pa]
};

/// sigma(F) [Pa]; F with det F > 0.
Mat3 neo_hookean_stress(const Mat3& F, const NeoHookeanModuli& m);

/// W(F), per unit reference volume [J/m^3].
double neo_hookean_energy(const Mat3& F, const NeoHookeanModuli& m);

/// The fastest plane-wave speed at F [m/s]; rho0 the reference density [kg/m^3]. NaN where the
/// law is not strongly elliptic.
double neo_hookean_wave_speed(const Mat3& F, const NeoHookeanModuli& m, double rho0);

}  // namespace impact
