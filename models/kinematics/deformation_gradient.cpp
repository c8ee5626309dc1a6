#include "models/kinematics/deformation_gradient.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace impact {

Mat3 advance_deformation_gradient_exponential(const Mat3& F, const Mat3& L, double dt) {
  const Mat3 A = L * dt;
  return A.exp() * F;
}

Mat3 constant_velocity_gradient(const Mat3& F0, const Mat3& F1, double dt) {
  const Mat3 increment = F1 * F0.inverse();
  const Mat3 log_increment = increment.log();
  return log_increment / dt;
}

}  // namespace impact
