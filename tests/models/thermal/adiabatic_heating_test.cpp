// Adiabatic heating (report eq. 8): the temperature rise equals chi sigma:D^p dt / (rho c_p) for a
// stress on the yield surface with D^p built from associated J2 flow, elastic loading does not
// heat, the 150.4 K rise computed by hand, and the reader's error messages.
#include "models/thermal/adiabatic_heating.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "helpers/input_problems.hpp"
#include "models/core/tensor.hpp"

using namespace impact;
using impact::testing::problems_text;

namespace {

constexpr double kRho = 2700.0, kCp = 896.0, kChi = 0.9;  // report Table 1

}  // namespace

BOOST_AUTO_TEST_SUITE(thermal_adiabatic_heating)

BOOST_AUTO_TEST_CASE(rise_equals_chi_times_plastic_stress_power_over_rho_cp) {
  // An arbitrary stress whose deviator is scaled onto sigma_eq = sigma_y, plus a pressure.
  const double sigma_y = 382e6, rate = 3.7e3, dt = 2.5e-8;
  Mat3 a;
  a << 1.0, 0.4, -0.3, 0.4, -0.7, 0.2, -0.3, 0.2, 0.1;
  const Mat3 s = deviator(a) * (sigma_y / von_mises(a));
  const Mat3 sigma = s - 1.2e9 * Mat3::Identity();
  // Associated J2 flow: D^p = eps_dot_p (3/2) s / sigma_eq.
  const Mat3 Dp = rate * 1.5 * s / std::sqrt(1.5 * ddot(s, s));
  const double expected = kChi * ddot(sigma, Dp) * dt / (kRho * kCp);
  BOOST_TEST(adiabatic_temperature_rise(kChi, sigma_y, rate * dt, kRho, kCp) == expected,
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(elastic_loading_does_not_heat) {
  // The 2004 code heated by chi sigma:D even with no plastic strain; here d_ep = 0 gives 0.
  BOOST_TEST(adiabatic_temperature_rise(kChi, 324e6, 0.0, kRho, kCp) == 0.0);
}

BOOST_AUTO_TEST_CASE(plastic_work_to_unit_strain_heats_6061_by_150_4_kelvin) {
  // By hand: Delta T = chi int_0^1 (A + B e^n) de / (rho c_p)
  //                                       = chi (A + B/(n+1)) / (rho c_p) = 150.4 K.
  // Summed from the function in 1e5 midpoint increments (quadrature error ~ h^1.42, about 1e-8).
  const double A = 324e6, B = 114e6, n = 0.42;
  const int steps = 100000;
  const double h = 1.0 / steps;
  double rise = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double e = (i + 0.5) * h;
    rise += adiabatic_temperature_rise(kChi, A + B * std::pow(e, n), h, kRho, kCp);
  }
  const double closed = kChi * (A + B / (n + 1.0)) / (kRho * kCp);
  BOOST_TEST(rise == closed, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(std::abs(closed - 150.4) < 0.05);
}

BOOST_AUTO_TEST_CASE(reader_defaults_to_chi_0_9_and_heating_on) {
  const Json j = Json::object();
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/adiabatic_heating", problems);
  const AdiabaticHeatingParams p = read_adiabatic_heating(r);
  BOOST_TEST(problems.empty());
  BOOST_TEST(p.enabled);
  BOOST_TEST(p.taylor_quinney == 0.9);
}

BOOST_AUTO_TEST_CASE(reader_names_the_key_path_of_an_unknown_key_and_an_out_of_range_value) {
  const Json j = Json::parse(R"({"taylor_quinney": 1.2, "chi": 0.9})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/adiabatic_heating", problems);
  read_adiabatic_heating(r);
  const std::string text = problems_text(problems);
  BOOST_TEST(text.find("mat.json: /constitutive_model/adiabatic_heating/taylor_quinney: expected a "
                       "number in [0, 1], got 1.2") != std::string::npos);
  BOOST_TEST(text.find("mat.json: /constitutive_model/adiabatic_heating/chi: unknown key") !=
             std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
