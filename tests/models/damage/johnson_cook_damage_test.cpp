// Johnson-Cook damage (report eq. 7) with the Table 1 constants: fracture strains against hand
// evaluations of the closed form, the rate and temperature factors, the floor that replaces the
// 2004 code's "no damage in strong tension", damage accumulation along a proportional path, the
// triaxiality of standard stress states and the reader's error messages.
#include "models/damage/johnson_cook_damage.hpp"
#include "helpers/input_problems.hpp"

#include <Eigen/Geometry>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace impact;
using impact::testing::problems_text;

namespace {

JohnsonCookDamageParams al6061() {
  JohnsonCookDamageParams p;
  p.D1 = -0.77;
  p.D2 = 1.45;
  p.D3 = -0.47;
  p.D4 = 0.0;
  p.D5 = 1.6;
  p.reference_strain_rate = 1.0;
  p.min_fracture_strain = 1e-3;
  p.room_temperature = 294.0;
  p.melt_temperature = 925.0;
  return p;
}

Mat3 diagonal(double a, double b, double c) {
  Mat3 s = Mat3::Zero();
  s(0, 0) = a;
  s(1, 1) = b;
  s(2, 2) = c;
  return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(damage_johnson_cook_damage)

BOOST_AUTO_TEST_CASE(uniaxial_tension_fracture_strain_is_0_470) {
  // By hand: sigma* = 1/3, D4 = 0, T* = 0: eps_f = D1 + D2 exp(D3/3).
  const double expected = -0.77 + 1.45 * std::exp(-0.47 / 3.0);
  BOOST_TEST(jc_fracture_strain(al6061(), 1.0 / 3.0, 1.0, 294.0) == expected,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(expected - 0.470) < 0.0005);
}

BOOST_AUTO_TEST_CASE(fracture_strains_match_the_table_of_the_reference_notes) {
  // docs/report_code.md sec. 5 (two-digit values at T* = 0); the closed form to 1e-12 and the
  // printed value to 0.01 (the notes' 0.92 at -1/3 is 0.926 truncated).
  const double sigma_star[] = {-1.0 / 3.0, 0.0, 1.0 / 3.0, 0.6, 1.0};
  const double table[] = {0.92, 0.68, 0.47, 0.32, 0.14};
  for (int i = 0; i < 5; ++i) {
    const double closed = -0.77 + 1.45 * std::exp(-0.47 * sigma_star[i]);
    const double eps_f = jc_fracture_strain(al6061(), sigma_star[i], 0.5, 294.0);
    BOOST_TEST(eps_f == closed, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::abs(eps_f - table[i]) < 0.01);
  }
}

BOOST_AUTO_TEST_CASE(fracture_strain_is_floored_beyond_triaxiality_1_347_and_damage_grows_there) {
  const auto p = al6061();
  // eps_f = 0 at sigma* = ln(-D1/D2)/D3 = 1.3467.
  const double zero_crossing = std::log(0.77 / 1.45) / -0.47;
  BOOST_TEST(std::abs(zero_crossing - 1.347) < 0.0005);
  BOOST_TEST(jc_fracture_strain(p, zero_crossing - 0.01, 1.0, 294.0) > p.min_fracture_strain);
  BOOST_TEST(jc_fracture_strain(p, 2.0, 1.0, 294.0) == p.min_fracture_strain);
  // The 2004 code returned no increment here; now it is the largest one: d_ep / eps_min.
  const double d_ep = 1e-4;
  BOOST_TEST(jc_damage_increment(p, d_ep, 2.0, 1.0, 294.0) == d_ep / 1e-3,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(jc_damage_increment(p, d_ep, 2.0, 1.0, 294.0) >
             jc_damage_increment(p, d_ep, 1.0, 1.0, 294.0));
}

BOOST_AUTO_TEST_CASE(temperature_factor_is_one_plus_D5_T_star_clamped_to_room_and_melt) {
  const auto p = al6061();
  const double base = -0.77 + 1.45 * std::exp(-0.47 / 3.0);
  const double t_star = (500.0 - 294.0) / (925.0 - 294.0);
  BOOST_TEST(jc_fracture_strain(p, 1.0 / 3.0, 1.0, 500.0) == base * (1.0 + 1.6 * t_star),
             boost::test_tools::tolerance(1e-12));
  // Below room temperature: the room value (the 2004 code's T = 0 K start gave 1 + D5 T* = 0.25).
  BOOST_TEST(jc_fracture_strain(p, 1.0 / 3.0, 1.0, 0.0) == base,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(jc_fracture_strain(p, 1.0 / 3.0, 1.0, 200.0) == base,
             boost::test_tools::tolerance(1e-12));
  // Above the melt: the melt value 1 + D5.
  BOOST_TEST(jc_fracture_strain(p, 1.0 / 3.0, 1.0, 925.0) == base * 2.6,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(jc_fracture_strain(p, 1.0 / 3.0, 1.0, 2000.0) == base * 2.6,
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(rate_factor_uses_the_rate_normalised_by_the_reference_and_floors_at_one) {
  auto p = al6061();
  p.D4 = 0.011;
  const double base = -0.77 + 1.45 * std::exp(-0.47 / 3.0);
  BOOST_TEST(jc_fracture_strain(p, 1.0 / 3.0, 1e3, 294.0) == base * (1.0 + 0.011 * std::log(1e3)),
             boost::test_tools::tolerance(1e-12));
  // Below the reference rate: no change.
  BOOST_TEST(jc_fracture_strain(p, 1.0 / 3.0, 1e-4, 294.0) == base,
             boost::test_tools::tolerance(1e-12));
  // With rate0 = 1e-3 /s a rate of 1 /s is rate* = 1e3 (the 2004 code would have used ln 1 = 0).
  p.reference_strain_rate = 1e-3;
  BOOST_TEST(jc_fracture_strain(p, 1.0 / 3.0, 1.0, 294.0) == base * (1.0 + 0.011 * std::log(1e3)),
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(damage_at_constant_triaxiality_equals_plastic_strain_over_fracture_strain) {
  // A proportional uniaxial-tension path whose stress magnitude hardens as in Johnson-Cook flow:
  // the triaxiality stays 1/3, so D = eps_p / eps_f(1/3) after any number of steps.
  const auto p = al6061();
  const double rate = 250.0, T = 400.0, d_ep = 1e-3;
  const int steps = 300;
  double D = 0.0, ep = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double sigma = 324e6 + 114e6 * std::pow(ep + d_ep, 0.42);
    D += jc_damage_increment(p, d_ep, triaxiality(diagonal(sigma, 0.0, 0.0)), rate, T);
    ep += d_ep;
  }
  const double t_star = (T - 294.0) / (925.0 - 294.0);
  const double eps_f = (-0.77 + 1.45 * std::exp(-0.47 / 3.0)) * (1.0 + 1.6 * t_star);
  BOOST_TEST(D == ep / eps_f, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(triaxiality_of_shear_uniaxial_and_equibiaxial_tension) {
  Mat3 shear = Mat3::Zero();
  shear(0, 1) = shear(1, 0) = 7e7;
  BOOST_TEST(triaxiality(shear) == 0.0);
  BOOST_TEST(triaxiality(diagonal(3e8, 0.0, 0.0)) == 1.0 / 3.0,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(triaxiality(diagonal(-3e8, 0.0, 0.0)) == -1.0 / 3.0,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(triaxiality(diagonal(2e8, 2e8, 0.0)) == 2.0 / 3.0,
             boost::test_tools::tolerance(1e-14));
  // Pure hydrostatic stress has no sigma_eq: documented value 0.
  BOOST_TEST(triaxiality(diagonal(1e9, 1e9, 1e9)) == 0.0);
  BOOST_TEST(triaxiality(Mat3::Zero()) == 0.0);
}

BOOST_AUTO_TEST_CASE(reader_accepts_table_1_and_fills_defaults_and_temperatures) {
  const Json j = Json::parse(
      R"({"type": "johnson_cook", "D1": -0.77, "D2": 1.45, "D3": -0.47, "D4": 0.0, "D5": 1.6})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/damage", problems);
  const auto p = read_johnson_cook_damage(r, 294.0, 925.0);
  BOOST_TEST(problems.empty());
  BOOST_TEST(p.D3 == -0.47);
  BOOST_TEST(p.reference_strain_rate == 1.0);
  BOOST_TEST(p.min_fracture_strain == 1e-3);
  BOOST_TEST(p.melt_temperature == 925.0);
}

BOOST_AUTO_TEST_CASE(reader_names_the_key_path_of_an_unknown_key_and_an_out_of_range_value) {
  const Json j = Json::parse(
      R"({"D1": -0.77, "D2": 1.45, "D3": -0.47, "D4": 0.0, "D5": 1.6, "D6": 1.0,
          "min_fracture_strain": -0.1})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/damage", problems);
  read_johnson_cook_damage(r, 294.0, 925.0);
  const std::string text = problems_text(problems);
  BOOST_TEST(text.find("mat.json: /constitutive_model/damage/D6: unknown key") !=
             std::string::npos);
  BOOST_TEST(
      text.find("mat.json: /constitutive_model/damage/min_fracture_strain: expected a number "
                "in (0, inf), got -0.1") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(cutoff_triaxiality_gives_no_damage_below_it_and_the_closed_form_above) {
  JohnsonCookDamageParams p = al6061();
  p.cutoff_triaxiality = -1.0 / 3.0;
  BOOST_TEST(jc_damage_increment(p, 0.01, -0.34, 1.0, 294.0) == 0.0);
  BOOST_TEST(jc_damage_increment(p, 0.01, -1.5, 1.0, 294.0) == 0.0);
  // Just above the cut-off: d_ep / (D1 + D2 exp(D3 sigma*)), by hand 0.01 / 0.9226 at -0.33.
  BOOST_TEST(jc_damage_increment(p, 0.01, -0.33, 1.0, 294.0) ==
                 0.01 / (-0.77 + 1.45 * std::exp(-0.47 * -0.33)),
             boost::test_tools::tolerance(1e-14));
  p.cutoff_triaxiality.reset();  // the report's eq. 7: damage at every triaxiality
  BOOST_TEST(jc_damage_increment(p, 0.01, -0.34, 1.0, 294.0) > 0.0);
}

// Uniaxial compression is sigma* = -1/3 exactly; computed in a rotated frame it lands a few ulp on
// either side. 1000 random frames and stress magnitudes 1 MPa..10 GPa: triaxiality() is within
// 1 eps of -1/3 and at or above it in most frames (the strict cut-off accrued damage there), yet
// with the cut-off at -1/3 no frame accrues damage. Just above the band (2 x cutoff_tolerance, and
// -1/3 + 1e-6) the closed form applies again: the band is round-off wide, not a shifted cut-off.
BOOST_AUTO_TEST_CASE(
    uniaxial_compression_in_rotated_frames_accrues_no_damage_at_cutoff_minus_one_third) {
  JohnsonCookDamageParams p = al6061();
  p.cutoff_triaxiality = -1.0 / 3.0;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  std::mt19937_64 gen(37);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int above = 0, damaged = 0;
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const Mat3 R =
        Eigen::Quaterniond(u(gen), u(gen), u(gen), u(gen)).normalized().toRotationMatrix();
    const double magnitude = std::pow(10.0, 8.0 + 2.0 * u(gen));
    const double t = triaxiality(R * diagonal(-magnitude, 0.0, 0.0) * R.transpose());
    above += t >= -1.0 / 3.0;
    worst = std::max(worst, std::abs(t + 1.0 / 3.0));
    damaged += jc_damage_increment(p, 0.01, t, 1.0, 294.0) != 0.0;
  }
  BOOST_TEST_MESSAGE("rotated uniaxial compression: "
                     << above << " of 1000 frames at or above -1/3, |sigma* + 1/3| <= "
                     << worst / eps << " eps");
  BOOST_TEST(above > 0);  // round-off does put frames at or above the cut-off
  BOOST_TEST(worst <= eps);
  BOOST_TEST(damaged == 0);
  const double band = cutoff_tolerance(-1.0 / 3.0);
  BOOST_TEST(band == 8.0 * eps * 4.0 / 3.0);
  BOOST_TEST(jc_damage_increment(p, 0.01, -1.0 / 3.0 + band, 1.0, 294.0) == 0.0);
  for (const double t : {-1.0 / 3.0 + 2.0 * band, -1.0 / 3.0 + 1e-6}) {
    BOOST_TEST_CONTEXT("sigma* = -1/3 + " << t + 1.0 / 3.0) {
      BOOST_TEST(jc_damage_increment(p, 0.01, t, 1.0, 294.0) ==
                     0.01 / (-0.77 + 1.45 * std::exp(-0.47 * t)),
                 boost::test_tools::tolerance(1e-14));
    }
  }
}

BOOST_AUTO_TEST_CASE(reader_takes_a_cutoff_and_rejects_a_positive_one) {
  const Json ok = Json::parse(
      R"({"D1": -0.77, "D2": 1.45, "D3": -0.47, "D4": 0.0, "D5": 1.6, "cutoff_triaxiality": -0.5})");
  InputProblems fine("mat.json");
  JsonReader r(ok, "/constitutive_model/damage", fine);
  BOOST_TEST(*read_johnson_cook_damage(r, 294.0, 925.0).cutoff_triaxiality == -0.5);
  BOOST_TEST(fine.empty());
  const Json bad = Json::parse(
      R"({"D1": -0.77, "D2": 1.45, "D3": -0.47, "D4": 0.0, "D5": 1.6, "cutoff_triaxiality": 0.3})");
  InputProblems problems("mat.json");
  JsonReader rb(bad, "/constitutive_model/damage", problems);
  read_johnson_cook_damage(rb, 294.0, 925.0);
  BOOST_TEST(problems_text(problems).find(
                 "mat.json: /constitutive_model/damage/cutoff_triaxiality: expected a number in "
                 "[-10, 0], got 0.3") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(reader_rejects_a_non_positive_fracture_strain_in_pure_shear) {
  const Json j = Json::parse(R"({"D1": -0.77, "D2": -1.45, "D3": -0.47, "D4": 0.0, "D5": 1.6})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/damage", problems);
  read_johnson_cook_damage(r, 294.0, 925.0);
  BOOST_TEST(problems_text(problems).find("/damage/D2: expected D1 + D2 > 0") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
