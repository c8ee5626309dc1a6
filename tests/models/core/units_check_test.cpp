// Units plausibility (models/core/units_check.hpp): the likely unit of each common slip, no
// finding for plausible SI values, and the two ways a reader reports it (JsonReader::quantity):
// a warning when the value is admissible, the hint inside the error when it is not.
#include "models/core/units_check.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>

#include "models/core/input.hpp"

using namespace impact;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The unit guessed for `value`, or "" when there is no finding.
std::string unit_of(Quantity q, double value) {
  const auto guess = likely_unit(q, value);
  return guess ? guess->unit : "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(core_units_check)

BOOST_AUTO_TEST_CASE(common_slips_are_recognised_with_their_si_value) {
  const auto density = likely_unit(Quantity::density, 2.7);
  BOOST_TEST_REQUIRE(density.has_value());
  BOOST_TEST(density->unit == "g/cm^3");
  BOOST_TEST(density->value_in_si == 2700.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(unit_of(Quantity::elastic_modulus, 26.0) == "GPa");
  BOOST_TEST(unit_of(Quantity::elastic_modulus, 66.4) == "GPa");
  BOOST_TEST(unit_of(Quantity::elastic_modulus, 26000.0) == "MPa");
  BOOST_TEST(unit_of(Quantity::stress, 324.0) == "MPa");
  BOOST_TEST(unit_of(Quantity::stress, -100.0) == "MPa");  // compression: the magnitude counts
  BOOST_TEST(unit_of(Quantity::stress, 0.3) == "GPa");     // 0.3 GPa is closer to typical
  BOOST_TEST(unit_of(Quantity::specific_heat, 0.896) == "J/(g K)");
  BOOST_TEST(unit_of(Quantity::sound_speed, 5.386) == "km/s");
  BOOST_TEST(unit_of(Quantity::speed, 1.47e6) == "mm/s");
  BOOST_TEST(unit_of(Quantity::length, 119.0) == "mm");
  const auto celsius = likely_unit(Quantity::temperature, 21.0);
  BOOST_TEST_REQUIRE(celsius.has_value());
  BOOST_TEST(celsius->unit == "degC");
  BOOST_TEST(celsius->value_in_si == 294.15, boost::test_tools::tolerance(1e-12));
  // -20 degC is refused by a temperature's range (> 0 K); the hint still names the unit.
  BOOST_TEST(unit_of(Quantity::temperature, -20.0) == "degC");
}

BOOST_AUTO_TEST_CASE(plausible_zero_and_unexplained_values_give_no_finding) {
  // The shipped 6061-T6 values and scenes.
  BOOST_TEST(unit_of(Quantity::density, 2700.0).empty());
  BOOST_TEST(unit_of(Quantity::elastic_modulus, 26e9).empty());
  BOOST_TEST(unit_of(Quantity::stress, 324e6).empty());
  BOOST_TEST(unit_of(Quantity::temperature, 294.0).empty());
  BOOST_TEST(unit_of(Quantity::temperature, 77.0).empty());  // liquid nitrogen is real
  BOOST_TEST(unit_of(Quantity::specific_heat, 896.0).empty());
  BOOST_TEST(unit_of(Quantity::sound_speed, 5386.0).empty());
  BOOST_TEST(unit_of(Quantity::speed, 1470.0).empty());
  BOOST_TEST(unit_of(Quantity::speed, 0.5).empty());  // slow is plausible
  BOOST_TEST(unit_of(Quantity::length, 0.119).empty());
  // Zero (B = 0, a stress-free component), non-finite values, and implausible values that no
  // common unit explains (a foam of 30 kg/m^3; an elastic-only A = 1e15 Pa) are left alone.
  BOOST_TEST(unit_of(Quantity::stress, 0.0).empty());
  BOOST_TEST(unit_of(Quantity::density, std::numeric_limits<double>::quiet_NaN()).empty());
  BOOST_TEST(unit_of(Quantity::density, std::numeric_limits<double>::infinity()).empty());
  BOOST_TEST(unit_of(Quantity::density, 30.0).empty());
  BOOST_TEST(unit_of(Quantity::stress, 1e15).empty());
  // A negative value of a positive-only quantity is a wrong sign, not a unit: -5 kg/m^3 was
  // given the g/cm^3 hint (-5 g/cm^3 = -5000 kg/m^3). Stress and speed keep theirs.
  BOOST_TEST(unit_of(Quantity::density, -5.0).empty());
  BOOST_TEST(unit_of(Quantity::elastic_modulus, -26.0).empty());
  BOOST_TEST(unit_of(Quantity::specific_heat, -0.9).empty());
  BOOST_TEST(unit_of(Quantity::sound_speed, -5.4).empty());
  BOOST_TEST(unit_of(Quantity::length, -119.0).empty());
  BOOST_TEST(unit_of(Quantity::speed, -1.47e6) == "mm/s");
}

BOOST_AUTO_TEST_CASE(the_hint_names_value_unit_si_value_and_si_unit) {
  const auto hint = unit_hint(Quantity::elastic_modulus, 26.0);
  BOOST_TEST_REQUIRE(hint.has_value());
  BOOST_TEST(*hint == "26 looks like GPa (26 GPa = 2.6e+10 Pa); SI expects Pa");
  BOOST_TEST(!unit_hint(Quantity::elastic_modulus, 26e9).has_value());
}

BOOST_AUTO_TEST_CASE(every_quantity_has_a_consistent_table) {
  for (Quantity q :
       {Quantity::density, Quantity::elastic_modulus, Quantity::stress, Quantity::temperature,
        Quantity::specific_heat, Quantity::sound_speed, Quantity::speed, Quantity::length}) {
    const QuantityUnits& u = quantity_units(q);
    BOOST_TEST(u.low < u.typical);
    BOOST_TEST(u.typical < u.high);
    BOOST_TEST(!u.alternatives.empty());
    BOOST_TEST(unit_of(q, u.typical).empty());  // the typical value itself is never flagged
  }
}

BOOST_AUTO_TEST_CASE(a_reader_warns_for_an_admissible_value_and_reads_it) {
  const Json j = Json::parse(R"({"density": 2.7, "shear_modulus": 26e9})");
  InputProblems problems("m.json");
  JsonReader r(j, "", problems);
  BOOST_TEST(r.quantity("density", Quantity::density, Range::positive(), "") == 2.7);
  BOOST_TEST(r.quantity("shear_modulus", Quantity::elastic_modulus, Range::positive(), "") == 26e9);
  BOOST_TEST(r.quantity_or("room_temperature", 294.0, Quantity::temperature, Range::positive(),
                           "") == 294.0);
  r.reject_unknown_keys();
  BOOST_TEST(problems.empty());
  BOOST_TEST_REQUIRE(problems.warnings().size() == 1u);
  BOOST_TEST(problems.warnings()[0] ==
             "m.json: /density: 2.7 looks like g/cm^3 (2.7 g/cm^3 = 2700 kg/m^3); SI expects "
             "kg/m^3; the value is used as given");
}

BOOST_AUTO_TEST_CASE(an_inadmissible_value_is_an_error_that_names_the_likely_unit) {
  const Json j = Json::parse(R"({"temperature": -20, "density": 2.7})");
  InputProblems problems("p.json");
  JsonReader r(j, "", problems);
  r.quantity("temperature", Quantity::temperature, Range::open(0.0, 1e4), "initial temperature");
  r.quantity("density", Quantity::density, Range::positive(), "");
  std::string text;
  try {
    problems.throw_if_any();
  } catch (const InputError& e) {
    text = e.what();
  }
  BOOST_TEST(contains(text,
                      "p.json: /temperature: expected a number in (0, 10000), got -20 "
                      "(initial temperature): -20 looks like degC (-20 degC = 253.15 K)"));
  // Warnings travel with the error: the unit slip may explain it.
  BOOST_TEST(contains(text, "warning: p.json: /density: 2.7 looks like g/cm^3"));
}

BOOST_AUTO_TEST_CASE(problems_of_a_referenced_file_are_nested_under_the_referring_key) {
  InputProblems inner("material.json");
  inner.add("/density", "expected a number in (0, 30000], got -1");
  inner.warn("/shear_modulus", "26 looks like GPa");
  InputProblems outer("scene.json");
  try {
    inner.throw_if_any();
  } catch (const InputError& e) {
    outer.add_nested("/materials/al/file", "in material ", e);
  }
  BOOST_TEST(outer.count() == 1u);
  BOOST_TEST_REQUIRE(outer.warnings().size() == 1u);
  BOOST_TEST(outer.warnings()[0] ==
             "scene.json: /materials/al/file: in material material.json: /shear_modulus: 26 looks "
             "like GPa");
}

BOOST_AUTO_TEST_SUITE_END()
