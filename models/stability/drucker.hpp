// Drucker's stability postulate (Drucker 1959, J. Appl. Mech. 26:101-106), report eq. (10): the
// material is unstable (a point fails) when the second-order plastic work is not positive,
//   sigma_dot : D^p <= 0   while it loads plastically (D^p != 0),   sigma_dot = C^ep : D.
//
// For the associated J2 tangent of elastic_plastic_tangent.hpp, with N = (3/2) s / sigma_eq,
// N:N = 3/2, C^e:N = 2 mu N and the tangent's own plastic rate eps_dot_c = 2 mu N:D / (3 mu + H):
//   sigma_dot = C^e:D - 2 mu N eps_dot_c,
//   sigma_dot : (eps_dot_p N) = eps_dot_p [2 mu N:D - 2 mu (3/2) eps_dot_c]
//                             = eps_dot_p [(3 mu + H) eps_dot_c - 3 mu eps_dot_c]
//                             = H eps_dot_p eps_dot_c,
// which is H eps_dot_p^2 when D^p = eps_dot_p N is the plastic rate of the same loading. In plastic
// loading eps_dot_p > 0 and (3 mu + H > 0) eps_dot_c > 0, so the check fires exactly when H < 0:
// when thermal (or any other) softening along the process outweighs strain hardening. At H = 0
// exactly (ideal plasticity) the indicator is 0 up to round-off: drucker_check_j2 (what the
// update runs) calls that neutral, stable, rather than failing points on the sign of noise.
//
// Difference from the 2004 code (docs/report_code.md sec. 9): it tested sigma_dot : D with the
// total D, which equals D:C^e:D - (2 mu N:D)^2 / (3 mu + H) and is positive whenever D has an
// elastic part not parallel to N, and it used a tangent that was effectively ideal-plastic (sec.
// 7), so it almost never fired. Here the printed eq. (10) is used, with the consistent tangent.
#pragma once

#include "models/core/tensor.hpp"

namespace impact {

struct DruckerResult {
  double indicator = 0.0;  ///< sigma_dot : D^p [Pa/s^2]; 0 when the check did not run
  bool unstable = false;   ///< indicator <= 0 while D^p != 0
};

/// Drucker's check with tangent C (for instance elastic_plastic_tangent), rate of deformation D
/// [1/s] and plastic rate of deformation D^p [1/s] of the same step.
DruckerResult drucker_check(const Tensor4& tangent, const Mat3& D, const Mat3& Dp);

/// The same check with the J2 tangent of elastic_plastic_tangent(K, mu, stress, H) in closed form,
/// without assembling it (9 + 27 multiplications instead of 81 + 81):
///   D^p : C^ep : D = lambda tr D tr D^p + mu D^p : (D + D^T) - (2 mu)^2/(3 mu + H) (N:D)(N:D^p),
/// lambda = K - 2 mu/3, N = (3/2) s / sigma_eq (the elastic part alone when sigma_eq = 0). An
/// indicator within 1e-12 of its three terms' size is round-off of the neutral case H = 0 (ideal
/// plasticity) and counts as stable.
DruckerResult drucker_check_j2(double bulk_modulus, double shear_modulus, const Mat3& stress,
                               double H, const Mat3& D, const Mat3& Dp);

}  // namespace impact
