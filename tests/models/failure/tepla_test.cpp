// TEPLA-F (report eq. 9): the indicator reaches 1 exactly when the plastic strain reaches the
// Johnson-Cook fracture strain (zero porosity), the mixed case, porosity growth against its closed
// form (first-order convergence of forward Euler), the Chu-Needleman nucleation integral, and the
// reader's error messages.
#include "models/failure/tepla.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "helpers/input_problems.hpp"
#include "models/damage/johnson_cook_damage.hpp"

using namespace impact;
using impact::testing::problems_text;

BOOST_AUTO_TEST_SUITE(failure_tepla)

BOOST_AUTO_TEST_CASE(fires_within_one_increment_of_the_fracture_strain_with_zero_porosity) {
  JohnsonCookDamageParams jc;
  jc.D1 = -0.77;
  jc.D2 = 1.45;
  jc.D3 = -0.47;
  jc.D4 = 0.0;
  jc.D5 = 1.6;
  const double sigma_star = 0.6, rate = 1e3, T = 294.0;
  const double eps_f = -0.77 + 1.45 * std::exp(-0.47 * sigma_star);  // 0.3237, independent of rate
  const double d_ep = 1.0 / 7919.0;                                  // not commensurate with eps_f
  double D = 0.0, ep = 0.0;
  int steps = 0;
  while (tepla_indicator(0.0, 0.5, D) < 1.0 && steps < 100000) {
    D += jc_damage_increment(jc, d_ep, sigma_star, rate, T);
    ep += d_ep;
    ++steps;
  }
  // First step with indicator >= 1: eps_p has just passed eps_f (rounding allowance 1e-12).
  BOOST_TEST(ep >= eps_f - 1e-12);
  BOOST_TEST(ep - d_ep < eps_f + 1e-12);
}

BOOST_AUTO_TEST_CASE(indicator_is_one_on_the_failure_ellipse) {
  const double fc = 0.37;
  BOOST_TEST(tepla_indicator(fc / std::sqrt(2.0), fc, 1.0 / std::sqrt(2.0)) == 1.0,
             boost::test_tools::tolerance(1e-15));
  BOOST_TEST(tepla_indicator(fc, fc, 0.0) == 1.0);
  BOOST_TEST(tepla_indicator(0.0, fc, 1.0) == 1.0);
  BOOST_TEST(tepla_indicator(0.6 * fc, fc, 0.8) == 1.0, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(tepla_indicator(0.5 * fc, fc, 0.5) < 1.0);
}

BOOST_AUTO_TEST_CASE(porosity_growth_converges_at_first_order_to_the_closed_form) {
  // No nucleation, constant tr D: df/dt = (1 - f) trD  =>  f(t) = 1 - (1 - f0) exp(-trD t).
  TeplaParams p;
  p.nucleation_fraction = 0.0;
  const double f0 = 0.01, trD = 1e3, t_end = 1e-3;
  const double exact = 1.0 - (1.0 - f0) * std::exp(-trD * t_end);
  double previous_error = 0.0;
  for (int n : {100, 200, 400, 800, 1600}) {
    double f = f0;
    const double dt = t_end / n;
    for (int i = 0; i < n; ++i) f = porosity_update(p, f, trD, 0.0, 0.0, dt);
    const double error = std::abs(f - exact);
    if (previous_error > 0.0) {
      // First order: halving dt halves the error (ratio 2 within 5 %).
      BOOST_TEST(previous_error / error == 2.0, boost::test_tools::tolerance(0.05));
    }
    previous_error = error;
  }
  BOOST_TEST(previous_error < 2e-4);
}

BOOST_AUTO_TEST_CASE(compression_neither_grows_nor_closes_voids) {
  TeplaParams p;
  p.nucleation_fraction = 0.0;
  BOOST_TEST(porosity_update(p, 0.02, -5e3, 0.1, 0.0, 1e-6) == 0.02);
}

BOOST_AUTO_TEST_CASE(nucleation_over_all_plastic_strains_adds_the_nucleating_fraction) {
  // Integral of A(eps_p) over (-inf, inf) is f_n; summed from the update with tr D = 0 over
  // e_n +- 10 s_n (tails below 1e-22) in steps of s_n / 200.
  TeplaParams p;
  p.nucleation_fraction = 0.04;
  p.nucleation_strain = 0.3;
  p.nucleation_std = 0.1;
  const double h = p.nucleation_std / 200.0;
  double f = 0.0;
  for (int i = 0; i < 4000; ++i) {
    const double ep = p.nucleation_strain - 10.0 * p.nucleation_std + (i + 0.5) * h;
    f = porosity_update(p, f, 0.0, ep, h, 1e-6);
  }
  BOOST_TEST(std::abs(f - p.nucleation_fraction) < 1e-6);
  // Peak intensity at e_n: f_n / (s_n sqrt(2 pi)).
  BOOST_TEST(nucleation_intensity(p, 0.3) == 0.04 / (0.1 * std::sqrt(2.0 * std::numbers::pi)),
             boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(porosity_stays_below_one_under_huge_dilatation) {
  TeplaParams p;
  const double f = porosity_update(p, 0.9, 1e9, 0.3, 0.1, 1.0);
  BOOST_TEST(f < 1.0);
  BOOST_TEST(f > 0.999);
}

BOOST_AUTO_TEST_CASE(reader_defaults_keep_porosity_at_zero_as_the_report_did) {
  const Json j = Json::parse(R"({"enabled": true, "critical_porosity": 0.5})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/tepla", problems);
  const TeplaParams p = read_tepla(r);
  BOOST_TEST(problems.empty());
  BOOST_TEST(!p.evolve_porosity);
  BOOST_TEST(p.initial_porosity == 0.0);
}

BOOST_AUTO_TEST_CASE(reader_names_the_key_path_of_an_unknown_key_and_an_out_of_range_value) {
  const Json j = Json::parse(R"({"critical_porosity": 1.5, "evolve_porosty": true})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/tepla", problems);
  read_tepla(r);
  const std::string text = problems_text(problems);
  BOOST_TEST(
      text.find("mat.json: /constitutive_model/tepla/critical_porosity: expected a number in "
                "(0, 1], got 1.5") != std::string::npos);
  BOOST_TEST(text.find("mat.json: /constitutive_model/tepla/evolve_porosty: unknown key (did you "
                       "mean evolve_porosity?)") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(reader_rejects_an_initial_porosity_at_or_above_the_critical_one) {
  const Json j = Json::parse(R"({"critical_porosity": 0.2, "initial_porosity": 0.2})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/tepla", problems);
  read_tepla(r);
  BOOST_TEST(problems_text(problems).find("/tepla/initial_porosity: expected an initial porosity "
                                          "below critical_porosity") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
