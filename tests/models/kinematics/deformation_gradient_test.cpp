// Advancing F with dF/dt = L F: the exponential is exact for a constant spin (Rodrigues), forward
// Euler inflates a spinning point by a closed-form factor per step, and constant_velocity_gradient
// inverts the exponential update.
#include "models/kinematics/deformation_gradient.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

using namespace impact;

namespace {

// Skew matrix K with K v = n x v.
Mat3 cross_matrix(const Vec3& n) {
  Mat3 K;
  K << 0.0, -n(2), n(1), n(2), 0.0, -n(0), -n(1), n(0), 0.0;
  return K;
}

// Rotation through angle a about the unit axis n (Rodrigues): I + sin a K + (1 - cos a) K^2.
Mat3 rodrigues(const Vec3& axis, double angle) {
  const Mat3 K = cross_matrix(axis.normalized());
  return Mat3::Identity() + std::sin(angle) * K + (1.0 - std::cos(angle)) * K * K;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(kinematics_deformation_gradient)

BOOST_AUTO_TEST_CASE(exponential_update_of_a_constant_spin_reproduces_the_rodrigues_rotation) {
  // W = omega K(n): F(t) = exp(W t) = rotation through omega t about n. 2000 steps to 5 rad.
  // Tolerance 1e-12 on every entry (each step adds ~1e-16; observed ~1e-14).
  const Vec3 n = Vec3(1.0, 2.0, -2.0) / 3.0;
  const double omega = 5.0e4;  // [rad/s]
  const int steps = 2000;
  const double dt = 5.0 / omega / steps;
  const Mat3 W = omega * cross_matrix(n);
  Mat3 F = Mat3::Identity();
  for (int k = 0; k < steps; ++k)
    F = advance_deformation_gradient(F, W, dt, FIntegration::exponential);
  const Mat3 exact = rodrigues(n, omega * steps * dt);
  BOOST_TEST_MESSAGE("exponential, 2000 spin steps: max entry error "
                     << (F - exact).cwiseAbs().maxCoeff());
  BOOST_TEST((F - exact).cwiseAbs().maxCoeff() < 1e-12);
  BOOST_TEST(std::abs(F.determinant() - 1.0) < 1e-12);
}

BOOST_AUTO_TEST_CASE(forward_euler_of_a_constant_spin_inflates_by_the_closed_form_factor) {
  // Spin about e3: I + W dt = [[1, -w dt, 0], [w dt, 1, 0], [0, 0, 1]] = a Q(phi) (+) 1 in the
  // (e1, e2) plane, with a = sqrt(1 + (w dt)^2) and tan(phi) = w dt. After n steps
  //   F = a^n Q(n phi) (+) 1,  det F = (1 + (w dt)^2)^n,  |F e1| = (1 + (w dt)^2)^(n/2),
  // while the exact motion is the rotation through n w dt with det = 1. (The in-plane stretch
  // grows like (1 + (w dt)^2)^(n/2); the determinant, the product of two such stretches, like the
  // n-th power.) Tolerance 1e-12 relative (round-off over n steps).
  const double omega = 1.0e4, dt = 2.0e-6;  // w dt = 0.02
  const int steps = 5000;                   // 100 rad, ~16 turns
  Mat3 W = Mat3::Zero();
  W(0, 1) = -omega;
  W(1, 0) = omega;
  Mat3 F = Mat3::Identity();
  for (int k = 0; k < steps; ++k)
    F = advance_deformation_gradient(F, W, dt, FIntegration::forward_euler);
  const double wdt2 = (omega * dt) * (omega * dt);
  const double det_exact = std::pow(1.0 + wdt2, steps);  // 7.39: the point gained 639 % volume
  const double stretch = std::pow(1.0 + wdt2, 0.5 * steps);
  const double phi = steps * std::atan(omega * dt);
  BOOST_TEST_MESSAGE("forward Euler spin: det F = " << F.determinant() << " (closed form "
                                                    << det_exact << ")");
  BOOST_TEST(std::abs(F.determinant() / det_exact - 1.0) < 1e-12);
  BOOST_TEST(std::abs(F.col(0).norm() / stretch - 1.0) < 1e-12);
  Mat3 closed = Mat3::Identity();
  closed.topLeftCorner<2, 2>() << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  closed.topLeftCorner<2, 2>() *= stretch;
  BOOST_TEST((F - closed).norm() / F.norm() < 1e-12);
  BOOST_TEST(F.determinant() > 7.0);  // the drift is large, not a round-off effect
}

BOOST_AUTO_TEST_CASE(forward_euler_is_exact_for_simple_shear) {
  // L = gdot e1 (x) e2 has L^2 = 0 and L F = L for F = I + gamma e1 (x) e2, so (I + L dt) F is the
  // exact F(t + dt) = I + (gamma + gdot dt) e1 (x) e2. 4096 steps of dt = 2^-11 reach gamma = 2.
  Mat3 L = Mat3::Zero();
  L(0, 1) = 1.0;
  Mat3 F = Mat3::Identity();
  for (int k = 0; k < 4096; ++k)
    F = advance_deformation_gradient(F, L, 1.0 / 2048, FIntegration::forward_euler);
  Mat3 exact = Mat3::Identity();
  exact(0, 1) = 2.0;
  BOOST_TEST((F == exact));  // dyadic steps: exact in binary
}

BOOST_AUTO_TEST_CASE(constant_velocity_gradient_inverts_the_exponential_update) {
  // Random L (rotation part below pi per step) and random F0 with det > 0; tolerance 1e-12
  // relative to |L|.
  std::mt19937 gen(1979);
  double worst = 0.0;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    Mat3 L, F0;
    for (int i = 0; i < 9; ++i) L(i / 3, i % 3) = 1.0e3 * u(gen);  // [1/s]
    F0 = Mat3::Identity();
    for (int i = 0; i < 9; ++i) F0(i / 3, i % 3) += 0.4 * u(gen);
    if (F0.determinant() < 0.1) continue;
    const double dt = 1.0e-3;  // |L dt| ~ 1
    const Mat3 F1 = advance_deformation_gradient(F0, L, dt, FIntegration::exponential);
    const Mat3 L_back = constant_velocity_gradient(F0, F1, dt);
    worst = std::max(worst, (L_back - L).norm() / L.norm());
  }
  BOOST_TEST_MESSAGE("logm inversion: worst relative error " << worst);
  BOOST_TEST(worst < 1e-12);
  // And for a known case: pure rotation through 1 rad about n in 2 ms gives L = (1/2e-3) K(n).
  const Vec3 n = Vec3(2.0, -1.0, 2.0) / 3.0;
  const Mat3 L = constant_velocity_gradient(Mat3::Identity(), rodrigues(n, 1.0), 2.0e-3);
  BOOST_TEST((L - 500.0 * cross_matrix(n)).norm() / 500.0 < 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
