// Objective stress rates for the hypoelastic update (report sec. 2; docs/report_code.md sec. 0
// item 2 and stage 1 items 4-7, stage 5 item 23).
//
// Green-Naghdi (polar) update (Dienes 1979, Acta Mech. 32:217-232; Flanagan & Taylor 1987, CMAME
// 62:305-320). With F = R U, the unrotated stress sigma_hat = R^T sigma R obeys an ordinary rate
// equation d(sigma_hat)/dt = C : D_hat with D_hat = R^T D R, D = sym L. One step:
//
//   sigma_hat_n = R_n^T sigma_n R_n                      un-rotate with the OLD rotation
//   D_hat       = R_{n+1/2}^T D R_{n+1/2},  R_{n+1/2} = nearest_rotation((R_n + R_{n+1}) / 2)
//   sigma_hat_{n+1} = sigma_hat_n + (material update with D_hat)
//   sigma_{n+1} = R_{n+1} sigma_hat_{n+1} R_{n+1}^T      re-rotate with the NEW rotation
//
// The midpoint rotation makes the D rotation second order in dt (Flanagan & Taylor 1987); the
// average of two rotations about one axis is cos(dtheta/2) times the rotation through the average
// angle, so nearest_rotation recovers exactly that rotation; midpoint_rotation gets it in closed
// form from the quaternion of R_n^T R_{n+1}.
//
// The 2004 code un-rotated and re-rotated with the same R_{n+1}: the two rotations cancel and the
// stress is never carried with the material (a stressed body spun rigidly keeps its lab-frame
// stress), which is not objective. Fixed in the code only in 2011. corotation_test shows both.
//
// Incremental Green-Naghdi update (option "green_naghdi_incremental"): the same rotations without a
// polar decomposition. The Green-Naghdi spin Omega = dR/dt R^T follows from L and the left
// stretch V = F R^T (Dienes 1979 eq. 4.6; Flanagan & Taylor 1987 eq. 24): F = V R gives
// L V = dV/dt + V Omega with dV/dt symmetric, and for symmetric V the skew part of V Omega has the
// axial vector (tr V I - V) omega / 2, so
//   omega = 2 (tr V I - V)^{-1} axial(skew(L V)).
// (tr V I - V is positive definite for V positive definite.) One step, second order in dt: V_n =
// sym(F_n R_n^T) gives omega_n; a predictor R* = cay(omega_n dt) R_n gives V_{n+1} =
// sym(F_{n+1} R*^T) and omega_{n+1}; with their mean omega, R_{n+1} = cay(omega dt) R_n and
// R_{n+1/2} = cay(omega dt / 2) R_n, cay the Cayley (Hughes-Winget) rotation, exactly orthogonal.
// No state beyond R: V is recomputed from F and R each step. It drifts from the polar factor by
// O(dt^2) over a path (kinematics_test states the size on rotation and simple shear).
//
// Jaumann rate (option "jaumann", for comparison): sigma is rotated with the spin W = skew L by the
// Hughes-Winget increment Q = (I - W dt/2)^{-1} (I + W dt/2) (Hughes & Winget 1980, IJNME
// 15:1862-1867); the composed model applies it over half a step before and half a step after the
// material update with D (midpoint form, second order). Q is exactly orthogonal for skew W (a
// Cayley transform, rotation angle 2 atan(|w| dt/2)). Under simple shear the Jaumann rate makes the
// elastic shear stress oscillate (mu sin gamma).
#pragma once

#include "models/core/tensor.hpp"

namespace impact {

enum class ObjectiveRate { green_naghdi, green_naghdi_incremental, jaumann };

struct Corotation {
  Mat3 R_old;  ///< R_n: un-rotates the old stress
  Mat3 R_new;  ///< R_{n+1} = rotation of F_{n+1}: re-rotates the new stress
  Mat3 R_mid;  ///< R_{n+1/2}: rotates D into the unrotated frame
};

/// R_old (R_old^T R_new)^{1/2}: the rotation halfway from R_old to R_new, by the square root of the
/// unit quaternion of R_old^T R_new (closed form, no iteration). Equals
/// nearest_rotation((R_old + R_new) / 2), which is used beyond a 151-degree step (1 + tr(R_old^T
/// R_new) < 1/4).
Mat3 midpoint_rotation(const Mat3& R_old, const Mat3& R_new);

/// One Green-Naghdi step applied to the symmetric stress and rate of deformation: what the
/// hypoelastic update works with in the unrotated frame.
struct Corotated {
  Mat3 R_new;   ///< R_{n+1}
  Mat3 R_mid;   ///< midpoint_rotation(R_n, R_{n+1})
  Mat3 stress;  ///< R_n^T sigma_n R_n
  Mat3 D;       ///< R_mid^T D R_mid
};

/// The step from R_old to R_new applied to sigma_n and D (both symmetric; the results are exactly
/// symmetric): corotate_lanes (corotation_lanes.hpp) on one double, so that corotation_batch gives
/// the same bits.
Corotated corotate(const Mat3& R_old, const Mat3& R_new, const Mat3& stress, const Mat3& D);

/// The rotations of one Green-Naghdi step; R_new = polar_rotation(F_new, R_old), det F_new > 0.
Corotation corotation(const Mat3& R_old, const Mat3& F_new);

/// The Green-Naghdi spin vector omega (Omega = dR/dt R^T = [omega]x) for the velocity gradient L
/// [1/s] and the left stretch V (symmetric positive definite) of F = V R.
Vec3 green_naghdi_spin(const Mat3& L, const Mat3& V);

/// The rotations of one Green-Naghdi step without a polar decomposition (header comment):
/// F_old = F_n with rotation R_old = R_n, F_new = F_{n+1}, L the step's velocity gradient.
Corotation incremental_corotation(const Mat3& R_old, const Mat3& F_old, const Mat3& F_new,
                                  const Mat3& L, double dt);

/// R^T a R: lab frame -> unrotated frame.
inline Mat3 unrotate(const Mat3& a, const Mat3& R) {
  return R.transpose() * a * R;
}

/// R a R^T: unrotated frame -> lab frame.
inline Mat3 rotate(const Mat3& a, const Mat3& R) {
  return R * a * R.transpose();
}

/// Hughes-Winget increment Q = (I - W dt/2)^{-1} (I + W dt/2) for a spin W [1/s] over dt [s].
Mat3 hughes_winget_rotation(const Mat3& W, double dt);

}  // namespace impact
