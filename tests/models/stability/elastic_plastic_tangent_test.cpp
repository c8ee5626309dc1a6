// Consistent J2 elastic-plastic tangent: closed forms along and orthogonal to the flow direction,
// symmetries, the elastic limits, the effective hardening slope against hand-computed numbers, and
// the whole 9x9 tangent against a central-difference tangent of an independent one-step radial
// return with linear hardening.
#include "models/stability/elastic_plastic_tangent.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>

using namespace impact;

namespace {

constexpr double kK = 66.4e9, kMu = 26e9;  // 6061-T6, report Table 1

// An arbitrary stress: a deviator scaled to sigma_eq = 310 MPa plus a mean stress of -150 MPa.
Mat3 test_stress() {
  Mat3 a;
  a << 0.9, 0.35, -0.2, 0.35, -0.4, 0.15, -0.2, 0.15, 0.25;
  const Mat3 s = deviator(a) * (310e6 / von_mises(a));
  return s - 150e6 * Mat3::Identity();
}

Mat3 flow_direction(const Mat3& stress) {
  const Mat3 s = deviator(stress);
  return 1.5 * s / std::sqrt(1.5 * ddot(s, s));
}

Mat3 apply(const Tensor4& c, const Mat3& d) {
  return unflatten(c * flatten(d));
}

// Independent one-step radial return for sigma_y = sigma0 + h ep (Wilkins 1964; Simo & Hughes
// 1998, box 3.1): s_tr = s_n + 2 mu dev de, p = p_n + K tr de; if plastic, the increment
// dp = (q_tr - sigma_y(ep_n)) / (3 mu + h) and s = s_tr (1 - 3 mu dp / q_tr).
Mat3 radial_return(const Mat3& stress_n, double yield_n, double h, const Mat3& de) {
  const Mat3 s_tr = deviator(stress_n) + 2.0 * kMu * deviator(de);
  const double mean = stress_n.trace() / 3.0 + kK * de.trace();
  const double q_tr = std::sqrt(1.5 * ddot(s_tr, s_tr));
  Mat3 s = s_tr;
  if (q_tr > yield_n) {
    const double dp = (q_tr - yield_n) / (3.0 * kMu + h);
    s = s_tr * (1.0 - 3.0 * kMu * dp / q_tr);
  }
  return s + mean * Mat3::Identity();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stability_elastic_plastic_tangent)

BOOST_AUTO_TEST_CASE(rate_along_the_flow_direction_gives_the_series_plastic_modulus) {
  // D = a N: C^e:D = 2 mu a N and (N (x) N):D = (3/2) a N, so
  //   sigma_dot = 2 mu a N [1 - 3 mu / (3 mu + H)] = [2 mu H / (3 mu + H)] D,
  // i.e. d sigma_eq / d eps_eq = 3 mu H / (3 mu + H): the elastic 3 mu in series with H.
  // Tolerance 1e-12: round-off times the cancellation factor 3 mu / |H| <= 260 here.
  const Mat3 stress = test_stress();
  const Mat3 D = 1.7e3 * flow_direction(stress);
  for (double H : {2e9, 5e8, -3e8}) {
    const Mat3 expected = 2.0 * kMu * H / (3.0 * kMu + H) * D;
    const Mat3 got = apply(elastic_plastic_tangent(kK, kMu, stress, H), D);
    BOOST_TEST((got - expected).norm() / expected.norm() < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(rate_orthogonal_to_the_flow_direction_is_mapped_elastically) {
  // N:D = 0 (a volumetric part and a deviator orthogonal to N): no plastic flow, C^ep:D = C^e:D.
  const Mat3 stress = test_stress();
  const Mat3 N = flow_direction(stress);
  Mat3 b;
  b << 0.3, -1.1, 0.4, -1.1, 0.8, 0.6, 0.4, 0.6, -0.5;
  const Mat3 D = 1e3 * (b - ddot(N, b) / ddot(N, N) * N + 0.2 * Mat3::Identity());
  BOOST_TEST(std::abs(ddot(N, D)) < 1e-12 * D.norm());
  const Mat3 elastic = apply(isotropic_elasticity(kK, kMu), D);
  for (double H : {1e9, 1e7, -1e8}) {
    const Mat3 got = apply(elastic_plastic_tangent(kK, kMu, stress, H), D);
    BOOST_TEST((got - elastic).norm() / elastic.norm() < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(has_major_and_minor_symmetries) {
  const Tensor4 c = elastic_plastic_tangent(kK, kMu, test_stress(), 1e8);
  BOOST_TEST((c - c.transpose()).cwiseAbs().maxCoeff() == 0.0);  // a sum of symmetric terms
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          BOOST_TEST(c(3 * i + j, 3 * k + l) == c(3 * j + i, 3 * k + l));
          BOOST_TEST(c(3 * i + j, 3 * k + l) == c(3 * i + j, 3 * l + k));
        }
}

BOOST_AUTO_TEST_CASE(hydrostatic_stress_and_infinite_hardening_give_the_elastic_tangent) {
  const Tensor4 ce = isotropic_elasticity(kK, kMu);
  // No deviator: no flow direction.
  BOOST_TEST((elastic_plastic_tangent(kK, kMu, -2e9 * Mat3::Identity(), 1e8) == ce));
  // Johnson-Cook's slope at eps_p = 0 (n < 1) is +inf: no plastic flow can start.
  const double inf = std::numeric_limits<double>::infinity();
  BOOST_TEST((elastic_plastic_tangent(kK, kMu, test_stress(), inf) == ce));
}

BOOST_AUTO_TEST_CASE(effective_hardening_combines_the_slopes_as_documented) {
  // Hand numbers: d_ep = 50 MPa, d_rate = 2e5 Pa s, d_T = -6e5 Pa/K, sigma_y = 300 MPa,
  // dt = 1e-8 s, chi = 0.9, rho cp = 2700 * 896 = 2 419 200 J/(m^3 K).
  //   thermal:  -6e5 * 0.9 * 300e6 / 2419200 = -1.62e14 / 2419200 = -66 964 285.714285714 Pa
  //   rate:     2e5 / 1e-8 = 2e13 Pa
  const FlowSlopes slopes{50e6, 2e5, -6e5};
  const double thermal = -66964285.714285714;
  auto H = [&](RateSlope r, bool adiabatic) {
    return effective_hardening(slopes, 300e6, 1e-8, r, adiabatic, 0.9, 2700.0, 896.0);
  };
  const auto tol = boost::test_tools::tolerance(1e-12);
  BOOST_TEST(H(RateSlope::constant_rate, false) == 50e6, tol);
  BOOST_TEST(H(RateSlope::constant_rate, true) == 50e6 + thermal, tol);  // -16.96 MPa
  BOOST_TEST(H(RateSlope::algorithmic, false) == 50e6 + 2e13, tol);
  BOOST_TEST(H(RateSlope::algorithmic, true) == 50e6 + 2e13 + thermal, tol);
  BOOST_TEST(H(RateSlope::constant_rate, true) < 0.0);  // softening wins at constant rate...
  BOOST_TEST(H(RateSlope::algorithmic, true) > 0.0);    // ...and is hidden by the rate slope/dt
}

BOOST_AUTO_TEST_CASE(equals_the_central_difference_tangent_of_a_radial_return) {
  // Start on the yield surface sigma_eq = sigma_y(ep_n) and take a small plastic base increment
  // de0 = h0 (N + 0.3 B); the algorithmic tangent of the return there differs from the continuum
  // one by O(3 mu dp / q) ~ 3e-7 (dp ~ h0 = 1e-9). Central differences with step 1e-12 in each
  // symmetric direction E_kl: truncation ~ 1e-12 * 3 mu / q, round-off ~ eps q / 1e-12 / C ~ 1e-6.
  // Tolerance: 1e-5 of max |C^e|.
  const double sigma0 = 300e6, ep_n = 0.05, h0 = 1e-9, delta = 1e-12;
  Mat3 b;
  b << 0.2, -0.5, 0.1, -0.5, -0.3, 0.4, 0.1, 0.4, 0.6;
  for (double h : {5e8, -2e8}) {
    const double yield_n = sigma0 + h * ep_n;
    Mat3 a;
    a << 0.9, 0.35, -0.2, 0.35, -0.4, 0.15, -0.2, 0.15, 0.25;
    const Mat3 stress_n = deviator(a) * (yield_n / von_mises(a)) - 80e6 * Mat3::Identity();
    const Mat3 de0 = h0 * (flow_direction(stress_n) + 0.3 * b);
    Tensor4 fd;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        Mat3 e = Mat3::Zero();
        e(k, l) += 0.5;
        e(l, k) += 0.5;
        const Mat3 plus = radial_return(stress_n, yield_n, h, de0 + delta * e);
        const Mat3 minus = radial_return(stress_n, yield_n, h, de0 - delta * e);
        fd.col(3 * k + l) = flatten((plus - minus) / (2.0 * delta));
      }
    const Tensor4 c = elastic_plastic_tangent(kK, kMu, stress_n, h);
    const double scale = isotropic_elasticity(kK, kMu).cwiseAbs().maxCoeff();
    const double error = (fd - c).cwiseAbs().maxCoeff() / scale;
    BOOST_TEST_MESSAGE("H = " << h << ": max |C_fd - C^ep| / max |C^e| = " << error);
    BOOST_TEST(error < 1e-5);
    // The plastic correction itself is large (over 0.1 of C^e), so this comparison has teeth.
    BOOST_TEST((isotropic_elasticity(kK, kMu) - c).cwiseAbs().maxCoeff() / scale > 0.1);
  }
}

BOOST_AUTO_TEST_SUITE_END()
