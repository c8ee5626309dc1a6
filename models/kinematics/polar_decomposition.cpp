#include "models/kinematics/polar_decomposition.hpp"

#include "models/kinematics/polar_rotation_lanes.hpp"

#include <cmath>
#include <limits>

namespace impact {

namespace {

// Cofactor matrix: X^{-T} = cof(X) / det X. Written out so the Newton step needs no pivoting.
Mat3 cofactor(const Mat3& x) {
  Mat3 c;
  c(0, 0) = x(1, 1) * x(2, 2) - x(1, 2) * x(2, 1);
  c(0, 1) = x(1, 2) * x(2, 0) - x(1, 0) * x(2, 2);
  c(0, 2) = x(1, 0) * x(2, 1) - x(1, 1) * x(2, 0);
  c(1, 0) = x(0, 2) * x(2, 1) - x(0, 1) * x(2, 2);
  c(1, 1) = x(0, 0) * x(2, 2) - x(0, 2) * x(2, 0);
  c(1, 2) = x(0, 1) * x(2, 0) - x(0, 0) * x(2, 1);
  c(2, 0) = x(0, 1) * x(1, 2) - x(0, 2) * x(1, 1);
  c(2, 1) = x(0, 2) * x(1, 0) - x(0, 0) * x(1, 2);
  c(2, 2) = x(0, 0) * x(1, 1) - x(0, 1) * x(1, 0);
  return c;
}

}  // namespace

PolarDecomposition polar_decomposition(const Mat3& F) {
  constexpr int max_iterations = 30;
  // Quadratic convergence: once a step changes X by delta (relative), the error left in the new
  // iterate is ~delta^2/2, so delta <= 1e-8 already means ~1e-16. Stopping there avoids waiting for
  // a step size below round-off, which may never come.
  constexpr double quadratic_stop = 1e-8;
  constexpr double tolerance = 1e-15;
  Mat3 X = F;
  int k = 0;
  while (k < max_iterations) {
    const Mat3 inv_t = cofactor(X) / X.determinant();  // X^{-T}
    const double g = std::sqrt(inv_t.norm() / X.norm());
    const Mat3 next = 0.5 * (g * X + inv_t / g);
    const double delta = (next - X).norm() / next.norm();
    X = next;
    ++k;
    if (delta <= quadratic_stop || delta <= tolerance) break;
  }
  // U = R^T F is symmetric to round-off; symmetrize so the caller gets an exactly symmetric U.
  return {X, sym(X.transpose() * F), k};
}

Mat3 polar_rotation(const Mat3& F, const Mat3& guess, int* iterations) {
  // The lanes' algorithm on one point (polar_rotation_lanes.hpp): the batched update's rotation
  // gives the same bits.
  const PolarLanes<double> warm = polar_rotation_lanes(to_lanes(F), to_lanes(guess));
  if (warm.converged != 0) {
    const Mat3 R = to_mat3(warm.R);
    if (iterations) *iterations = static_cast<int>(warm.iterations);
    return R;
  }
  constexpr int max_iterations = 8;
  const PolarDecomposition pd = polar_decomposition(F);
  if (iterations) *iterations = max_iterations + pd.iterations;
  return pd.R;
}

Mat3 cayley_rotation(const Vec3& c) {
  Mat3 K;
  K << 0.0, -c(2), c(1), c(2), 0.0, -c(0), -c(1), c(0), 0.0;
  return Mat3::Identity() + (2.0 / (1.0 + c.squaredNorm())) * (K + K * K);
}

Mat3 nearest_rotation(const Mat3& Q) {
  constexpr int max_iterations = 20;
  constexpr double tolerance = 1e-15;
  Mat3 X = Q;
  double previous = std::numeric_limits<double>::infinity();
  for (int k = 0; k < max_iterations; ++k) {
    const Mat3 E = X.transpose() * X - Mat3::Identity();
    const double e = E.norm();
    // Stop at the tolerance, or when round-off (not the iteration) sets the size of E: near
    // convergence each step must at least halve it.
    if (e < tolerance || (e < 1e-12 && e > 0.5 * previous)) break;
    previous = e;
    // X (3I - X^T X)/2 = X (I - E/2): the correction form loses no digits to cancellation.
    X -= 0.5 * X * E;
  }
  return X;
}

}  // namespace impact
