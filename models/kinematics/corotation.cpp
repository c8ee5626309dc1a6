#include "models/kinematics/corotation.hpp"

#include "models/kinematics/polar_decomposition.hpp"

namespace impact {

Corotation corotation(const Mat3& R_old, const Mat3& F_new) {
  const Mat3 R_new = polar_decomposition(F_new).R;
  return {R_old, R_new, nearest_rotation(0.5 * (R_old + R_new))};
}

Mat3 hughes_winget_rotation(const Mat3& W, double dt) {
  const Mat3 half = 0.5 * dt * W;
  // I - W dt/2 is never singular for skew W (its eigenvalues are 1 and 1 +- i |w| dt/2).
  return (Mat3::Identity() - half).inverse() * (Mat3::Identity() + half);
}

}  // namespace impact
