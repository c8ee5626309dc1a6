#include "models/kinematics/corotation.hpp"

#include <cmath>

#include "models/kinematics/corotation_lanes.hpp"
#include "models/kinematics/polar_decomposition.hpp"

namespace impact {

Mat3 midpoint_rotation(const Mat3& R_old, const Mat3& R_new) {
  bool wide = false;
  const Mat3 R_mid = to_mat3(lane_algebra::midpoint_lanes(to_lanes(R_old), to_lanes(R_new), wide));
  // Beyond a ~151-degree step w = cos(angle / 2) loses digits: the polar factor of the mean.
  return wide ? nearest_rotation(0.5 * (R_old + R_new)) : R_mid;
}

Corotated corotate(const Mat3& R_old, const Mat3& R_new, const Mat3& stress, const Mat3& D) {
  const CorotatedLanes<double> c =
      corotate_lanes(to_lanes(R_old), to_lanes(R_new), to_lanes(stress), to_lanes(D));
  if (c.wide == 0) return {R_new, to_mat3(c.R_mid), to_mat3(c.stress), to_mat3(c.D)};
  const Mat3 R_mid = midpoint_rotation(R_old, R_new);
  return {R_new, R_mid, to_mat3(c.stress),
          to_mat3(lane_algebra::unrotate_symmetric(to_lanes(D), to_lanes(R_mid)))};
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
