// Path reading: named paths expand into the legs they promise (named_paths.hpp), log-spaced steps
// close the leg, and bad documents name the JSON key.
#include "pointdriver/path/path.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>

#include "pointdriver/test_paths.hpp"

using namespace impact;
using namespace impact::pointdriver;
using namespace impact::pointdriver::testing;

BOOST_AUTO_TEST_SUITE(pointdriver_path)

BOOST_AUTO_TEST_CASE(uniaxial_stress_expands_to_L_xx_with_zero_lateral_stress) {
  const Path p = read_path(
      document(Json{
          {"type", "uniaxial_stress"}, {"strain", 0.2}, {"strain_rate", 1000.0}, {"steps", 100}}),
      "test");
  BOOST_REQUIRE_EQUAL(p.legs.size(), 1u);
  const Leg& l = p.legs[0];
  BOOST_TEST(l.duration == 0.2 / 1000.0, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(l.steps == 100);
  BOOST_TEST(l.velocity_gradient[0].value_or(-1.0) == 1000.0);  // xx
  // Shear components of L fixed at zero (an isotropic material has no shear strain without
  // shear stress), yy and zz free for the stress equations.
  for (int k : {1, 2, 3, 5, 6, 7}) BOOST_TEST(l.velocity_gradient[k].value_or(-1.0) == 0.0);
  BOOST_TEST(!l.velocity_gradient[4].has_value());  // yy
  BOOST_TEST(!l.velocity_gradient[8].has_value());  // zz
  BOOST_TEST(l.stress[1].value_or(-1.0) == 0.0);    // yy
  BOOST_TEST(l.stress[2].value_or(-1.0) == 0.0);    // zz
  BOOST_TEST(!l.stress[0].has_value());             // xx is kinematic
  // The expansion is visible in the resolved document written beside every run.
  BOOST_TEST(p.resolved["legs"][0].contains("velocity_gradient"));
  BOOST_TEST(!p.resolved["legs"][0].contains("type"));
}

BOOST_AUTO_TEST_CASE(uniaxial_strain_fixes_all_nine_velocity_gradient_components) {
  const Path p = read_path(
      document(Json{
          {"type", "uniaxial_strain"}, {"strain", -0.1}, {"strain_rate", -100.0}, {"steps", 10}}),
      "test");
  const Leg& l = p.legs.at(0);
  BOOST_TEST(l.velocity_gradient[0].value_or(0.0) == -100.0);
  for (int k = 1; k < 9; ++k) BOOST_TEST(l.velocity_gradient[k].value_or(1.0) == 0.0);
  for (int c = 0; c < 6; ++c) BOOST_TEST(!l.stress[c].has_value());
}

BOOST_AUTO_TEST_CASE(triaxial_expands_to_confinement_then_axial_loading_at_that_pressure) {
  const double pc = 100e6;
  const Path p = read_path(document(Json{{"type", "triaxial"},
                                         {"confining_pressure", pc},
                                         {"confinement_duration", 1e-4},
                                         {"strain", -0.1},
                                         {"strain_rate", -1000.0},
                                         {"steps", 10}}),
                           "test");
  BOOST_REQUIRE_EQUAL(p.legs.size(), 2u);
  for (int c = 0; c < 3; ++c) BOOST_TEST(p.legs[0].stress[c].value_or(0.0) == -pc);
  BOOST_TEST(p.legs[1].velocity_gradient[0].value_or(0.0) == -1000.0);
  BOOST_TEST(p.legs[1].stress[1].value_or(0.0) == -pc);
  BOOST_TEST(p.legs[1].stress[2].value_or(0.0) == -pc);
}

BOOST_AUTO_TEST_CASE(constant_triaxiality_sets_lateral_to_axial_stress_ratio_from_eta) {
  // sigma = diag(s, k s, k s): eta = (1 + 2k) / (3 (1 - k))  =>  k = (3 eta - 1) / (3 eta + 2).
  for (double eta : {0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0}) {
    const Path p = read_path(document(Json{{"type", "constant_triaxiality"},
                                           {"triaxiality", eta},
                                           {"strain", 0.1},
                                           {"strain_rate", 1.0},
                                           {"steps", 10}}),
                             "test");
    const double k = p.legs.at(0).stress_ratio[1].value_or(-99.0);
    BOOST_TEST((1 + 2 * k) / (3 * (1 - k)) == eta, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(p.legs[0].stress_ratio[2].value_or(-99.0) == k);
  }
}

BOOST_AUTO_TEST_CASE(load_unload_reverse_spreads_the_rotation_in_proportion_to_duration) {
  const Path p = read_path(document(Json{{"type", "load_unload_reverse"},
                                         {"strain", 0.02},
                                         {"strain_rate", 100.0},
                                         {"unload_duration", 1e-4},
                                         {"reverse_strain", 0.04},
                                         {"steps", 10},
                                         {"rotation", {{"axis", {0, 0, 1}}, {"angle", 1.0}}}}),
                           "test");
  BOOST_REQUIRE_EQUAL(p.legs.size(), 3u);
  double total = 0.0, angle = 0.0;
  for (const Leg& l : p.legs) total += l.duration;
  for (const Leg& l : p.legs) {
    BOOST_TEST(l.rotation_angle == l.duration / total, boost::test_tools::tolerance(1e-14));
    angle += l.rotation_angle;
  }
  BOOST_TEST(angle == 1.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(p.legs[1].stress[0].value_or(-1.0) == 0.0);  // unload to sigma_xx = 0
  BOOST_TEST(p.legs[2].velocity_gradient[0].value_or(0.0) == -100.0);
}

BOOST_AUTO_TEST_CASE(log_spaced_steps_start_with_first_step_and_sum_to_the_duration) {
  const double duration = 1e-2, first = 1e-6;
  const int steps = 60;
  const Rows r = run_document(document(Json{{"duration", duration},
                                            {"steps", steps},
                                            {"first_step", first},
                                            {"velocity_gradient", {{"xx", 1.0}}},
                                            {"stress", {{"yy", 0.0}, {"zz", 0.0}}}}));
  BOOST_REQUIRE(r.result.completed);
  BOOST_REQUIRE_EQUAL(r.rows.size(), static_cast<std::size_t>(steps + 1));
  BOOST_TEST(r.rows[1].time == first, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(r.rows.back().time == duration, boost::test_tools::tolerance(1e-14));
  // Geometric: every step is the previous one times the same ratio.
  const double g = (r.rows[2].time - r.rows[1].time) / r.rows[1].time;
  BOOST_TEST(g > 1.0);
  for (int k = 2; k < steps - 1; ++k) {
    const double ratio =
        (r.rows[k + 1].time - r.rows[k].time) / (r.rows[k].time - r.rows[k - 1].time);
    BOOST_TEST(ratio == g, boost::test_tools::tolerance(1e-8));
  }
}

BOOST_AUTO_TEST_CASE(max_strain_increment_sets_the_number_of_steps) {
  const Path p = read_path(document(Json{{"type", "uniaxial_stress"},
                                         {"strain", 0.1},
                                         {"strain_rate", 10.0},
                                         {"max_strain_increment", 1e-3}}),
                           "test");
  BOOST_TEST(p.legs.at(0).steps == 100);
}

BOOST_AUTO_TEST_CASE(every_problem_is_reported_with_its_key_path) {
  Json doc = document(Json{{"steps", 10}, {"velocity_gradient", {{"xx", 1.0}}}});
  doc["temprature"] = 300.0;
  try {
    read_path(doc, "bad.json");
    BOOST_FAIL("read_path accepted a leg without duration and an unknown key");
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("bad.json") != std::string::npos);
    BOOST_TEST(m.find("/legs/0/duration") != std::string::npos);
    BOOST_TEST(m.find("/temprature") != std::string::npos);
    BOOST_TEST(m.find("temperature") != std::string::npos);
  }
}

BOOST_AUTO_TEST_SUITE_END()
