// The compressible neo-Hookean law (models/elasticity/neo_hookean.hpp) against what defines it,
// independently of its formulas: the Cauchy stress is the derivative of the stored energy,
// sigma = (1/J) dW/dF F^T (central differences of W, which is checked against its own definition
// on simple shear); it is objective; at small strain it is Hooke's law with mu and lambda; its
// wave-speed bound holds every acoustic-tensor eigenvalue computed from differences of the
// first Piola-Kirchhoff stress; the material file's type selects it and refuses the
// elastic-plastic keys it would ignore.
#include "models/elasticity/neo_hookean.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>
#include <string>

#include "models/material/material.hpp"

using namespace impact;

namespace {

const NeoHookeanModuli kModuli{3.846e6, 5.769e6};  // E = 1e7 Pa, nu = 0.3

Mat3 random_deformation(std::mt19937_64& gen, double size) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mat3 F = Mat3::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F(i, j) += size * u(gen);
  return F;
}

// dW/dF by central differences of W [Pa]: the first Piola-Kirchhoff stress.
Mat3 piola_by_differences(const Mat3& F) {
  Mat3 P;
  const double h = 1e-6;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Mat3 Fp = F, Fm = F;
      Fp(i, j) += h;
      Fm(i, j) -= h;
      P(i, j) = (neo_hookean_energy(Fp, kModuli) - neo_hookean_energy(Fm, kModuli)) / (2.0 * h);
    }
  return P;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(neo_hookean)

