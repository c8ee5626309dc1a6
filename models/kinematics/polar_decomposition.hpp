// Polar decomposition F = R U of a deformation gradient (report sec. 2, the hypoelastic update is
// done in the unrotated configuration of R; reference_code_notes.md stage 1 item 4).
//
//   R proper orthogonal (R^T R = I, det R = +1), U = R^T F symmetric positive definite.
//
// R is the orthogonal polar factor, computed by the scaled Newton iteration of Higham (1986),
// "Computing the polar decomposition - with applications", SIAM J. Sci. Stat. Comput. 7:1160-1174:
//
//   X_0 = F,   X_{k+1} = (g_k X_k + X_k^{-T} / g_k) / 2,   g_k = (||X_k^{-1}||_F / ||X_k||_F)^{1/2}
//
// Each step maps every singular value s to (g s + 1/(g s))/2, so the iterates keep the singular
// vectors of F and converge quadratically to R; the scaling g_k (Higham's Frobenius-norm
// approximation of the optimal (s_min s_max)^{-1/2}) makes the first steps fast when F is
// strongly stretched (simple shear gamma = 10 has s_max/s_min ~ 100; ~7 steps).
// The 2004 code used a closed form through the invariants of C = F^T F instead; Newton is simpler
// to make accurate to round-off for large stretches and for F = R exactly (one step).
//
// Only det F > 0 is handled: for det F < 0 the iteration converges to an orthogonal matrix with
// det = -1 (an improper rotation). The caller guarantees J = det F > 0 (the update rejects J <= 0
// before decomposing).
#pragma once

#include "models/core/tensor.hpp"

namespace impact {

struct PolarDecomposition {
  Mat3 R;          ///< rotation (proper orthogonal)
  Mat3 U;          ///< right stretch tensor (symmetric positive definite)
  int iterations;  ///< Newton steps taken
};

/// F = R U for det F > 0 (see the header comment). Converges to ~1e-15 relative in at most 30
/// steps.
PolarDecomposition polar_decomposition(const Mat3& F);

/// The rotation nearest to a nearly orthogonal Q (singular values in (0, sqrt 3), e.g. the average
/// (R_n + R_{n+1})/2 of two rotations, whose singular values are cos of half the step's rotation
/// angle): Newton-Schulz iteration X <- X (3 I - X^T X) / 2 until ||X^T X - I||_F < 1e-15 (at most
/// 20 steps, or earlier if round-off stops the decrease). It needs no matrix inverse; it converges
/// quadratically to the orthogonal polar factor of Q (Bjorck & Bowie 1971, SIAM J. Numer. Anal.
/// 8:358; Higham 1986).
Mat3 nearest_rotation(const Mat3& Q);

}  // namespace impact
