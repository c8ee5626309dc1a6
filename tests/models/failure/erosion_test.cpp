// Erosion of failed points (report sec. 3): each algorithm on a tensile and a compressive state,
// exact equalities; names round-trip; unknown names (including the 2004 code's catch-all) rejected.
#include "models/failure/erosion.hpp"

#include <boost/test/unit_test.hpp>
#include <string>

using namespace impact;

namespace {

// Mean stress +100 MPa (tensile) or -100 MPa (compressive), with a shear and a normal deviator.
// Diagonals chosen so that the mean and the deviator are exact in binary floating point.
Mat3 state(double mean_stress) {
  Mat3 s;
  s << mean_stress + 64e6, 16e6, 0.0, 16e6, mean_stress - 32e6, -8e6, 0.0, -8e6, mean_stress - 32e6;
  return s;
}

std::string problems_text(const InputProblems& problems) {
  try {
    problems.throw_if_any();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(failure_erosion)

BOOST_AUTO_TEST_CASE(none_and_keep_stress_leave_the_stress_unchanged) {
  for (double m : {100e6, -100e6}) {
    BOOST_TEST((erode_stress(Erosion::none, state(m)) == state(m)));
    BOOST_TEST((erode_stress(Erosion::keep_stress, state(m)) == state(m)));
  }
}

BOOST_AUTO_TEST_CASE(allow_no_tension_drops_a_tensile_mean_stress_and_keeps_the_deviator) {
  const Mat3 eroded = erode_stress(Erosion::allow_no_tension, state(100e6));
  BOOST_TEST((eroded == state(0.0)));  // exactly the deviator
  BOOST_TEST(eroded.trace() == 0.0);
  BOOST_TEST((erode_stress(Erosion::allow_no_tension, state(-100e6)) == state(-100e6)));
  BOOST_TEST((erode_stress(Erosion::allow_no_tension, state(0.0)) == state(0.0)));
}

BOOST_AUTO_TEST_CASE(zero_stress_zeroes_every_component) {
  for (double m : {100e6, -100e6})
    BOOST_TEST((erode_stress(Erosion::zero_stress, state(m)) == Mat3::Zero()));
}

BOOST_AUTO_TEST_CASE(names_are_the_reports_spelling_and_round_trip) {
  BOOST_TEST(erosion_name(Erosion::allow_no_tension) == "AllowNoTension");
  BOOST_TEST(erosion_name(Erosion::keep_stress) == "KeepStress");
  BOOST_TEST(erosion_name(Erosion::zero_stress) == "ZeroStress");
  BOOST_TEST(erosion_name(Erosion::none) == "none");
  for (Erosion e :
       {Erosion::none, Erosion::allow_no_tension, Erosion::keep_stress, Erosion::zero_stress})
    BOOST_TEST((erosion_from_name(erosion_name(e)) == e));
  BOOST_TEST(!erosion_from_name("RemoveMass").has_value());
  BOOST_TEST(!erosion_from_name("keepstress").has_value());
}

BOOST_AUTO_TEST_CASE(reader_reads_the_algorithm) {
  const Json j = Json::parse(R"({"algorithm": "AllowNoTension"})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/erosion", problems);
  BOOST_TEST((read_erosion(r) == Erosion::allow_no_tension));
  BOOST_TEST(problems.empty());
}

BOOST_AUTO_TEST_CASE(reader_names_the_key_path_of_an_unknown_name_and_an_unknown_key) {
  // The 2004 code treated any unknown string as KeepStress; here it is an error.
  const Json j = Json::parse(R"({"algorithm": "KeepStres", "factor": 0.1})");
  InputProblems problems("mat.json");
  JsonReader r(j, "/constitutive_model/erosion", problems);
  read_erosion(r);
  const std::string text = problems_text(problems);
  BOOST_TEST(
      text.find("mat.json: /constitutive_model/erosion/algorithm: unknown name \"KeepStres\"; "
                "known: none, AllowNoTension, KeepStress, ZeroStress (did you mean "
                "KeepStress?)") != std::string::npos);
  BOOST_TEST(text.find("mat.json: /constitutive_model/erosion/factor: unknown key") !=
             std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