BOOST_AUTO_TEST_CASE(the_energy_is_its_definition_on_simple_shear_and_dilatation) {
  BOOST_TEST(neo_hookean_energy(Mat3::Identity(), kModuli) == 0.0);
  for (const double s : {0.7, 1.3}) {  // F = s I: tr C - 3 = 3 (s^2 - 1), ln J = 3 ln s
    const double lnJ = 3.0 * std::log(s);
    const double W =
        1.5 * kModuli.mu * (s * s - 1.0) - kModuli.mu * lnJ + 0.5 * kModuli.lambda * lnJ * lnJ;
    BOOST_TEST(neo_hookean_energy(s * Mat3::Identity(), kModuli) == W,
               boost::test_tools::tolerance(1e-13));
  }
  Mat3 F = Mat3::Identity();
  F(0, 1) = 1.5;  // J = 1, tr C - 3 = gamma^2: W = mu gamma^2 / 2
  BOOST_TEST(neo_hookean_energy(F, kModuli) == 0.5 * kModuli.mu * 2.25,
             boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(the_stress_is_the_derivative_of_the_stored_energy_at_large_strain) {
  std::mt19937_64 gen(3);
  for (int n = 0; n < 20; ++n) {
    const Mat3 F = random_deformation(gen, 0.4);
    if (F.determinant() < 0.3) continue;
    const Mat3 expected = piola_by_differences(F) * F.transpose() / F.determinant();
    const Mat3 sigma = neo_hookean_stress(F, kModuli);
    BOOST_TEST_INFO("F = " << F << ", J = " << F.determinant());
    BOOST_TEST((sigma - expected).norm() <= 1e-6 * expected.norm());
    BOOST_TEST((sigma - sigma.transpose()).norm() <= 1e-12 * sigma.norm());
  }
}

BOOST_AUTO_TEST_CASE(the_stress_is_objective) {
  std::mt19937_64 gen(5);
  for (int n = 0; n < 10; ++n) {
    const Mat3 F = random_deformation(gen, 0.3);
    const Mat3 Q = Eigen::AngleAxisd(0.3 + n, Eigen::Vector3d(1.0, 2.0, -0.5 * n).normalized())
                       .toRotationMatrix();
    const Mat3 sigma = neo_hookean_stress(F, kModuli);
    const Mat3 rotated = neo_hookean_stress(Q * F, kModuli);
    BOOST_TEST((rotated - Q * sigma * Q.transpose()).norm() <= 1e-12 * sigma.norm());
  }
}

BOOST_AUTO_TEST_CASE(at_small_strain_it_is_hookes_law_with_mu_and_lambda) {
  std::mt19937_64 gen(9);
  const Mat3 grad = random_deformation(gen, 1.0) - Mat3::Identity();
  for (const double size : {1e-4, 1e-5}) {
    const Mat3 F = Mat3::Identity() + size * grad;
    const Mat3 eps = 0.5 * size * (grad + grad.transpose());
    const Mat3 hooke = kModuli.lambda * eps.trace() * Mat3::Identity() + 2.0 * kModuli.mu * eps;
    // The difference is second order in the strain.
    BOOST_TEST((neo_hookean_stress(F, kModuli) - hooke).norm() <= 10.0 * size * hooke.norm());
  }
}

// The first Piola-Kirchhoff stress written from W by hand, P = mu (F - F^-T) + lambda ln J F^-T
// (Bonet & Wood 2008, eq. 6.28), for the acoustic tensor's differences (less noise than second
// differences of W).
Mat3 piola(const Mat3& F) {
  const Mat3 FinvT = F.inverse().transpose();
  return kModuli.mu * (F - FinvT) + kModuli.lambda * std::log(F.determinant()) * FinvT;
}

// rho c^2 along a spatial direction m are the eigenvalues of the spatial acoustic tensor
// Q_ik(m) = (1/J) A_iJkL (F^T m)_J (F^T m)_L, A = dP/dF (it holds the initial-stress term; Ogden
// 1984, Non-linear Elastic Deformations, sec. 6.2.7); A's columns by differences of P.
BOOST_AUTO_TEST_CASE(the_wave_speed_bound_holds_every_direction_and_is_exact_at_rest) {
  const double rho0 = 1000.0;
  const double at_rest = neo_hookean_wave_speed(Mat3::Identity(), kModuli, rho0);
  BOOST_TEST(at_rest == std::sqrt((kModuli.lambda + 2.0 * kModuli.mu) / rho0),
             boost::test_tools::tolerance(1e-14));
  std::mt19937_64 gen(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 0; n < 10; ++n) {
    const Mat3 F = random_deformation(gen, 0.3);
    const double J = F.determinant();
    const double bound = neo_hookean_wave_speed(F, kModuli, rho0);
    // b's largest principal direction first: there the longitudinal wave is the fastest.
    const Eigen::SelfAdjointEigenSolver<Mat3> b(F * F.transpose());
    for (int k = 0; k < 20; ++k) {
      Eigen::Vector3d m(u(gen), u(gen), u(gen));
      if (k == 0) m = b.eigenvectors().col(2);
      m.normalize();
      Mat3 Q = Mat3::Zero();
      const double h = 1e-6;
      for (int c = 0; c < 3; ++c) {
        // dP in the direction e_c (x) F^T m; Q's column c is dP F^T m / J.
        const Mat3 dF = Eigen::Vector3d::Unit(c) * (F.transpose() * m).transpose();
        const Mat3 dP = (piola(F + h * dF) - piola(F - h * dF)) / (2.0 * h);
        Q.col(c) = dP * (F.transpose() * m) / J;
      }
      const double largest =
          Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (Q + Q.transpose())).eigenvalues().maxCoeff();
      const double c2 = largest / (rho0 / J);
      BOOST_TEST_INFO("F = " << F << ", m = " << m.transpose());
      BOOST_TEST(c2 <= bound * bound * (1.0 + 1e-4));
      if (k == 0) BOOST_TEST(c2 == bound * bound, boost::test_tools::tolerance(1e-4));
    }
  }
}

BOOST_AUTO_TEST_CASE(the_material_type_selects_it_and_refuses_the_keys_it_would_ignore) {
  const std::string file = std::string(IMPACT_SOURCE_DIR) + "/data/materials/neo_hookean_soft.json";
  const Material soft = load_material(file);
  BOOST_TEST(soft.model.hyperelastic());
  // The file's E = 1e7 Pa, nu = 0.3: lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)).
  BOOST_TEST(soft.model.neo_hookean_moduli().lambda == 1e7 * 0.3 / (1.3 * 0.4),
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(soft.model.neo_hookean_moduli().mu == 1e7 / 2.6, boost::test_tools::tolerance(1e-12));
  // Its writer's output reads back the same law.
  const Material again = read_material(to_json(soft), file);
  BOOST_TEST(again.model.hyperelastic());
  BOOST_TEST(again.model.params().shear_modulus == soft.model.params().shear_modulus);
  for (const char* patch :
       {R"({"constitutive_model": {"flow_stress": {"A": 1e8}}})", R"({"melt_temperature": 925.0})",
        R"({"specific_heat": 900.0})", R"({"bulk_modulus": 2.0e6})"}) {  // lambda < 0, nu = -0.11
    BOOST_TEST_INFO(patch);
    BOOST_CHECK_THROW(load_material(file, Json::parse(patch)), InputError);
  }
  try {
    load_material(file, Json::parse(R"({"constitutive_model": {"flow_stress": {"A": 1e8}}})"));
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("/constitutive_model/flow_stress") != std::string::npos);
  }
}

BOOST_AUTO_TEST_SUITE_END()
