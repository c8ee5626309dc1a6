// Replay files: a step the solver cannot solve stops the run with completed = false and a path
// that starts from the state at the start of that step and fails the same way.
#include "pointdriver/driver/replay.hpp"

#include <boost/test/unit_test.hpp>

#include "pointdriver/test_paths.hpp"

using namespace impact;
using namespace impact::pointdriver;
using namespace impact::pointdriver::testing;

namespace {

/// Uniaxial stress whose plastic steps cannot be solved: one Newton iteration with the elastic
/// Jacobian and no cut-back. The elastic steps converge (the elastic Jacobian is exact there).
Json unsolvable() {
  return document(
      Json{{"type", "uniaxial_stress"}, {"strain", 0.02}, {"strain_rate", 1000.0}, {"steps", 20}},
      Json::object(),
      Json{{"solver", {{"max_iterations", 1}, {"max_cutbacks", 0}, {"jacobian", "elastic"}}}});
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pointdriver_replay)

BOOST_AUTO_TEST_CASE(an_unsolvable_step_stops_the_run_with_a_replay_path) {
  const Rows r = run_document(unsolvable());
  BOOST_TEST(!r.result.completed);
  BOOST_REQUIRE(r.result.replay.has_value());
  BOOST_TEST(r.result.error.find("did not converge") != std::string::npos);
  BOOST_TEST(r.result.steps + 1 == static_cast<int>(r.rows.size()));
  // It failed on the first plastic step: every row written is elastic.
  BOOST_TEST(r.rows.size() > 2u);
  BOOST_TEST(r.rows.back().state.plastic_strain == 0.0);
}

BOOST_AUTO_TEST_CASE(the_replay_starts_from_the_last_solved_state_and_fails_the_same_way) {
  const Rows r = run_document(unsolvable());
  BOOST_REQUIRE(r.result.replay.has_value());
  const Json replay = Json::parse(r.result.replay->dump());  // as written to and read from a file
  const Path path = read_path(replay, "replay.json");
  BOOST_REQUIRE_EQUAL(path.legs.size(), 1u);
  BOOST_TEST(path.legs[0].steps == 1);
  const Row& before = r.rows.back();
  BOOST_TEST((path.initial_state.stress - before.state.stress).cwiseAbs().maxCoeff() == 0.0);
  BOOST_TEST((path.initial_state.F - before.state.F).cwiseAbs().maxCoeff() == 0.0);
  BOOST_TEST(path.legs[0].duration == r.rows[1].time, boost::test_tools::tolerance(1e-12));

  std::vector<Row> rows;
  const RunResult again = run_path(path, [&](const Row& row) { rows.push_back(row); });
  BOOST_TEST(!again.completed);
  BOOST_TEST(again.steps == 0);
  BOOST_TEST(again.error.find("did not converge") != std::string::npos);
  BOOST_REQUIRE(!rows.empty());
  BOOST_TEST((rows.front().state.stress - before.state.stress).cwiseAbs().maxCoeff() == 0.0);

  // With the default solver the same step is solved: the failure was the solver's, not the path's.
  Json fixed = replay;
  fixed.erase("solver");
  std::vector<Row> solved;
  const RunResult ok =
      run_path(read_path(fixed, "replay.json"), [&](const Row& row) { solved.push_back(row); });
  BOOST_TEST(ok.completed);
  BOOST_TEST(solved.back().state.plastic_strain > 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
