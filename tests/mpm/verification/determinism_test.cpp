// Threads and determinism (docs/mpm.md#threads-and-determinism) on
// data/scenes/verification/two_spheres.json (two elastic spheres, 4304 particles, head-on at
// 2 x 10 m/s in one velocity field), 50 steps of the default gimp/MUSL.
// (a) The same scene and thread count (2) give bit-identical results: every particle's position,
//     velocity and stress (==) after 50 steps, and every ledger row at every step.
// (b) 1 against 2 threads: the scatters (P2G, the MUSL re-map) sum each node in one order
//     whatever the thread count (mpm/step/scatter_order.hpp), and every other input of a
//     particle's step is per node or per particle, or a min/max: every particle's position,
//     velocity and stress are bit-identical. Only the ledger's particle sums (kinetic energy,
//     momentum) are added in per-thread partials, so its energies differ by round-off: asserted
//     below 1e-12 of E0 (measured 1.8e-14 with the former per-thread grid buffers).
#include <boost/test/unit_test.hpp>

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
Result run_steps(int threads) {
  const Scene scene = test::verification_scene("two_spheres.json");
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
  // Energy columns of the ledger (kinetic, strain, total) relative to E0, at every step.
  const auto& cols = a.columns;
  double de = 0.0;
  for (std::size_t c = 0; c < cols.size(); ++c) {
    if (cols[c].find("energy [J]") == std::string::npos) continue;
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
      de = std::max(de, std::abs(a.rows[i][c] - b.rows[i][c]) / a.initial_energy);
    }
  }
  BOOST_TEST_MESSAGE("1 vs 2 threads after " << kSteps << " steps: " << differ
                                             << " particles differ, energies " << de << " of E0");
  BOOST_TEST(differ == 0u);
  BOOST_TEST(de < 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
