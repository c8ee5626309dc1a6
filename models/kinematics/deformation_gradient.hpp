// Advancing the deformation gradient over a step from the velocity gradient L = grad v
// (docs/report_code.md sec. 3):  dF/dt = L F.
//
//   forward_euler:  F_{n+1} = (I + L dt) F_n        (the 2004 code; the MPM default)
//   exponential:    F_{n+1} = exp(L dt) F_n         (exact for L constant over the step)
//
// Forward Euler is first order and, for a pure spin W, not a rotation: det(I + W dt) =
// 1 + |w|^2 dt^2, so a spinning point gains volume every step (tests/.../deformation_gradient_test
// measures it). The exponential keeps det F = exp(tr L dt) J_n exactly and a pure spin orthogonal.
// exp and log are Eigen's unsupported MatrixFunctions (Pade with scaling and squaring; inverse
// scaling and squaring on the Schur form).
#pragma once

#include "models/core/tensor.hpp"

namespace impact {

enum class FIntegration { forward_euler, exponential };

/// exp(L dt) F_n (out of line: it is the rare choice).
Mat3 advance_deformation_gradient_exponential(const Mat3& F, const Mat3& L, double dt);

/// F_{n+1} from F_n, a velocity gradient L [1/s] held constant over dt [s]. Inline: the MPM
/// calls it once per particle and step, and the call cost 3 % of the recommended scene's step
/// (docs/performance.md).
inline Mat3 advance_deformation_gradient(const Mat3& F, const Mat3& L, double dt,
                                         FIntegration how) {
  if (how == FIntegration::exponential) return advance_deformation_gradient_exponential(F, L, dt);
  // (I + L dt) F written as F + dt (L F): the increment is not rounded against the identity.
  return F + dt * (L * F);
}

/// The constant velocity gradient [1/s] that takes F0 to F1 in dt [s]: L = logm(F1 F0^{-1}) / dt,
/// the inverse of advance_deformation_gradient(F0, L, dt, exponential). Used by the point driver
/// for prescribed-F legs. The principal logarithm is taken, so the increment F1 F0^{-1} must have
/// no eigenvalue on the closed negative real axis (in particular its rotation angle must be below
/// pi); split longer legs into steps. Allocates (Schur form): not for the per-point hot loop.
Mat3 constant_velocity_gradient(const Mat3& F0, const Mat3& F1, double dt);

}  // namespace impact
