// Polar decomposition F = R U (Higham's scaled Newton iteration) and the Newton-Schulz nearest
// rotation: the defining properties for random F, the closed-form rotation of simple shear, and the
// exact midpoint rotation of two rotations about one axis.
#include "models/kinematics/polar_decomposition.hpp"

#include "models/kinematics/corotation.hpp"

#include <Eigen/Eigenvalues>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

using namespace impact;

namespace {

// Rotation through angle a about the unit axis n (Rodrigues): I + sin a K + (1 - cos a) K^2.
Mat3 rodrigues(const Vec3& axis, double angle) {
  const Vec3 n = axis.normalized();
  Mat3 K;
  K << 0.0, -n(2), n(1), n(2), 0.0, -n(0), -n(1), n(0), 0.0;
  return Mat3::Identity() + std::sin(angle) * K + (1.0 - std::cos(angle)) * K * K;
}

double orthogonality_error(const Mat3& R) {
  return (R.transpose() * R - Mat3::Identity()).norm();
}

// Checks every property of F = R U; tol is relative to ||F|| for the product.
void check_polar(const Mat3& F, const PolarDecomposition& p, double tol) {
  BOOST_TEST(orthogonality_error(p.R) < tol);
  BOOST_TEST(std::abs(p.R.determinant() - 1.0) < tol);
  BOOST_TEST((p.U - p.U.transpose()).norm() == 0.0);
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(p.U);
  BOOST_TEST(eig.eigenvalues().minCoeff() > 0.0);
  BOOST_TEST((p.R * p.U - F).norm() / F.norm() < tol);
  // U is the SPD square root of C = F^T F.
  BOOST_TEST((p.U * p.U - F.transpose() * F).norm() / (F.transpose() * F).norm() < tol);
  BOOST_TEST(p.iterations <= 30);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(kinematics_polar_decomposition)

BOOST_AUTO_TEST_CASE(random_deformation_gradients_give_a_proper_rotation_times_an_spd_stretch) {
  // Fixed seed. Two families: (1) entries uniform in [-1, 1] with a column flipped if det < 0
  // (condition numbers up to ~1e3 occur; nearly singular draws |det| < 1e-3 are skipped);
  // (2) R1 diag(s) R2 with stretches in [0.1, 10]. Tolerance 1e-13 (round-off is ~1e-15).
  std::mt19937 gen(20040101);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> log_s(std::log(0.1), std::log(10.0));
  int tested = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Mat3 F;
    if (trial % 2 == 0) {
      for (int i = 0; i < 9; ++i) F(i / 3, i % 3) = u(gen);
      if (F.determinant() < 0.0) F.col(0) *= -1.0;
      if (F.determinant() < 1e-3) continue;
    } else {
      const Mat3 R1 = rodrigues(Vec3(u(gen), u(gen), u(gen)), 3.0 * u(gen));
      const Mat3 R2 = rodrigues(Vec3(u(gen), u(gen), u(gen)), 3.0 * u(gen));
      F = R1 * Vec3(std::exp(log_s(gen)), std::exp(log_s(gen)), std::exp(log_s(gen))).asDiagonal() *
          R2;
    }
    check_polar(F, polar_decomposition(F), 1e-13);
    ++tested;
  }
  BOOST_TEST(tested > 300);
}

BOOST_AUTO_TEST_CASE(a_pure_rotation_is_returned_unchanged_with_unit_stretch_in_one_step) {
  const Mat3 Q = rodrigues(Vec3(1.0, -2.0, 0.5), 2.7);
  const PolarDecomposition p = polar_decomposition(Q);
  BOOST_TEST((p.R - Q).norm() < 1e-14);
  BOOST_TEST((p.U - Mat3::Identity()).norm() < 1e-14);
  BOOST_TEST(p.iterations <= 2);
}

BOOST_AUTO_TEST_CASE(simple_shear_rotation_matches_the_closed_form_angle_up_to_gamma_ten) {
  // F = I + gamma e1 (x) e2. Try R = [[c, s, 0], [-s, c, 0], [0, 0, 1]] (c = cos t, s = sin t):
  //   R^T F = [[c, c gamma - s, 0], [s, s gamma + c, 0], [0, 0, 1]],
  // which is symmetric iff c gamma - s = s, i.e. tan t = gamma / 2, and then positive definite
  // (c > 0, det = 1 > 0). By uniqueness of the polar decomposition this is R.
  for (const double gamma : {0.1, 2.0, 10.0}) {
    Mat3 F = Mat3::Identity();
    F(0, 1) = gamma;
    const double t = std::atan(gamma / 2.0);
    Mat3 R_exact;
    R_exact << std::cos(t), std::sin(t), 0.0, -std::sin(t), std::cos(t), 0.0, 0.0, 0.0, 1.0;
    const PolarDecomposition p = polar_decomposition(F);
    BOOST_TEST_CONTEXT("gamma = " << gamma << ", iterations = " << p.iterations) {
      BOOST_TEST((p.R - R_exact).cwiseAbs().maxCoeff() < 1e-14);
      check_polar(F, p, 1e-13);
    }
  }
}

BOOST_AUTO_TEST_CASE(nearest_rotation_of_an_averaged_pair_is_the_rotation_through_the_mean_angle) {
  // (R(a) + R(b))/2 = cos((b - a)/2) R((a + b)/2) for one axis: its orthogonal factor is
  // R((a+b)/2).
  const Vec3 axis(0.3, -0.4, 0.866);
  const double pairs[][2] = {{0.30, 0.31}, {0.3, 0.5}, {-1.0, 1.2}, {2.0, 3.5}};
  for (const auto& ab : pairs) {
    const Mat3 average = 0.5 * (rodrigues(axis, ab[0]) + rodrigues(axis, ab[1]));
    const Mat3 R = nearest_rotation(average);
    BOOST_TEST_CONTEXT("angles " << ab[0] << ", " << ab[1]) {
      BOOST_TEST((R - rodrigues(axis, 0.5 * (ab[0] + ab[1]))).cwiseAbs().maxCoeff() < 1e-14);
      BOOST_TEST(std::abs(R.determinant() - 1.0) < 1e-14);
    }
  }
  // An exact rotation is a fixed point.
  const Mat3 Q = rodrigues(axis, 1.0);
  BOOST_TEST((nearest_rotation(Q) - Q).cwiseAbs().maxCoeff() < 1e-15);
}

BOOST_AUTO_TEST_CASE(nearest_rotation_agrees_with_the_polar_factor_of_a_perturbed_rotation) {
  // Both iterations converge to the same orthogonal polar factor (different algorithms).
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    Mat3 Q = rodrigues(Vec3(u(gen), u(gen), u(gen)), 3.0 * u(gen));
    for (int i = 0; i < 9; ++i) Q(i / 3, i % 3) += 0.05 * u(gen);
    BOOST_TEST((nearest_rotation(Q) - polar_decomposition(Q).R).norm() < 1e-14);
  }
}

