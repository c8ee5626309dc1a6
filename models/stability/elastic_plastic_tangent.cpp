#include "models/stability/elastic_plastic_tangent.hpp"

namespace impact {

Tensor4 elastic_plastic_tangent(double bulk_modulus, double shear_modulus, const Mat3& stress,
                                double H) {
  Tensor4 c = isotropic_elasticity(bulk_modulus, shear_modulus);
  const Mat3 s = deviator(stress);
  const double sigma_eq = std::sqrt(1.5 * ddot(s, s));
  if (sigma_eq == 0.0) return c;
  const Eigen::Matrix<double, 9, 1> n = flatten(1.5 * s / sigma_eq);
  // (2 mu)^2 / (3 mu + H); H = +inf gives 0, i.e. C^e.
  const double factor = 4.0 * shear_modulus * shear_modulus / (3.0 * shear_modulus + H);
  // n_a n_b formed before scaling, so the tangent is exactly (bitwise) symmetric.
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b < 9; ++b) c(a, b) -= factor * (n(a) * n(b));
  return c;
}

double effective_hardening(const FlowSlopes& slopes, double flow_stress, double dt,
                           RateSlope rate_slope, bool adiabatic, double taylor_quinney,
                           double density, double specific_heat) {
  double H = slopes.d_plastic_strain;
  if (rate_slope == RateSlope::algorithmic) H += slopes.d_rate / dt;
  if (adiabatic) {
    // dT/d eps_p = chi sigma_y / (rho cp), report eq. (8).
    H += slopes.d_temperature * taylor_quinney * flow_stress / (density * specific_heat);
  }
  return H;
}

}  // namespace impact
