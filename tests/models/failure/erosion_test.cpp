// Erosion of failed points (report sec. 3): each algorithm on a tensile and a compressive state,
// exact equalities; names round-trip; unknown names (including the 2004 code's catch-all) rejected.
// Suite failure_erosion_in_update: the same definitions through ElasticPlastic::update (step 6 of
// models/material/elastic_plastic.cpp) on a point that fails by TEPLA on this step (damage D = 1
// carried in, a plastic step: (f/f_c)^2 + D^2 = 1), tensile and compressive, against the update of
// the same material with erosion none (no failure detection). Asserted per algorithm:
//   none            not flagged, stress identical, eroded_energy 0;
//   KeepStress      flagged (cause tepla), stress identical, eroded_energy 0;
//   AllowNoTension  tensile mean stress: the deviator of the un-eroded stress (|mean| <= 1e-12 |s|
//                   and |sigma - dev sigma_ref| <= 1e-12 |sigma_ref|: the stress is eroded in the
//                   unrotated frame and rotated back with a rotation that is the identity to
//                   round-off); compressive: identical;
//   ZeroStress      exactly zero;
// and StepReport::eroded_energy = w(sigma_ref) - w(sigma) with w = s:s/(4 mu) + p^2/(2 K)
// computed here from the lab-frame stresses, to 1e-12 relative (of w(sigma_ref)). A point that had
// already failed gets the erosion again but books no eroded energy (booked on the step of failure
// only: elastic_plastic.hpp).
#include "models/failure/erosion.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "helpers/input_problems.hpp"
#include "models/material/material.hpp"

using namespace impact;
using impact::testing::problems_text;

namespace {

// Mean stress +100 MPa (tensile) or -100 MPa (compressive), with a shear and a normal deviator.
// Diagonals chosen so that the mean and the deviator are exact in binary floating point.
Mat3 state(double mean_stress) {
  Mat3 s;
  s << mean_stress + 64e6, 16e6, 0.0, 16e6, mean_stress - 32e6, -8e6, 0.0, -8e6, mean_stress - 32e6;
  return s;
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

namespace {

const std::string kAl = std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json";

// 6061 with a low, flat yield stress (A = 100 MPa, B = 0) so that the step is plastic, TEPLA the
// only failure check, no damage evolution (D stays at the value carried in) and no heating.
ElasticPlastic failing_model(const char* algorithm) {
  Json o = Json::parse(R"({"constitutive_model": {"flow_stress": {"A": 1.0e8, "B": 0.0},
      "damage": {"type": "none"}, "adiabatic_heating": {"enabled": false},
      "stability_check": {"type": "none"}, "melting": {"do_melting": false}}})");
  o["constitutive_model"]["erosion"] = {{"algorithm", algorithm}};
  return load_material(kAl, o).model;
}

// Complementary elastic energy density, written out here (not the library's expression).
double energy_density(const Mat3& t, double mu, double K) {
  const double p = t.trace() / 3.0;
  double ss = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double s = t(i, j) - (i == j ? p : 0.0);
      ss += s * s;
    }
  return ss / (4.0 * mu) + p * p / (2.0 * K);
}

struct Step {
  PointState s1;
  StepReport r;
};

// One plastic step from a pre-stressed start (mean `sign` x 150 MPa, a deviator at 90 MPa von
// Mises plus a shear), stretching along x and compressing or dilating by 1e3 /s volumetric.
Step step(const ElasticPlastic& model, double sign, bool already_failed = false) {
  PointState s0 = model.initial_state(294.0);
  s0.stress << sign * 150e6 + 60e6, 10e6, 0.0, 10e6, sign * 150e6 - 30e6, 0.0, 0.0, 0.0,
      sign * 150e6 - 30e6;
  s0.damage = 1.0;
  s0.failed = already_failed;
  const double dt = 1e-7;
  const Vec3 rates = Vec3(2e4, -1e4, -1e4) + Vec3::Constant(sign * 1e3);
  const Mat3 F1 = Vec3((rates * dt).array().exp()).asDiagonal();
  Step out;
  out.r = model.update(s0, Mat3(rates.asDiagonal()), F1, dt, out.s1);
  BOOST_REQUIRE(out.r.status == UpdateStatus::ok);
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(failure_erosion_in_update)

BOOST_AUTO_TEST_CASE(each_algorithm_on_a_point_failing_by_tepla_matches_the_definition) {
  const ElasticPlastic reference_model = failing_model("none");
  const double mu = reference_model.params().shear_modulus;
  const double K = reference_model.params().bulk_modulus;
  for (double sign : {1.0, -1.0}) {
    const Step ref = step(reference_model, sign);
    const Mat3& sigma = ref.s1.stress;
    BOOST_REQUIRE(ref.r.plastic);
    BOOST_REQUIRE(sign * mean(sigma) > 0.0);  // tensile / compressive as intended
    BOOST_TEST(to_string(ref.r.failure) == "none");
    BOOST_TEST(!ref.s1.failed);
    BOOST_TEST(ref.r.eroded_energy == 0.0);
    const double w_ref = energy_density(sigma, mu, K);
    for (const char* name : {"AllowNoTension", "KeepStress", "ZeroStress"}) {
      const Step e = step(failing_model(name), sign);
      const Mat3& eroded = e.s1.stress;
      const double expected = w_ref - energy_density(eroded, mu, K);
      BOOST_TEST_MESSAGE(name << (sign > 0 ? " tension" : " compression") << ": mean stress "
                              << mean(sigma) / 1e6 << " -> " << mean(eroded) / 1e6
                              << " MPa; eroded_energy " << e.r.eroded_energy << " J/m^3, expected "
                              << expected << " (w_ref " << w_ref << "), |difference| "
                              << std::abs(e.r.eroded_energy - expected));
      BOOST_TEST_CONTEXT(name << (sign > 0 ? " tension" : " compression")) {
        BOOST_TEST(to_string(e.r.failure) == "tepla");
        BOOST_TEST(e.s1.failed);
        const std::string n = name;
        if (n == "KeepStress" || (n == "AllowNoTension" && sign < 0.0)) {
          BOOST_TEST((eroded == sigma));
        } else if (n == "AllowNoTension") {
          BOOST_TEST(std::abs(mean(eroded)) <= 1e-12 * sigma.norm());
          BOOST_TEST((eroded - deviator(sigma)).norm() <= 1e-12 * sigma.norm());
        } else {
          BOOST_TEST((eroded == Mat3::Zero()));
        }
        BOOST_TEST(std::abs(e.r.eroded_energy - expected) <= 1e-12 * w_ref);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(an_already_failed_point_is_eroded_again_but_books_no_energy) {
  const ElasticPlastic reference_model = failing_model("none");
  for (double sign : {1.0, -1.0}) {
    const Mat3 sigma = step(reference_model, sign).s1.stress;
    const Step zero = step(failing_model("ZeroStress"), sign, /*already_failed=*/true);
    BOOST_TEST(to_string(zero.r.failure) == "none");  // not a new failure
    BOOST_TEST((zero.s1.stress == Mat3::Zero()));
    BOOST_TEST(zero.r.eroded_energy == 0.0);
    const Step ant = step(failing_model("AllowNoTension"), sign, /*already_failed=*/true);
    BOOST_TEST(ant.r.eroded_energy == 0.0);
    if (sign > 0.0) {
      BOOST_TEST((ant.s1.stress - deviator(sigma)).norm() <= 1e-12 * sigma.norm());
    } else {
      BOOST_TEST((ant.s1.stress == sigma));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
