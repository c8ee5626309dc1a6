// Drucker's postulate (report eq. 10) with the consistent J2 tangent and 6061-T6 Johnson-Cook
// slopes computed by hand here: it fires under adiabatic thermal softening and not under isothermal
// hardening in uniaxial plastic loading, its indicator equals H eps_dot_p eps_dot_c (H eps_dot_p^2
// for the tangent's own plastic rate), and it needs plastic flow.
#include "models/stability/drucker.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "helpers/finite_difference.hpp"
#include "models/stability/elastic_plastic_tangent.hpp"

using namespace impact;
using impact::testing::central_difference;
using impact::testing::relative_difference;

namespace {

// 6061-T6 (report Table 1).
constexpr double kK = 66.4e9, kMu = 26e9;
constexpr double kA = 324e6, kB = 114e6, kN = 0.42, kM = 1.34, kTr = 294.0, kTm = 925.0;
constexpr double kChi = 0.9, kRho = 2700.0, kCp = 896.0;

// Johnson-Cook without the rate term, written out here: sigma_y = (A + B ep^n)(1 - T*^m).
double homologous(double T) {
  return (T - kTr) / (kTm - kTr);
}
double jc(double ep, double T) {
  return (kA + kB * std::pow(ep, kN)) * (1.0 - std::pow(homologous(T), kM));
}
double jc_d_ep(double ep, double T) {
  return kB * kN * std::pow(ep, kN - 1.0) * (1.0 - std::pow(homologous(T), kM));
}
double jc_d_T(double ep, double T) {
  return -(kA + kB * std::pow(ep, kN)) * kM * std::pow(homologous(T), kM - 1.0) / (kTm - kTr);
}

// H by hand: strain hardening plus, if adiabatic, d_T * dT/d ep = d_T chi sigma_y / (rho cp).
double hand_H(double ep, double T, bool adiabatic) {
  return jc_d_ep(ep, T) + (adiabatic ? jc_d_T(ep, T) * kChi * jc(ep, T) / (kRho * kCp) : 0.0);
}

// Uniaxial stress sigma e1 (x) e1 loading plastically at rate eps_dot_p with slope H: the stress
// rate is sigma_dot = H eps_dot_p e1 (x) e1 (sigma_eq = sigma_11), the elastic part of D is
// sigma_dot/E along e1 and -nu sigma_dot/E across, and D^p = eps_dot_p diag(1, -1/2, -1/2).
struct Uniaxial {
  Mat3 stress, D, Dp, stress_rate;
};
Uniaxial uniaxial(double sigma, double H, double eps_dot_p) {
  const double E = 9.0 * kK * kMu / (3.0 * kK + kMu);
  const double nu = (3.0 * kK - 2.0 * kMu) / (2.0 * (3.0 * kK + kMu));
  const double rate = H * eps_dot_p;
  Uniaxial u;
  u.stress = Mat3::Zero();
  u.stress(0, 0) = sigma;
  u.Dp = eps_dot_p * Vec3(1.0, -0.5, -0.5).asDiagonal();
  u.D = u.Dp;
  u.D(0, 0) += rate / E;
  u.D(1, 1) -= nu * rate / E;
  u.D(2, 2) -= nu * rate / E;
  u.stress_rate = Mat3::Zero();
  u.stress_rate(0, 0) = rate;
  return u;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stability_drucker)

BOOST_AUTO_TEST_CASE(hand_johnson_cook_slopes_match_central_differences) {
  // Guards the reference of the other cases. Relative 1e-7 (step 1e-6 relative).
  for (double ep : {0.1, 0.3, 0.5})
    for (double T : {400.0, 600.0, 700.0}) {
      const double d_ep = central_difference([&](double e) { return jc(e, T); }, ep);
      const double d_T = central_difference([&](double t) { return jc(ep, t); }, T);
      BOOST_TEST(relative_difference(jc_d_ep(ep, T), d_ep) < 1e-7);
      BOOST_TEST(relative_difference(jc_d_T(ep, T), d_T) < 1e-7);
    }
}

BOOST_AUTO_TEST_CASE(fires_under_adiabatic_thermal_softening_in_uniaxial_plastic_loading) {
  // eps_p = 0.5, T = 600 K: sigma_y = 254.05 MPa, d_ep = 44.44 MPa, d_T = -0.6794 MPa/K,
  // dT/d eps_p = chi sigma_y / (rho cp) = 94.5 K, so H = 44.44 - 64.22 = -19.78 MPa < 0.
  // (At eps_p = 0.3, 600 K, H = +0.60 MPa: still just stable; see the threshold case below.)
  const double ep = 0.5, T = 600.0, eps_dot_p = 1e3;
  const double H = hand_H(ep, T, true);
  BOOST_TEST(H < -19e6);
  const double H_lib = effective_hardening({jc_d_ep(ep, T), 0.0, jc_d_T(ep, T)}, jc(ep, T), 1e-8,
                                           RateSlope::constant_rate, true, kChi, kRho, kCp);
  BOOST_TEST(H_lib == H, boost::test_tools::tolerance(1e-12));

  const Uniaxial u = uniaxial(jc(ep, T), H, eps_dot_p);
  const Tensor4 c = elastic_plastic_tangent(kK, kMu, u.stress, H);
  // The tangent reproduces the uniaxial stress rate (lateral rates vanish): round-off relative to
  // the elastic stress rate 3 mu eps_dot_p, 1e-12.
  const Mat3 rate = unflatten(c * flatten(u.D));
  BOOST_TEST((rate - u.stress_rate).cwiseAbs().maxCoeff() / (3.0 * kMu * eps_dot_p) < 1e-12);

  const DruckerResult r = drucker_check(c, u.D, u.Dp);
  // sigma_dot : D^p = H eps_dot_p^2. Tolerance 1e-10 relative (round-off times 3 mu / |H| ~ 4e3).
  BOOST_TEST(r.indicator == H * eps_dot_p * eps_dot_p, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(r.indicator < 0.0);
  BOOST_TEST(r.unstable);
}

BOOST_AUTO_TEST_CASE(does_not_fire_under_isothermal_strain_hardening) {
  const double ep = 0.5, T = 600.0, eps_dot_p = 1e3;
  const double H = hand_H(ep, T, false);  // = d_ep = 44.44 MPa
  BOOST_TEST(H > 44e6);
  const Uniaxial u = uniaxial(jc(ep, T), H, eps_dot_p);
  const DruckerResult r = drucker_check(elastic_plastic_tangent(kK, kMu, u.stress, H), u.D, u.Dp);
  BOOST_TEST(r.indicator == H * eps_dot_p * eps_dot_p, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(!r.unstable);
}

BOOST_AUTO_TEST_CASE(fires_exactly_when_adiabatic_H_changes_sign_near_the_threshold) {
  // eps_p = 0.3: H = +0.603 MPa at 600 K (stable) and -2.17 MPa at 650 K (unstable). Tolerance
  // 1e-8: round-off times 3 mu / |H| ~ 1.3e5 at 600 K.
  const double ep = 0.3, eps_dot_p = 2e3;
  for (double T : {600.0, 650.0}) {
    const double H = hand_H(ep, T, true);
    const Uniaxial u = uniaxial(jc(ep, T), H, eps_dot_p);
    const DruckerResult r = drucker_check(elastic_plastic_tangent(kK, kMu, u.stress, H), u.D, u.Dp);
    BOOST_TEST(r.indicator == H * eps_dot_p * eps_dot_p, boost::test_tools::tolerance(1e-8));
    BOOST_TEST(r.unstable == (H <= 0.0));
  }
  BOOST_TEST(hand_H(0.3, 600.0, true) > 0.5e6);
  BOOST_TEST(hand_H(0.3, 650.0, true) < -2e6);
}

BOOST_AUTO_TEST_CASE(indicator_is_H_times_both_plastic_rates_for_any_loading_direction) {
  // General stress and D with N:D > 0; D^p = e N with an arbitrary e > 0 (not the tangent's own
  // rate e_c = 2 mu N:D / (3 mu + H)): sigma_dot : D^p = H e e_c (derivation in drucker.hpp).
  Mat3 a, d;
  a << 0.9, 0.35, -0.2, 0.35, -0.4, 0.15, -0.2, 0.15, 0.25;
  d << 1.0, 0.3, -0.4, 0.3, -0.2, 0.5, -0.4, 0.5, 0.7;
  const Mat3 stress = deviator(a) * (280e6 / von_mises(a)) + 90e6 * Mat3::Identity();
  const Mat3 s = deviator(stress);
  const Mat3 N = 1.5 * s / std::sqrt(1.5 * ddot(s, s));
  const Mat3 D = 1e3 * d;
  BOOST_TEST(ddot(N, D) > 0.0);
  const double e = 750.0;
  for (double H : {3e8, 4e7, -6e7, -5e8}) {
    const double e_c = 2.0 * kMu * ddot(N, D) / (3.0 * kMu + H);
    const DruckerResult r = drucker_check(elastic_plastic_tangent(kK, kMu, stress, H), D, e * N);
    BOOST_TEST(r.indicator == H * e * e_c, boost::test_tools::tolerance(1e-10));
    BOOST_TEST(r.unstable == (H <= 0.0));
  }
}

BOOST_AUTO_TEST_CASE(does_not_fire_without_plastic_flow) {
  const double H = hand_H(0.5, 600.0, true);  // softening, but D^p = 0 (elastic step)
  const Uniaxial u = uniaxial(jc(0.5, 600.0), H, 1e3);
  const DruckerResult r =
      drucker_check(elastic_plastic_tangent(kK, kMu, u.stress, H), u.D, Mat3::Zero());
  BOOST_TEST(r.indicator == 0.0);
  BOOST_TEST(!r.unstable);
}

BOOST_AUTO_TEST_CASE(the_2004_total_rate_form_stays_positive_under_the_same_softening) {
  // The 2004 code tested sigma_dot : D with the total D. For the uniaxial D of the first case that
  // is H eps_dot_p^2 (1 + H / E) < 0 too, but adding an elastic shear rate (orthogonal to N, so the
  // plastic rate is unchanged) adds 2 mu D_shear : D_shear = 1.04e17 Pa/s^2 and makes it positive,
  // while eq. (10), sigma_dot : D^p = H eps_dot_p^2, is unaffected. Hence it almost never fired.
  const double ep = 0.5, T = 600.0;
  const double H = hand_H(ep, T, true);
  const Uniaxial u = uniaxial(jc(ep, T), H, 1e3);
  Mat3 shear = Mat3::Zero();
  shear(1, 2) = shear(2, 1) = 1e3;  // an elastic shear rate, orthogonal to N
  const Mat3 D = u.D + shear;
  const Tensor4 c = elastic_plastic_tangent(kK, kMu, u.stress, H);
  BOOST_TEST(drucker_check(c, D, D).indicator > 0.0);  // 2004 form: "stable"
  BOOST_TEST(drucker_check(c, D, u.Dp).unstable);      // eq. (10): unstable
}

// The closed form (drucker_check_j2, what check_stability runs) equals the assembled 9x9 tangent's
// D^p : C^ep : D to round-off (1e-12 of the terms' scale) and gives the same verdict, over random
// stresses, rates of deformation (non-symmetric parts included) and plastic rates, for hardening,
// softening, ideal (H = 0) and rigid-plastic (H = +inf) slopes, and at zero deviatoric stress.
BOOST_AUTO_TEST_CASE(the_closed_form_equals_the_assembled_tangent) {
  std::srand(7);
  const auto random = []() { return 2.0 * std::rand() / RAND_MAX - 1.0; };
  const auto random_mat = [&]() {
    Mat3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = random();
    return m;
  };
  int checked = 0;
  for (const double H : {5e8, -3e8, 0.0, std::numeric_limits<double>::infinity()})
    for (int k = 0; k < 50; ++k) {
      Mat3 stress = 300e6 * random_mat();
      stress = 0.5 * (stress + stress.transpose());
      if (k == 0) stress = -100e6 * Mat3::Identity();  // sigma_eq = 0
      const Mat3 D = 1e3 * random_mat();
      const Mat3 Dp = k % 5 == 0 ? Mat3(Mat3::Zero()) : Mat3(1e3 * random_mat());
      const DruckerResult a = drucker_check(elastic_plastic_tangent(kK, kMu, stress, H), D, Dp);
      const DruckerResult b = drucker_check_j2(kK, kMu, stress, H, D, Dp);
      const double scale = kK * D.norm() * Dp.norm() + 1.0;
      BOOST_TEST_CONTEXT("H " << H << " k " << k) {
        BOOST_TEST(std::abs(a.indicator - b.indicator) <= 1e-12 * scale);
        if (std::abs(a.indicator) > 1e-9 * scale) BOOST_TEST(a.unstable == b.unstable);
      }
      ++checked;
    }
  BOOST_TEST(checked == 200);
}

// Ideal plasticity (H = 0) is Drucker's neutral case: the closed form's indicator is round-off
// and the point is not failed on its sign, over 100 stress levels and rates; a softening of
// only 10 Pa (H / 3 mu = 1.3e-10) already fires.
BOOST_AUTO_TEST_CASE(ideal_plasticity_is_neutral_not_unstable) {
  int fired_neutral = 0, fired_soft = 0;
  for (int k = 1; k <= 100; ++k) {
    const double sigma = 100e6 + 3.3e6 * k, rate = 0.37 * k;
    const Uniaxial ideal = uniaxial(sigma, 0.0, rate);
    const DruckerResult a = drucker_check_j2(kK, kMu, ideal.stress, 0.0, ideal.D, ideal.Dp);
    fired_neutral += a.unstable;
    const Uniaxial soft = uniaxial(sigma, -10.0, rate);
    fired_soft += drucker_check_j2(kK, kMu, soft.stress, -10.0, soft.D, soft.Dp).unstable;
  }
  BOOST_TEST(fired_neutral == 0);
  BOOST_TEST(fired_soft == 100);
}

BOOST_AUTO_TEST_SUITE_END()
