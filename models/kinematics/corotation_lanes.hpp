// The Green-Naghdi step's rotations applied (corotation.hpp): the midpoint rotation R_{n+1/2}, the
// un-rotated old stress R_n^T sigma_n R_n and the un-rotated rate of deformation
// R_{n+1/2}^T D R_{n+1/2}, for one point (V = double) or a vector of points (V = lane::Vec): one
// source, like polar_rotation_lanes.hpp. corotate (corotation.hpp) is this template on a double;
// corotation_batch (corotation_batch.hpp) on the lanes of the batched update, so a point gets the
// same bits alone or in a batch.
#pragma once

#include "models/kinematics/polar_rotation_lanes.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace impact {

template <class V>
struct alignas(lane::kLaneBytes) CorotatedLanes {
  LaneMat3<V> R_mid;
  LaneMat3<V> stress;  ///< R_n^T sigma_n R_n (symmetric by construction)
  LaneMat3<V> D;       ///< R_{n+1/2}^T D R_{n+1/2}
  /// Set where the step rotates by more than ~151 degrees (1 + tr Q < 1/4): the closed-form
  /// midpoint loses digits there, and the caller takes nearest_rotation((R_n + R_{n+1}) / 2)
  /// instead (corotation.cpp).
  lane::IntOf<V> wide;
};

namespace lane_algebra {

/// R_old (R_old^T R_new)^{1/2} by the square root of the unit quaternion (w, v) of Q = R_old^T
/// R_new, (1 + w, v) normalised (midpoint_rotation, corotation.hpp); `wide` where 1 + tr Q < 1/4.
template <class V>
[[gnu::always_inline]] inline LaneMat3<V> midpoint_lanes(const LaneMat3<V>& R_old,
                                                         const LaneMat3<V>& R_new,
                                                         lane::MaskOf<V>& wide) {
  const LaneMat3<V> Q = transpose_times(R_old, R_new);
  const V one_plus_trace = 1.0 + (Q.a[0][0] + Q.a[1][1] + Q.a[2][2]);  // 4 w^2 = 2 + 2 cos angle
  wide = one_plus_trace < 0.25;
  const V w = 0.5 * lane::sqrt(lane::select<V>(wide, 1.0, one_plus_trace));
  const V inv_4w = 1.0 / (4.0 * w);
  const V v0 = (Q.a[2][1] - Q.a[1][2]) * inv_4w, v1 = (Q.a[0][2] - Q.a[2][0]) * inv_4w;
  const V v2 = (Q.a[1][0] - Q.a[0][1]) * inv_4w;
  const V a0 = 1.0 + w;
  const V inv_norm = 1.0 / lane::sqrt(a0 * a0 + (v0 * v0 + v1 * v1 + v2 * v2));
  const V a = a0 * inv_norm, b = v0 * inv_norm, c = v1 * inv_norm, d = v2 * inv_norm;
  LaneMat3<V> half;
  half.a[0][0] = a * a + b * b - c * c - d * d;
  half.a[0][1] = 2.0 * (b * c - a * d);
  half.a[0][2] = 2.0 * (b * d + a * c);
  half.a[1][0] = 2.0 * (b * c + a * d);
  half.a[1][1] = a * a - b * b + c * c - d * d;
  half.a[1][2] = 2.0 * (c * d - a * b);
  half.a[2][0] = 2.0 * (b * d - a * c);
  half.a[2][1] = 2.0 * (c * d + a * b);
  half.a[2][2] = a * a - b * b - c * c + d * d;
  return times(R_old, half);
}

}  // namespace lane_algebra

/// The un-rotations of one Green-Naghdi step from R_n, R_{n+1}, sigma_n and D (both symmetric).
/// A `wide` lane's R_mid and D are not to be used (see CorotatedLanes).
template <class V>
[[gnu::always_inline]] inline CorotatedLanes<V> corotate_lanes(const LaneMat3<V>& R_old,
                                                               const LaneMat3<V>& R_new,
                                                               const LaneMat3<V>& stress,
                                                               const LaneMat3<V>& D) {
  using namespace lane_algebra;
  CorotatedLanes<V> out;
  lane::MaskOf<V> wide;
  out.R_mid = midpoint_lanes(R_old, R_new, wide);
  out.wide = lane::flag<V>(wide);
  out.stress = unrotate_symmetric(stress, R_old);
  out.D = unrotate_symmetric(D, out.R_mid);
  return out;
}

}  // namespace impact

#pragma GCC diagnostic pop
