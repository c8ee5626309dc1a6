#include "models/stability/drucker.hpp"

#include <cmath>

namespace impact {

DruckerResult drucker_check(const Tensor4& tangent, const Mat3& D, const Mat3& Dp) {
  const Eigen::Matrix<double, 9, 1> sigma_dot = tangent * flatten(D);
  DruckerResult r;
  r.indicator = flatten(Dp).dot(sigma_dot);
  const bool plastic_loading = (Dp.array() != 0.0).any();
  r.unstable = plastic_loading && r.indicator <= 0.0;
  return r;
}

DruckerResult drucker_check_j2(double bulk_modulus, double shear_modulus, const Mat3& stress,
                               double H, const Mat3& D, const Mat3& Dp) {
  const double lambda = bulk_modulus - 2.0 * shear_modulus / 3.0;
  const double volumetric = lambda * D.trace() * Dp.trace();
  const double shear = shear_modulus * ddot(Dp, D + D.transpose());
  double plastic = 0.0;
  const Mat3 s = deviator(stress);
  const double sigma_eq = std::sqrt(1.5 * ddot(s, s));
  if (sigma_eq != 0.0) {
    const Mat3 N = 1.5 * s / sigma_eq;
    const double factor = 4.0 * shear_modulus * shear_modulus / (3.0 * shear_modulus + H);
    plastic = factor * ddot(N, D) * ddot(N, Dp);
  }
  DruckerResult r;
  r.indicator = volumetric + shear - plastic;
  // Ideal plasticity (H = 0) is the neutral case: the terms cancel and what is left is their
  // round-off. Within kNeutral of the terms' size the verdict is stable, not a failure on noise;
  // a real softening leaves H/(3 mu) of it (1e-12 is H ~ 0.1 Pa for mu = 26 GPa).
  constexpr double kNeutral = 1e-12;
  const double size = std::abs(volumetric) + std::abs(shear) + std::abs(plastic);
  const bool plastic_loading = (Dp.array() != 0.0).any();
  r.unstable = plastic_loading && r.indicator <= 0.0 && -r.indicator > kNeutral * size;
  return r;
}

}  // namespace impact
