// Johnson-Cook flow stress: values against hand-evaluated closed forms of report eq. (5) with the
// Table 1 constants, derivatives against central differences, documented edge behaviour.
#include "models/flow_stress/johnson_cook.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>

#include "helpers/finite_difference.hpp"

using namespace impact;
using impact::testing::central_difference;
using impact::testing::relative_difference;

namespace {

JohnsonCookParams al6061() {
  JohnsonCookParams p;
  p.A = 324e6;
  p.B = 114e6;
  p.n = 0.42;
  p.C = 0.002;
  p.m = 1.34;
  p.reference_strain_rate = 1.0;
  p.room_temperature = 294.0;
  p.melt_temperature = 925.0;
  return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(flow_stress_johnson_cook)

BOOST_AUTO_TEST_CASE(equals_A_at_zero_strain_reference_rate_room_temperature) {
  const auto p = al6061();
  BOOST_TEST(johnson_cook(p, 0.0, 1.0, 294.0).value == 324e6, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(quasi_static_flow_stress_at_twenty_percent_strain_is_382_MPa) {
  // By hand: 324 + 114 * 0.2^0.42 = 382.0 MPa.
  const auto p = al6061();
  const double expected = 324e6 + 114e6 * std::exp(0.42 * std::log(0.2));
  BOOST_TEST(johnson_cook(p, 0.2, 1.0, 294.0).value == expected,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(std::abs(expected - 382.0e6) < 0.05e6);
}

BOOST_AUTO_TEST_CASE(rate_and_temperature_factors_multiply_as_in_eq_5) {
  const auto p = al6061();
  const double ep = 0.1, rate = 1e4, T = 500.0;
  const double t_star = (T - 294.0) / (925.0 - 294.0);
  const double expected = (324e6 + 114e6 * std::pow(ep, 0.42)) * (1.0 + 0.002 * std::log(rate)) *
                          (1.0 - std::pow(t_star, 1.34));
  BOOST_TEST(johnson_cook(p, ep, rate, T).value == expected, boost::test_tools::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(clamped_form_gives_no_softening_below_the_reference_rate) {
  const auto p = al6061();
  BOOST_TEST(johnson_cook(p, 0.1, 1e-5, 294.0).value == johnson_cook(p, 0.1, 1.0, 294.0).value);
  BOOST_TEST(johnson_cook(p, 0.1, 1e-5, 294.0).d_rate == 0.0);
}

BOOST_AUTO_TEST_CASE(report_2004_form_jumps_by_two_to_the_C_at_the_reference_rate) {
  auto p = al6061();
  p.rate_form = JohnsonCookRateForm::report_2004;
  const double below = johnson_cook(p, 0.0, 1.0 - 1e-12, 294.0).value;
  const double at = johnson_cook(p, 0.0, 1.0, 294.0).value;
  BOOST_TEST(below / at == std::pow(2.0, 0.002), boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_CASE(no_thermal_hardening_below_room_and_zero_strength_at_melt) {
  const auto p = al6061();
  BOOST_TEST(johnson_cook(p, 0.1, 1.0, 77.0).value == johnson_cook(p, 0.1, 1.0, 294.0).value);
  BOOST_TEST(johnson_cook(p, 0.1, 1.0, 925.0).value == 0.0);
  BOOST_TEST(johnson_cook(p, 0.1, 1.0, 1200.0).value == 0.0);
}

BOOST_AUTO_TEST_CASE(derivatives_match_central_differences) {
  for (auto form : {JohnsonCookRateForm::clamped, JohnsonCookRateForm::report_2004}) {
    auto p = al6061();
    p.rate_form = form;
    for (double ep : {1e-4, 0.05, 0.3, 1.2})
      for (double rate : {0.3, 5.0, 1e3})
        for (double T : {350.0, 600.0, 900.0}) {
          const FlowStress f = johnson_cook(p, ep, rate, T);
          const double d_ep =
              central_difference([&](double x) { return johnson_cook(p, x, rate, T).value; }, ep);
          const double d_rate =
              central_difference([&](double x) { return johnson_cook(p, ep, x, T).value; }, rate);
          const double d_T =
              central_difference([&](double x) { return johnson_cook(p, ep, rate, x).value; }, T);
          BOOST_TEST(relative_difference(f.d_plastic_strain, d_ep) < 1e-6);
          BOOST_TEST(relative_difference(f.d_rate, d_rate, 1e-3) < 1e-6);
          BOOST_TEST(relative_difference(f.d_temperature, d_T) < 1e-6);
        }
  }
}

BOOST_AUTO_TEST_CASE(hardening_slope_is_unbounded_at_zero_plastic_strain_for_n_below_one) {
  const auto p = al6061();
  BOOST_TEST(std::isinf(johnson_cook(p, 0.0, 1.0, 294.0).d_plastic_strain));
}

BOOST_AUTO_TEST_CASE(reader_names_the_key_path_of_an_out_of_range_exponent) {
  const Json j = Json::parse(R"({"A": 324e6, "B": 114e6, "n": -0.3, "C": 0.002, "m": 1.34})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/flow_stress", problems);
  read_johnson_cook(r, 294.0, 925.0);
  BOOST_REQUIRE(!problems.empty());
  try {
    problems.throw_if_any();
  } catch (const InputError& e) {
    const std::string text = e.what();
    BOOST_TEST(text.find("mat.json: /constitutive_model/flow_stress/n: expected a number in (0, "
                         "1.5], got -0.3") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(reader_suggests_the_nearest_key_for_a_misspelling) {
  const Json j = Json::parse(R"({"A": 324e6, "B": 114e6, "n": 0.42, "C": 0.002, "mm": 1.34})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/flow_stress", problems);
  read_johnson_cook(r, 294.0, 925.0);
  try {
    problems.throw_if_any();
    BOOST_FAIL("expected an InputError");
  } catch (const InputError& e) {
    const std::string text = e.what();
    BOOST_TEST(text.find("/flow_stress/m: missing required number") != std::string::npos);
    BOOST_TEST(text.find("/flow_stress/mm: unknown key (did you mean m?)") != std::string::npos);
  }
}

BOOST_AUTO_TEST_SUITE_END()
