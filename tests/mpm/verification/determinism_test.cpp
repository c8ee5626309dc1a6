// Threads and determinism (docs/mpm.md#threads-and-determinism) on
// data/scenes/verification/two_spheres.json (two elastic spheres, 4304 particles, head-on at
// 2 x 10 m/s in one velocity field), 50 steps of the default gimp/MUSL.
// (a) The same scene and thread count (2) give bit-identical results: every particle's position,
//     velocity and stress (==) after 50 steps, and every ledger row at every step.
// (b) 1 against 2 threads: the scatters (P2G, the MUSL re-map) sum each node in one order
//     whatever the thread count (mpm/step/scatter_order.hpp), and every other input of a
//     particle's step is per node or per particle, or a min/max: every particle's position,
//     velocity and stress are bit-identical. The ledger's sums over particles and nodes are
//     taken per fixed chunk and added in chunk order (G2P, the stress update, contact), so every
//     ledger row is bit-identical too (before, G2P's kinetic energy and momentum were per-thread
//     partials and differed by about 1e-14 of E0).
// (c) The same for two bodies in friction contact on a wall under gravity (block_on_block.json:
//     contact's friction heat summed over nodes) on 1, 2 and 3 threads.
#include <boost/test/unit_test.hpp>

#include <algorithm>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

constexpr int kSteps = 50;

struct Result {
  std::vector<Vec3> x, v;
  std::vector<Mat3> stress;
  std::vector<std::string> columns;       ///< the ledger's
  std::vector<std::vector<double>> rows;  ///< ledger values after every step
  double initial_energy = 0.0;
};

// Runs one Simulation to the end before the next is built: the OpenMP thread count is global.
Result run_steps(int threads, const char* scene_file = "two_spheres.json") {
  const Scene scene = test::verification_scene(scene_file);
  Simulation sim(scene, threads);
  BOOST_REQUIRE(sim.threads() == threads);
  Result r;
  r.initial_energy = sim.ledger().initial_energy();
  r.columns = sim.ledger().columns();
  for (int i = 0; i < kSteps && !sim.finished(); ++i) {
    sim.step();
    r.rows.push_back(sim.ledger().values(sim.ledger().row()));
  }
  BOOST_REQUIRE(sim.steps() == kSteps);
  const Particles& P = sim.particles();
  r.x = P.x;
  r.v = P.v;
  for (const PointState& s : P.state) r.stress.push_back(s.stress);
  return r;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_determinism)

BOOST_AUTO_TEST_CASE(same_thread_count_is_bit_identical) {
  const Result a = run_steps(2), b = run_steps(2);
  BOOST_REQUIRE(a.x.size() == b.x.size());
  std::size_t differ = 0;
  for (std::size_t p = 0; p < a.x.size(); ++p) {
    if (!(a.x[p] == b.x[p]) || !(a.v[p] == b.v[p]) || !(a.stress[p] == b.stress[p])) ++differ;
  }
  BOOST_TEST_MESSAGE(a.x.size() << " particles, " << kSteps << " steps, 2 threads twice: " << differ
                                << " particles differ");
  BOOST_TEST(differ == 0u);
  BOOST_REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i) BOOST_TEST(a.rows[i] == b.rows[i]);
}

BOOST_AUTO_TEST_CASE(one_and_two_threads_give_the_same_particles) {
  const Result a = run_steps(1), b = run_steps(2);
  BOOST_REQUIRE(a.x.size() == b.x.size());
  std::size_t differ = 0;
  for (std::size_t p = 0; p < a.x.size(); ++p) {
    if (!(a.x[p] == b.x[p]) || !(a.v[p] == b.v[p]) || !(a.stress[p] == b.stress[p])) ++differ;
  }
  BOOST_TEST_MESSAGE("1 vs 2 threads after " << kSteps << " steps: " << differ
                                             << " particles differ");
  BOOST_TEST(differ == 0u);
  BOOST_REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    BOOST_TEST(a.rows[i] == b.rows[i], "step " << i + 1);
}

BOOST_AUTO_TEST_CASE(friction_contact_books_the_same_bits_on_any_thread_count) {
  const Result one = run_steps(1, "block_on_block.json");
  for (int threads : {2, 3}) {
    const Result many = run_steps(threads, "block_on_block.json");
    BOOST_REQUIRE(many.x.size() == one.x.size());
    std::size_t differ = 0;
    for (std::size_t p = 0; p < one.x.size(); ++p)
      if (!(one.x[p] == many.x[p]) || !(one.v[p] == many.v[p]) ||
          !(one.stress[p] == many.stress[p]))
        ++differ;
    BOOST_TEST(differ == 0u, differ << " particles differ on " << threads << " threads");
    BOOST_REQUIRE(many.rows.size() == one.rows.size());
    for (std::size_t i = 0; i < one.rows.size(); ++i)
      BOOST_TEST(many.rows[i] == one.rows[i], "step " << i + 1 << " on " << threads << " threads");
  }
  // The scene's books do move: friction heat is booked within these steps.
  const auto heat = std::find(one.columns.begin(), one.columns.end(), "friction_heat [J]");
  BOOST_REQUIRE(heat != one.columns.end());
  BOOST_TEST(one.rows.back()[std::size_t(heat - one.columns.begin())] > 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