BOOST_AUTO_TEST_CASE(warm_started_rotation_equals_the_cold_polar_factor_from_any_guess) {
  // F = R1 diag(s) R2 with stretches in [0.5, 2]; guesses: the answer rotated by 1e-6, 1e-2, 0.5
  // and 3 rad (the last two far: the fallback must still return the polar factor). Near guesses
  // must converge in at most 3 Newton steps; every result is orthogonal to 1e-14.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Mat3 R1 = rodrigues(Vec3(u(gen), u(gen), u(gen)), 3.0 * u(gen));
    const Mat3 R2 = rodrigues(Vec3(u(gen), u(gen), u(gen)), 3.0 * u(gen));
    const Mat3 F =
        R1 *
        Vec3(std::exp(0.7 * u(gen)), std::exp(0.7 * u(gen)), std::exp(0.7 * u(gen))).asDiagonal() *
        R2;
    const Mat3 R = polar_decomposition(F).R;
    for (double angle : {1e-6, 1e-2, 0.5, 3.0}) {
      const Mat3 guess = rodrigues(Vec3(u(gen), u(gen), u(gen)), angle) * R;
      int iterations = 0;
      const Mat3 warm = polar_rotation(F, guess, &iterations);
      BOOST_TEST_CONTEXT("trial " << trial << ", guess off by " << angle << " rad") {
        BOOST_TEST((warm - R).norm() < 1e-13);
        BOOST_TEST((warm.transpose() * warm - Mat3::Identity()).norm() < 1e-14);
        if (angle <= 1e-2) BOOST_TEST(iterations <= 3);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(midpoint_rotation_is_the_half_rotation_for_any_step_angle) {
  // R_old rotated about a fixed axis by a; the midpoint must be R_old rotated by a/2, from tiny
  // steps through the 151-degree switch to the polar factor of the mean.
  const Mat3 R_old = rodrigues(Vec3(0.3, -1.0, 0.4), 0.8);
  const Vec3 axis(1.0, 2.0, 2.0);
  for (double a : {1e-9, 1e-3, 0.3, 2.0, 2.4, 3.0}) {
    const Mat3 mid = midpoint_rotation(R_old, R_old * rodrigues(axis, a));
    BOOST_TEST_CONTEXT("step angle " << a) {
      BOOST_TEST((mid - R_old * rodrigues(axis, 0.5 * a)).norm() < 1e-13);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
