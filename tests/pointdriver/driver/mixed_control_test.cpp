// Mixed control: stress-controlled components reach their targets within the solver tolerance at
// every step, whatever the material does (elastic, plastic, confined).
#include "pointdriver/driver/mixed_control.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>

#include "pointdriver/test_paths.hpp"

using namespace impact;
using namespace impact::pointdriver;
using namespace impact::pointdriver::testing;

namespace {

/// The solver's acceptance bound on a stress row at this stress (path.hpp SolverSettings).
double allowed(const Row& r) {
  const SolverSettings s;
  return s.stress_tolerance + s.relative_stress_tolerance * r.state.stress.cwiseAbs().maxCoeff();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pointdriver_mixed_control)

BOOST_AUTO_TEST_CASE(uniaxial_stress_plan_has_two_stress_unknowns_and_four_stress_free_shears) {
  Leg leg;
  leg.duration = 1e-3;
  leg.steps = 1;
  leg.velocity_gradient[0] = 1000.0;
  leg.stress[1] = 0.0;
  leg.stress[2] = 0.0;
  const ControlPlan plan = make_plan(leg, Mat3::Identity(), Mat3::Zero());
  // yy, zz given; xy, yz, zx not given, hence stress-free: five stress equations, five unknowns.
  BOOST_TEST(plan.equations.size() == 5u);
  BOOST_TEST(plan.generators.size() == 5u);
  BOOST_TEST(plan.L_fixed(0, 0) == 1000.0);
  BOOST_TEST(!plan.all_deformation);
}

BOOST_AUTO_TEST_CASE(lateral_stress_of_plastic_uniaxial_stress_converges_to_tolerance) {
  const Rows r = run_document(document(
      Json{{"type", "uniaxial_stress"}, {"strain", 0.1}, {"strain_rate", 1000.0}, {"steps", 200}}));
  BOOST_REQUIRE(r.result.completed);
  BOOST_TEST(r.rows.back().state.plastic_strain > 0.09);  // strongly plastic
  int iterations = 0;
  for (const Row& row : r.rows) {
    BOOST_TEST(std::abs(row.state.stress(1, 1)) <= allowed(row));
    BOOST_TEST(std::abs(row.state.stress(2, 2)) <= allowed(row));
    BOOST_TEST(std::abs(row.state.stress(0, 1)) <= allowed(row));
    iterations += row.iterations;
  }
  BOOST_TEST(iterations > 0);  // the Newton solve actually ran and is reported
}

BOOST_AUTO_TEST_CASE(triaxial_confinement_holds_the_lateral_pressure_during_axial_loading) {
  const double pc = 150e6, tc = 1e-4;
  const Rows r = run_document(document(Json{{"type", "triaxial"},
                                            {"confining_pressure", pc},
                                            {"confinement_duration", tc},
                                            {"strain", -0.05},
                                            {"strain_rate", -1000.0},
                                            {"steps", 100}}));
  BOOST_REQUIRE(r.result.completed);
  for (const Row& row : r.rows) {
    if (row.step == 0) continue;
    if (row.leg == 0) {  // hydrostatic ramp 0 -> -pc
      for (int i = 0; i < 3; ++i) {
        BOOST_TEST(std::abs(row.state.stress(i, i) + pc * row.time / tc) <= allowed(row));
      }
    } else {
      BOOST_TEST(std::abs(row.state.stress(1, 1) + pc) <= allowed(row));
      BOOST_TEST(std::abs(row.state.stress(2, 2) + pc) <= allowed(row));
    }
  }
  // Under confinement the axial stress exceeds the confinement by the flow stress.
  const Row& last = r.rows.back();
  BOOST_TEST(last.state.plastic_strain > 0.0);
  BOOST_TEST(-last.state.stress(0, 0) - pc > 324e6);
}

BOOST_AUTO_TEST_CASE(a_prescribed_shear_stress_is_reached_with_no_spin) {
  const double txy = 50e6;
  const Rows r = run_document(document(Json{{"duration", 1e-4},
                                            {"steps", 50},
                                            {"velocity_gradient", {{"xx", 500.0}}},
                                            {"stress", {{"xy", txy}, {"yy", 0.0}, {"zz", 0.0}}}}));
  BOOST_REQUIRE(r.result.completed);
  const Row& last = r.rows.back();
  BOOST_TEST(std::abs(last.state.stress(0, 1) - txy) <= allowed(last));
  BOOST_TEST(std::abs(last.L(0, 1) - last.L(1, 0)) <= 1e-9 * std::abs(last.L(0, 1)));  // W_xy = 0
}

BOOST_AUTO_TEST_SUITE_END()
