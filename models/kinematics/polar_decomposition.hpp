// Polar decomposition F = R U of a deformation gradient (report sec. 2, the hypoelastic update is
// done in the unrotated configuration of R; docs/report_code.md sec. 3).
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

/// The rotation R of F = R U, warm-started from a nearby rotation `guess` (in an explicit solver,
/// the previous step's R: F_{n+1} rotates little in one step). Newton on the rotation vector phi
/// of R = guess * cay(phi) for the condition skew(R^T F) = 0: with S = R^T F the correction solves
///   ((tr S) I - sym S) delta = 2 axial(skew S)
/// (from [d]x S + S [d]x = [((tr S) I - S) d]x for symmetric S) and is applied as the exactly
/// orthogonal Cayley rotation through 2 atan(|delta|/2). Quadratic convergence: two or three steps
/// from a guess within a few degrees, each with no square root of a matrix and one 3x3 solve. A
/// final Newton-Schulz step removes the round-off drift of repeated products. Falls back to
/// polar_decomposition (Higham) when the guess is far (no convergence in 8 steps, or R^T F not
/// positive definite, i.e. a different stationary rotation), so the answer is always the polar
/// factor. `iterations`, when given, receives the steps taken (fallback steps included).
Mat3 polar_rotation(const Mat3& F, const Mat3& guess, int* iterations = nullptr);

/// Cayley rotation (I - [c]x)^{-1} (I + [c]x) = I + 2 ([c]x + [c]x^2) / (1 + |c|^2): the rotation
/// about c through 2 atan(|c|), exactly orthogonal (for a spin omega over dt, c = omega dt / 2:
/// the Hughes-Winget increment).
Mat3 cayley_rotation(const Vec3& c);

/// The rotation nearest to a nearly orthogonal Q (singular values in (0, sqrt 3), e.g. the average
/// (R_n + R_{n+1})/2 of two rotations, whose singular values are cos of half the step's rotation
/// angle): Newton-Schulz iteration X <- X (3 I - X^T X) / 2 until ||X^T X - I||_F < 1e-15 (at most
/// 20 steps, or earlier if round-off stops the decrease). It needs no matrix inverse; it converges
/// quadratically to the orthogonal polar factor of Q (Bjorck & Bowie 1971, SIAM J. Numer. Anal.
/// 8:358; Higham 1986).
Mat3 nearest_rotation(const Mat3& Q);

}  // namespace impact
