#include "models/kinematics/corotation.hpp"

#include <cmath>

#include "models/kinematics/polar_decomposition.hpp"

namespace impact {

Mat3 midpoint_rotation(const Mat3& R_old, const Mat3& R_new) {
  // Q = R_old^T R_new as a unit quaternion (w, v); its square root is (1 + w, v) normalised.
  const Mat3 Q = R_old.transpose() * R_new;
  const double one_plus_trace = 1.0 + Q.trace();  // = 4 w^2 = 2 + 2 cos(angle)
  if (one_plus_trace < 0.25) {  // step rotation beyond ~130 degrees: w loses digits
    return nearest_rotation(0.5 * (R_old + R_new));
  }
  const double w = 0.5 * std::sqrt(one_plus_trace);
  const Vec3 v = Vec3(Q(2, 1) - Q(1, 2), Q(0, 2) - Q(2, 0), Q(1, 0) - Q(0, 1)) / (4.0 * w);
  const double a0 = 1.0 + w;
  const double norm = std::sqrt(a0 * a0 + v.squaredNorm());
  const double a = a0 / norm, b = v(0) / norm, c = v(1) / norm, d = v(2) / norm;
  Mat3 half;
  half << a * a + b * b - c * c - d * d, 2.0 * (b * c - a * d), 2.0 * (b * d + a * c),
      2.0 * (b * c + a * d), a * a - b * b + c * c - d * d, 2.0 * (c * d - a * b),
      2.0 * (b * d - a * c), 2.0 * (c * d + a * b), a * a - b * b - c * c + d * d;
  return R_old * half;
}

Corotation corotation(const Mat3& R_old, const Mat3& F_new) {
  const Mat3 R_new = polar_rotation(F_new, R_old);
  return {R_old, R_new, midpoint_rotation(R_old, R_new)};
}

Vec3 green_naghdi_spin(const Mat3& L, const Mat3& V) {
  const Mat3 LV = L * V;
  const Vec3 z(LV(2, 1) - LV(1, 2), LV(0, 2) - LV(2, 0), LV(1, 0) - LV(0, 1));  // 2 axial(skew LV)
  const Mat3 A = V.trace() * Mat3::Identity() - V;
  return A.inverse() * z;
}

Corotation incremental_corotation(const Mat3& R_old, const Mat3& F_old, const Mat3& F_new,
                                  const Mat3& L, double dt) {
  const Vec3 w0 = green_naghdi_spin(L, sym(F_old * R_old.transpose()));
  const Mat3 R_pred = cayley_rotation(0.5 * dt * w0) * R_old;
  const Vec3 w1 = green_naghdi_spin(L, sym(F_new * R_pred.transpose()));
  const Vec3 w = 0.5 * (w0 + w1);
  return {R_old, cayley_rotation(0.5 * dt * w) * R_old, cayley_rotation(0.25 * dt * w) * R_old};
}

Mat3 hughes_winget_rotation(const Mat3& W, double dt) {
  const Mat3 half = 0.5 * dt * W;
  // I - W dt/2 is never singular for skew W (its eigenvalues are 1 and 1 +- i |w| dt/2).
  return (Mat3::Identity() - half).inverse() * (Mat3::Identity() + half);
}

}  // namespace impact
