// Small-tensor vocabulary shared by every sub-model. Second-order tensors are Eigen 3x3 matrices;
// stress is Cauchy stress with tension positive. Fourth-order tensors are 9x9 matrices indexed by
// (3i+j, 3k+l), so C_ijkl = T(3*i+j, 3*k+l) and the double contraction C:A is T * vec(A).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>

namespace impact {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;
using Tensor4 = Eigen::Matrix<double, 9, 9>;

/// Mean (hydrostatic) part tr(A)/3.
inline double mean(const Mat3& a) {
  return a.trace() / 3.0;
}

/// Deviatoric part dev A = A - tr(A)/3 I.
inline Mat3 deviator(const Mat3& a) {
  return a - mean(a) * Mat3::Identity();
}

/// Symmetric part (A + A^T)/2: the rate of deformation D of a velocity gradient L.
inline Mat3 sym(const Mat3& a) {
  return 0.5 * (a + a.transpose());
}

/// Skew part (A - A^T)/2: the spin W of a velocity gradient L.
inline Mat3 skew(const Mat3& a) {
  return 0.5 * (a - a.transpose());
}

/// Double contraction A:B = A_ij B_ij.
inline double ddot(const Mat3& a, const Mat3& b) {
  return (a.array() * b.array()).sum();
}

/// von Mises equivalent stress sqrt(3/2 s:s) of a stress tensor (report eq. 6).
inline double von_mises(const Mat3& stress) {
  const Mat3 s = deviator(stress);
  return std::sqrt(1.5 * ddot(s, s));
}

/// Flattening (3i+j) used by Tensor4.
inline Eigen::Matrix<double, 9, 1> flatten(const Mat3& a) {
  Eigen::Matrix<double, 9, 1> v;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v(3 * i + j) = a(i, j);
  return v;
}

inline Mat3 unflatten(const Eigen::Matrix<double, 9, 1>& v) {
  Mat3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a(i, j) = v(3 * i + j);
  return a;
}

/// Isotropic elasticity C = K I(x)I + 2 mu (I_sym - I(x)I/3), with both minor symmetries.
inline Tensor4 isotropic_elasticity(double bulk_modulus, double shear_modulus) {
  Tensor4 c = Tensor4::Zero();
  const double lambda = bulk_modulus - 2.0 * shear_modulus / 3.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          double v = 0.0;
          if (i == j && k == l) v += lambda;
          if (i == k && j == l) v += shear_modulus;
          if (i == l && j == k) v += shear_modulus;
          c(3 * i + j, 3 * k + l) = v;
        }
  return c;
}

}  // namespace impact
