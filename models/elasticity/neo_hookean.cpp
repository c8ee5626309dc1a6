#include "models/elasticity/neo_hookean.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace impact {

Mat3 neo_hookean_stress(const Mat3& F, const NeoHookeanModuli& m) {
  const double J = F.determinant();
  const Mat3 b = F * F.transpose();
  return (m.mu * (b - Mat3::Identity()) + m.lambda * std::log(J) * Mat3::Identity()) / J;
}

double neo_hookean_energy(const Mat3& F, const NeoHookeanModuli& m) {
  const double lnJ = std::log(F.determinant());
  const double trC = (F.transpose() * F).trace();
  return 0.5 * m.mu * (trC - 3.0) - m.mu * lnJ + 0.5 * m.lambda * lnJ * lnJ;
}

double neo_hookean_wave_speed(const Mat3& F, const NeoHookeanModuli& m, double rho0) {
  const double J = F.determinant();
  const Mat3 b = F * F.transpose();
  const Eigen::Vector3d stretches =
      Eigen::SelfAdjointEigenSolver<Mat3>(b, Eigen::EigenvaluesOnly).eigenvalues();  // ascending
  const double a = m.lambda + m.mu - m.lambda * std::log(J);
  // Strong ellipticity: every eigenvalue of Q positive, the smallest mu b_min + min(0, a).
  if (!(m.mu * stretches(0) + std::min(0.0, a) > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  return std::sqrt((m.mu * stretches(2) + std::max(0.0, a)) / rho0);
}

}  // namespace impact
