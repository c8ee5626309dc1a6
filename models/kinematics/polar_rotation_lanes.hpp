// The warm-started polar rotation (polar_decomposition.hpp, polar_rotation) for one point (V =
// double) or a vector of points (V = lane::Vec), one source for both: polar_rotation is this
// template on a double, and polar_rotation_batch (polar_rotation_batch.hpp) on the vector lanes of
// the batched update, so a point gets the same rotation alone or in a batch. Written with selects
// only (every lane runs until all have converged, a converged lane keeps its value), and with the
// 3x3 algebra spelt out: Eigen's fixed-size matrices do not take a vector as scalar.
#pragma once

#include "models/core/lane_mat3.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace impact {

namespace lane_algebra {

#define IMPACT_LANE_INLINE [[gnu::always_inline]] inline

/// The Cayley rotation I + 2 ([c]x + [c]x^2) / (1 + |c|^2) (polar_decomposition.hpp).
template <class V>
IMPACT_LANE_INLINE LaneMat3<V> cayley(V c0, V c1, V c2) {
  const V s = 2.0 / (1.0 + (c0 * c0 + c1 * c1 + c2 * c2));
  // [c]x^2 = c c^T - |c|^2 I.
  const V n2 = c0 * c0 + c1 * c1 + c2 * c2;
  LaneMat3<V> Q;
  Q.a[0][0] = 1.0 + s * (c0 * c0 - n2);
  Q.a[1][1] = 1.0 + s * (c1 * c1 - n2);
  Q.a[2][2] = 1.0 + s * (c2 * c2 - n2);
  Q.a[0][1] = s * (c0 * c1 - c2);
  Q.a[1][0] = s * (c0 * c1 + c2);
  Q.a[0][2] = s * (c0 * c2 + c1);
  Q.a[2][0] = s * (c0 * c2 - c1);
  Q.a[1][2] = s * (c1 * c2 - c0);
  Q.a[2][1] = s * (c1 * c2 + c0);
  return Q;
}

#undef IMPACT_LANE_INLINE

}  // namespace lane_algebra

/// The outcome on each lane: R, whether the warm start converged (else the caller falls back to
/// the cold polar decomposition), and the Newton steps taken.
template <class V>
struct alignas(lane::kLaneBytes) PolarLanes {
  LaneMat3<V> R;
  lane::IntOf<V> converged;
  lane::IntOf<V> iterations;
};

/// Newton on the rotation vector phi of R = guess cay(phi) for skew(R^T F) = 0, at most 8 steps,
/// stopping a lane once its correction is below 1e-8 rad; then one Newton-Schulz step, and the
/// check that R^T F is positive definite (polar_decomposition.hpp, polar_rotation).
template <class V>
[[gnu::always_inline]] inline PolarLanes<V> polar_rotation_lanes(const LaneMat3<V>& F,
                                                                 const LaneMat3<V>& guess) {
  using lane::select;
  using namespace lane_algebra;
  using Mask = lane::MaskOf<V>;
  constexpr int max_iterations = 8;
  constexpr double quadratic_stop = 1e-8;
  LaneMat3<V> Q = guess;
  const V zero = lane::splat<V>(0.0);
  Mask active = zero == zero;
  Mask converged = zero != zero;
  lane::IntOf<V> iterations{};
  for (int k = 1; k <= max_iterations && lane::any(active); ++k) {
    const LaneMat3<V> S = transpose_times(Q, F);
    const V w0 = 0.5 * (S.a[2][1] - S.a[1][2]);
    const V w1 = 0.5 * (S.a[0][2] - S.a[2][0]);
    const V w2 = 0.5 * (S.a[1][0] - S.a[0][1]);
    // J = (tr S) I - sym S, positive definite near the polar factor.
    const V tr = S.a[0][0] + S.a[1][1] + S.a[2][2];
    const V j00 = tr - S.a[0][0], j11 = tr - S.a[1][1], j22 = tr - S.a[2][2];
    const V j01 = -0.5 * (S.a[0][1] + S.a[1][0]);
    const V j02 = -0.5 * (S.a[0][2] + S.a[2][0]);
    const V j12 = -0.5 * (S.a[1][2] + S.a[2][1]);
    // delta = 2 J^{-1} w by the cofactors of the symmetric J.
    const V c00 = j11 * j22 - j12 * j12, c01 = j02 * j12 - j01 * j22, c02 = j01 * j12 - j02 * j11;
    const V c11 = j00 * j22 - j02 * j02, c12 = j01 * j02 - j00 * j12, c22 = j00 * j11 - j01 * j01;
    const V det = j00 * c00 + j01 * c01 + j02 * c02;
    const Mask far = !(det > 0.0);  // a different stationary rotation: the cold start decides
    const V scale = 2.0 / select<V>(far, 1.0, det);
    const V d0 = scale * (c00 * w0 + c01 * w1 + c02 * w2);
    const V d1 = scale * (c01 * w0 + c11 * w1 + c12 * w2);
    const V d2 = scale * (c02 * w0 + c12 * w1 + c22 * w2);
    const LaneMat3<V> Qn = times(Q, cayley(V(0.5 * d0), V(0.5 * d1), V(0.5 * d2)));
    const Mask step = active & !far;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Q.a[i][j] = select<V>(step, Qn.a[i][j], Q.a[i][j]);
    const Mask done = step & (d0 * d0 + d1 * d1 + d2 * d2 <= quadratic_stop * quadratic_stop);
    iterations = select(done, lane::IntOf<V>{} + k, iterations);
    converged = converged | done;
    active = step & !done;
  }
  // One Newton-Schulz step removes the round-off drift of the products: Q - Q (Q^T Q - I) / 2.
  LaneMat3<V> E = lane_algebra::transpose_times(Q, Q);
  for (int i = 0; i < 3; ++i) E.a[i][i] = E.a[i][i] - 1.0;
  const LaneMat3<V> QE = lane_algebra::times(Q, E);
  PolarLanes<V> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.R.a[i][j] = Q.a[i][j] - 0.5 * QE.a[i][j];
  // sym(R^T F) positive definite by its leading minors.
  const LaneMat3<V> U = lane_algebra::transpose_times(out.R, F);
  const V u01 = 0.5 * (U.a[0][1] + U.a[1][0]), u02 = 0.5 * (U.a[0][2] + U.a[2][0]);
  const V u12 = 0.5 * (U.a[1][2] + U.a[2][1]);
  const V m2 = U.a[0][0] * U.a[1][1] - u01 * u01;
  const V m3 = U.a[0][0] * (U.a[1][1] * U.a[2][2] - u12 * u12) -
               u01 * (u01 * U.a[2][2] - u12 * u02) + u02 * (u01 * u12 - U.a[1][1] * u02);
  const Mask positive = (U.a[0][0] > 0.0) & (m2 > 0.0) & (m3 > 0.0);
  out.converged = lane::flag<V>(converged & positive);
  out.iterations = iterations;
  return out;
}

}  // namespace impact

#pragma GCC diagnostic pop
