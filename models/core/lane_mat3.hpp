// A 3x3 matrix whose entries are one point's doubles (V = double) or a vector of points' (V =
// lane::Vec), and the small algebra the constitutive step needs on it, spelt out entry by entry in
// a fixed order: Eigen's fixed-size matrices do not take a vector as scalar, and a fixed order is
// what gives a point the same bits alone (the point driver) and in a vector (the MPM's batches).
#pragma once

#include "models/core/lane_math.hpp"
#include "models/core/tensor.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace impact {

/// A 3x3 matrix of lanes, row-major.
template <class V>
struct alignas(lane::kLaneBytes) LaneMat3 {
  V a[3][3];
};

/// One point's Eigen matrix as a one-lane LaneMat3, and back.
inline LaneMat3<double> to_lanes(const Mat3& A) {
  LaneMat3<double> L;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) L.a[i][j] = A(i, j);
  return L;
}
inline Mat3 to_mat3(const LaneMat3<double>& L) {
  Mat3 A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = L.a[i][j];
  return A;
}

namespace lane_algebra {

#define IMPACT_LANE_INLINE [[gnu::always_inline]] inline

/// A^T B.
template <class V>
IMPACT_LANE_INLINE LaneMat3<V> transpose_times(const LaneMat3<V>& A, const LaneMat3<V>& B) {
  LaneMat3<V> C;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      C.a[i][j] = A.a[0][i] * B.a[0][j] + A.a[1][i] * B.a[1][j] + A.a[2][i] * B.a[2][j];
  return C;
}

/// A B.
template <class V>
IMPACT_LANE_INLINE LaneMat3<V> times(const LaneMat3<V>& A, const LaneMat3<V>& B) {
  LaneMat3<V> C;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      C.a[i][j] = A.a[i][0] * B.a[0][j] + A.a[i][1] * B.a[1][j] + A.a[i][2] * B.a[2][j];
  return C;
}

/// det A by the first row's cofactors.
template <class V>
IMPACT_LANE_INLINE V determinant(const LaneMat3<V>& A) {
  return A.a[0][0] * (A.a[1][1] * A.a[2][2] - A.a[1][2] * A.a[2][1]) -
         A.a[0][1] * (A.a[1][0] * A.a[2][2] - A.a[1][2] * A.a[2][0]) +
         A.a[0][2] * (A.a[1][0] * A.a[2][1] - A.a[1][1] * A.a[2][0]);
}

template <class V>
IMPACT_LANE_INLINE V trace(const LaneMat3<V>& A) {
  return A.a[0][0] + A.a[1][1] + A.a[2][2];
}

/// A:B = A_ij B_ij, summed row by row.
template <class V>
IMPACT_LANE_INLINE V ddot(const LaneMat3<V>& A, const LaneMat3<V>& B) {
  V sum = A.a[0][0] * B.a[0][0];
  for (int k = 1; k < 9; ++k) sum = sum + A.a[k / 3][k % 3] * B.a[k / 3][k % 3];
  return sum;
}

/// dev A = A - tr(A)/3 I.
template <class V>
IMPACT_LANE_INLINE LaneMat3<V> deviator(const LaneMat3<V>& A) {
  const V m = trace(A) / 3.0;
  LaneMat3<V> C = A;
  for (int i = 0; i < 3; ++i) C.a[i][i] = A.a[i][i] - m;
  return C;
}

/// von Mises equivalent sqrt(3/2 s:s) of a deviator s (report eq. 6).
template <class V>
IMPACT_LANE_INLINE V equivalent_of_deviator(const LaneMat3<V>& s) {
  return lane::sqrt(V(1.5 * ddot(s, s)));
}

/// R^T A R for a symmetric A: lab frame -> unrotated frame, upper triangle computed and mirrored.
template <class V>
IMPACT_LANE_INLINE LaneMat3<V> unrotate_symmetric(const LaneMat3<V>& A, const LaneMat3<V>& R) {
  const LaneMat3<V> AR = times(A, R);
  LaneMat3<V> C;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      C.a[i][j] = R.a[0][i] * AR.a[0][j] + R.a[1][i] * AR.a[1][j] + R.a[2][i] * AR.a[2][j];
      C.a[j][i] = C.a[i][j];
    }
  return C;
}

/// R A R^T for a symmetric A: unrotated frame -> lab frame, upper triangle computed and mirrored.
template <class V>
IMPACT_LANE_INLINE LaneMat3<V> rotate_symmetric(const LaneMat3<V>& A, const LaneMat3<V>& R) {
  LaneMat3<V> RA = times(R, A);
  LaneMat3<V> C;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      C.a[i][j] = RA.a[i][0] * R.a[j][0] + RA.a[i][1] * R.a[j][1] + RA.a[i][2] * R.a[j][2];
      C.a[j][i] = C.a[i][j];
    }
  return C;
}

#undef IMPACT_LANE_INLINE

}  // namespace lane_algebra

}  // namespace impact

#pragma GCC diagnostic pop
