#include "models/stability/drucker.hpp"

namespace impact {

DruckerResult drucker_check(const Tensor4& tangent, const Mat3& D, const Mat3& Dp) {
  const Eigen::Matrix<double, 9, 1> sigma_dot = tangent * flatten(D);
  DruckerResult r;
  r.indicator = flatten(Dp).dot(sigma_dot);
  const bool plastic_loading = (Dp.array() != 0.0).any();
  r.unstable = plastic_loading && r.indicator <= 0.0;
  return r;
}

}  // namespace impact
