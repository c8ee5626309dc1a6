// Failure policies of run_path: stop ends the run at the failure, freeze keeps the failed state,
// continue goes on with the material's erosion rule. The failure is JC damage reaching 1 (TEPLA)
// in uniaxial tension, at eps_p = eps_f = D1 + D2 exp(D3/3) = 0.470 (report eq. 7).
#include "pointdriver/driver/driver.hpp"

#include <boost/test/unit_test.hpp>
#include <ostream>

#include "pointdriver/test_paths.hpp"

namespace impact {
// Lets BOOST_TEST print a failure cause by name.
inline std::ostream& boost_test_print_type(std::ostream& out, FailureCause c) {
  return out << to_string(c);
}
}  // namespace impact

using namespace impact;
using namespace impact::pointdriver;
using namespace impact::pointdriver::testing;

namespace {

Rows tension_to_failure(const std::string& policy, const std::string& erosion) {
  return run_document(
      document(Json{{"type", "uniaxial_stress"},
                    {"strain", 0.6},
                    {"strain_rate", 1.0},
                    {"max_strain_increment", 2e-3}},
               Json{{"constitutive_model", {{"erosion", {{"algorithm", erosion}}}}}},
               Json{{"failure_policy", policy}}));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pointdriver_failure_policy)

BOOST_AUTO_TEST_CASE(stop_ends_the_run_at_the_failure_time) {
  const Rows r = tension_to_failure("stop", "KeepStress");
  BOOST_REQUIRE(r.result.completed);
  BOOST_TEST(r.result.failure == FailureCause::tepla);
  BOOST_TEST(r.result.end_time == r.result.failure_time);
  BOOST_TEST(r.rows.back().time == r.result.failure_time);
  BOOST_TEST(r.rows.back().failure == FailureCause::tepla);
  BOOST_TEST(r.rows.back().state.damage >= 1.0);
  BOOST_TEST(r.rows[r.rows.size() - 2].state.damage < 1.0);
  BOOST_TEST(r.result.failure_time < 0.6);  // before the end of the path
}

BOOST_AUTO_TEST_CASE(freeze_keeps_the_failed_state_to_the_end_of_the_path) {
  const Rows r = tension_to_failure("freeze", "KeepStress");
  BOOST_REQUIRE(r.result.completed);
  BOOST_TEST(r.result.failure == FailureCause::tepla);
  BOOST_TEST(r.result.end_time == 0.6, boost::test_tools::tolerance(1e-12));
  std::size_t failed_row = 0;
  while (failed_row < r.rows.size() && r.rows[failed_row].failure == FailureCause::none)
    ++failed_row;
  BOOST_REQUIRE(failed_row + 10 < r.rows.size());
  const Row& at = r.rows[failed_row];
  BOOST_TEST(at.state.stress(0, 0) > 300e6);  // KeepStress: the failed point keeps its stress
  for (std::size_t i = failed_row + 1; i < r.rows.size(); ++i) {
    BOOST_TEST((r.rows[i].state.stress - at.state.stress).cwiseAbs().maxCoeff() == 0.0);
    BOOST_TEST(r.rows[i].state.plastic_strain == at.state.plastic_strain);
  }
}

BOOST_AUTO_TEST_CASE(continue_goes_on_with_the_erosion_rule_of_the_material) {
  const Rows r = tension_to_failure("continue", "ZeroStress");
  BOOST_REQUIRE(r.result.completed);
  BOOST_TEST(r.result.failure == FailureCause::tepla);
  BOOST_TEST(r.result.end_time == 0.6, boost::test_tools::tolerance(1e-12));
  bool after = false;
  int zero_rows = 0;
  for (const Row& row : r.rows) {
    if (after) {
      BOOST_TEST(row.state.failed);
      BOOST_TEST(row.state.stress.cwiseAbs().maxCoeff() == 0.0);  // ZeroStress erosion
      ++zero_rows;
    }
    after = after || row.failure != FailureCause::none;
  }
  BOOST_TEST(zero_rows > 10);
  // The strain keeps being applied after the failure.
  BOOST_TEST(std::log(r.rows.back().F(0, 0)) == 0.6, boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_SUITE_END()
