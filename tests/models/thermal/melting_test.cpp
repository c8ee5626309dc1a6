// Melting (report sec. 3): a melted point keeps its mean stress and loses its deviator; the melted
// predicate's boundary; the reader's error messages.
#include "models/thermal/melting.hpp"
#include "helpers/input_problems.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

using namespace impact;
using impact::testing::problems_text;

BOOST_AUTO_TEST_SUITE(thermal_melting)

BOOST_AUTO_TEST_CASE(melting_zeroes_the_deviator_and_keeps_the_mean_stress) {
  Mat3 sigma;
  sigma << -2.1e9, 3e8, -1e8, 3e8, -1.4e9, 5e7, -1e8, 5e7, -0.9e9;
  const double m = sigma.trace() / 3.0;  // -1.4667 GPa
  const Mat3 melted = melt_stress(sigma);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) BOOST_TEST(melted(i, j) == (i == j ? m : 0.0));
  BOOST_TEST(von_mises(melted) == 0.0);
  // Tension too (mean +200 MPa, exact in binary): the EOS decides the mean stress, not melting.
  Mat3 tension;
  tension << 264e6, 16e6, 0.0, 16e6, 168e6, -8e6, 0.0, -8e6, 168e6;
  BOOST_TEST((melt_stress(tension) == 2e8 * Mat3::Identity()));
}

BOOST_AUTO_TEST_CASE(a_point_is_melted_from_the_melting_temperature_on) {
  BOOST_TEST(!is_melted(std::nextafter(925.0, 0.0), 925.0));
  BOOST_TEST(is_melted(925.0, 925.0));
  BOOST_TEST(is_melted(1500.0, 925.0));
  BOOST_TEST(!is_melted(294.0, 925.0));
}

// Steinberg (1996), UCRL-MA-106439, 6061-T6: T_m0 = 1220 K, Gamma0 = 1.97, a = 1.5. Python:
// T_m0 exp(2 a (1 - 1/eta)) eta^(2 (Gamma0 - a - 1/3)).
BOOST_AUTO_TEST_CASE(the_scg_melting_curve_rises_with_compression_as_lindemanns_law) {
  MeltingParams p;
  BOOST_TEST(melting_temperature(p, 1220.0, 1.3) == 1220.0);  // constant: the material's T_m
  p.curve = MeltingCurve::steinberg_cochran_guinan;
  p.gamma0 = 1.97;
  p.a = 1.5;
  const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-12 * b; };
  BOOST_TEST(close(melting_temperature(p, 1220.0, 1.0), 1220.0));
  BOOST_TEST(close(melting_temperature(p, 1220.0, 1.1), 1644.817738178481));
  BOOST_TEST(close(melting_temperature(p, 1220.0, 1.3), 2619.2066066065727));
  BOOST_TEST(close(melting_temperature(p, 1220.0, 0.95), 1027.3020068637215));
}

BOOST_AUTO_TEST_CASE(reader_reads_the_scg_curve_and_requires_its_constants) {
  const Json j = Json::parse(R"({"curve": "steinberg_cochran_guinan", "gamma0": 1.97})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/melting", problems);
  const MeltingParams p = read_melting(r);
  BOOST_TEST((p.curve == MeltingCurve::steinberg_cochran_guinan));
  BOOST_TEST(p.gamma0 == 1.97);
  BOOST_REQUIRE(problems.count() == 1u);
  try {
    problems.throw_if_any();
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("mat.json: /constitutive_model/melting/a: missing "
                                          "required number") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(reader_defaults_to_melting_on) {
  const Json j = Json::object();
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/melting", problems);
  BOOST_TEST(read_melting(r).do_melting);
  BOOST_TEST(problems.empty());
}

BOOST_AUTO_TEST_CASE(reader_names_the_key_path_of_an_unknown_key_and_a_non_boolean_value) {
  // do_melting has no numeric range; a non-boolean is its out-of-range value.
  const Json j = Json::parse(R"({"do_melting": 1, "melt_temperature": 925.0})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/melting", problems);
  read_melting(r);
  const std::string text = problems_text(problems);
  BOOST_TEST(text.find("mat.json: /constitutive_model/melting/do_melting: expected true or false, "
                       "got a number 1") != std::string::npos);
  BOOST_TEST(text.find("mat.json: /constitutive_model/melting/melt_temperature: unknown key") !=
             std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
