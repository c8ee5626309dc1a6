// The particles' storage order (mpm/particles/particle_order.hpp, solver.shuffle_particles): the
// shuffle is a permutation, the same for the same seed, uniform over the permutations; a run with
// its particles shuffled is the same physics as the seeded run, its sums over particles in another
// order: every particle (matched by its seed index) and every book agree to round-off, not to the
// bit, and the shuffled run's particles are the same bits on 1 and 2 threads.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <map>
#include <numeric>
#include <vector>

#include "../verification_helpers.hpp"
#include "mpm/output/crater.hpp"
#include "mpm/particles/particle_order.hpp"
#include "mpm/step/body_force.hpp"

using namespace impact::mpm;
using impact::Json;
using impact::Vec3;

BOOST_AUTO_TEST_SUITE(mpm_particle_order)

BOOST_AUTO_TEST_CASE(a_shuffle_is_a_permutation_fixed_by_its_seed) {
  for (const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(2), std::size_t(1000)}) {
    std::vector<std::size_t> order = shuffled_order(n, 7);
    BOOST_TEST(order == shuffled_order(n, 7));
    std::sort(order.begin(), order.end());
    std::vector<std::size_t> identity(n);
    std::iota(identity.begin(), identity.end(), std::size_t(0));
    BOOST_TEST(order == identity);
  }
  const std::vector<std::size_t> a = shuffled_order(1000, 1), b = shuffled_order(1000, 2);
  std::size_t same = 0, fixed = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    same += a[i] == b[i];
    fixed += a[i] == i;
  }
  // A random permutation has one fixed point on average, two independent ones one common place.
  BOOST_TEST(same < 10u);
  BOOST_TEST(fixed < 10u);
}

// Each of the 3! orders of three particles over 60 000 seeds: 10 000 expected, binomial standard
// deviation sqrt(60000 / 6 * 5 / 6) = 91; the bound is 5 of them (a biased draw, e.g. j = r %
// (i + 1) without the rejection on a small range, would pass too: this guards the shuffle's shape,
// a swap missing or off by one gives some orders never).
BOOST_AUTO_TEST_CASE(every_order_of_three_is_equally_likely) {
  std::map<std::vector<std::size_t>, int> count;
  for (std::uint64_t seed = 1; seed <= 60000; ++seed) ++count[shuffled_order(3, seed)];
  BOOST_TEST(count.size() == 6u);
  for (const auto& [order, n] : count) BOOST_TEST(std::abs(n - 10000) < 5 * 91);
}

namespace {

struct Run {
  Particles particles;
  LedgerRow row;
};

// Two elastic blocks meeting obliquely in friction contact (mu 0.3: two fields, the contact's
// heat), one particle per cell (384; the sanitizer build runs this too), 12 steps.
Run run(std::uint64_t shuffle, int threads) {
  const Json one = {{"particles_per_cell", {1, 1, 1}}};
  const Json patch = {{"physics", {{"contact", {{"type", "friction"}, {"mu", 0.3}}}}},
                      {"objects", {{"left", one}, {"right", one}}},
                      {"solver", {{"shuffle_particles", shuffle}}}};
  Simulation sim(test::verification_scene("contact_blocks.json", patch), threads);
  for (int s = 0; s < 12; ++s) sim.step();
  return {sim.particles(), sim.ledger().row()};
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_shuffled_run_is_the_seeded_run_to_round_off) {
  const Run seeded = run(0, 1), shuffled = run(5, 1);
  const Particles &A = seeded.particles, &B = shuffled.particles;
  BOOST_TEST_REQUIRE(A.size() == B.size());
  BOOST_TEST(A.id.empty());  // seed order: the index is the seed index
  BOOST_TEST_REQUIRE(B.id.size() == B.size());
  std::size_t moved = 0;
  double dx = 0.0, dv = 0.0, ds = 0.0, stress = 0.0, p_body = 0.0;
  for (std::size_t p = 0; p < B.size(); ++p) {
    const std::size_t q = B.id[p];
    moved += q != p;
    dx = std::max(dx, (B.x[p] - A.x[q]).norm());
    dv = std::max(dv, (B.v[p] - A.v[q]).norm());
    ds = std::max(ds, (B.state[p].stress - A.state[q].stress).norm());
    stress = std::max(stress, A.state[q].stress.norm());
    p_body += 0.5 * A.mass[q] * A.v[q].norm();  // about one block's momentum
  }
  BOOST_TEST(moved > B.size() * 9 / 10);
  // Round-off of 12 steps: positions of about 1e-2 m to 1e-15 m, velocities of 10 m/s to 1e-11
  // m/s, stresses to 1e-12 of the largest (each about 1e-13 of its scale, against a step's
  // change of about 1e-4 of it).
  BOOST_TEST(dx < 1e-15);
  BOOST_TEST(dv < 1e-11);
  BOOST_TEST(ds < 1e-12 * stress);
  // ... and not to the bit (else the shuffle would measure nothing).
  BOOST_TEST(dx + dv + ds > 0.0);
  const LedgerRow &a = seeded.row, &b = shuffled.row;
  const double e0 = a.total_energy;
  BOOST_TEST(std::abs(b.kinetic_energy - a.kinetic_energy) < 1e-12 * e0);
  BOOST_TEST(std::abs(b.strain_energy - a.strain_energy) < 1e-12 * e0);
  BOOST_TEST(std::abs(b.energy_error - a.energy_error) < 1e-12);
  BOOST_TEST_REQUIRE(a.sinks.size() == b.sinks.size());
  for (std::size_t k = 0; k < a.sinks.size(); ++k)
    BOOST_TEST(std::abs(b.sinks[k] - a.sinks[k]) < 1e-12 * e0);
  // The blocks meet head-on: the total momentum is round-off, measured against one block's.
  BOOST_TEST((b.momentum - a.momentum).norm() < 1e-13 * p_body);
}

// Every particle's state is the same bits on any thread count (docs/mpm.md, threads); the
// ledger's sums are per-thread partials, equal to round-off.
BOOST_AUTO_TEST_CASE(a_shuffled_run_is_the_same_bits_on_one_and_two_threads) {
  const Run one = run(5, 1), two = run(5, 2);
  BOOST_TEST(one.particles.id == two.particles.id);
  bool same = true;
  for (std::size_t p = 0; p < one.particles.size(); ++p)
    same = same && one.particles.x[p] == two.particles.x[p] &&
           one.particles.v[p] == two.particles.v[p] &&
           one.particles.state[p].stress == two.particles.state[p].stress;
  BOOST_TEST(same);
  BOOST_TEST(std::abs(one.row.energy_error - two.row.energy_error) < 1e-12);
}

// The crater measure (mpm/output/crater.hpp) keeps its face layer's initial positions by seed
// index: a bowl pressed into one block's x = 4 mm face, the same displacement u(y, z) given to each
// particle (by its seed index) of a seeded and a shuffled store, measures the same crater. (The
// layer once kept its positions in storage order and matched them to the particles of the sorted
// seed indices, right only in seed order.)
BOOST_AUTO_TEST_CASE(the_crater_of_a_shuffled_store_is_the_seeded_one) {
  Scene scene = test::verification_scene("contact_blocks.json");
  const CraterSpec spec{0, 0.004, std::nullopt};
  const auto bowl = [](Particles P) {
    for (std::size_t p = 0; p < P.size(); ++p) {
      const double r2 = std::pow(P.x[p](1) - 0.006, 2) + std::pow(P.x[p](2) - 0.004, 2);
      P.x[p](0) += 1e-3 * std::exp(-r2 / 4e-6);
    }
    return P;
  };
  const auto crater_of = [&](std::uint64_t shuffle) {
    scene.solver.shuffle_particles = shuffle;
    const Simulation sim(scene, 1);
    const CraterMeasure measure(scene, spec, sim.particles(), Communicator::one_rank());
    return measure.measure(bowl(sim.particles()));
  };
  const Crater seeded = crater_of(0), shuffled = crater_of(5);
  BOOST_TEST(seeded.depth > 0.5e-3);
  BOOST_TEST(shuffled.depth == seeded.depth, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(shuffled.floor_displacement == seeded.floor_displacement,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(shuffled.axis_y == seeded.axis_y, boost::test_tools::tolerance(1e-12));
  BOOST_TEST_REQUIRE(seeded.half_depth_diameter.has_value());
  BOOST_TEST_REQUIRE(shuffled.half_depth_diameter.has_value());
  BOOST_TEST(*shuffled.half_depth_diameter == *seeded.half_depth_diameter,
             boost::test_tools::tolerance(1e-12));
}

// A failure names the same particle whatever the storage order: two particles' stress updates
// fail in the same step (an injected negative Jacobian), and the run stops naming the lower seed
// index, in seed order and shuffled, where the higher one is stored first (on 1 and 2 threads);
// and so does the start-of-step check of two velocities made NaN.
BOOST_AUTO_TEST_CASE(a_failure_names_the_lowest_seed_index_in_any_order) {
  const Json one = {{"particles_per_cell", {1, 1, 1}}};
  const Json blocks = {{"objects", {{"left", one}, {"right", one}}}};
  Json patch = blocks;
  patch["solver"] = {{"shuffle_particles", 5}};
  const Scene seeded = test::verification_scene("contact_blocks.json", blocks);
  const Scene shuffled = test::verification_scene("contact_blocks.json", patch);
  // Where each seed index is stored in the shuffled store: b > a stored before a.
  const std::vector<std::size_t> order =
      shuffled_order(Simulation(seeded, 1).particles().size(), 5);
  std::vector<std::size_t> where(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) where[order[i]] = i;
  const std::size_t a = 100;
  std::size_t b = a + 1;
  while (where[b] > where[a]) ++b;
  const auto named = [&](const Scene& scene, int threads, FaultInjection::Kind kind) {
    Simulation sim(scene, threads);
    sim.inject({kind, 2, b});
    sim.inject({kind, 2, a});
    try {
      for (int s = 0; s < 3; ++s) sim.step();
    } catch (const SolverFailure& e) {
      return std::string(e.what());
    }
    return std::string("no failure");
  };
  const std::string expected = "particle " + std::to_string(a) + " (";
  for (const auto kind : {FaultInjection::Kind::jacobian, FaultInjection::Kind::nan_velocity})
    for (const int threads : {1, 2})
      for (const Scene* scene : {&seeded, &shuffled}) {
        const std::string message = named(*scene, threads, kind);
        BOOST_TEST_INFO("threads " << threads << (scene == &seeded ? ", seeded: " : ", shuffled: ")
                                   << message);
        BOOST_TEST(message.find(expected) != std::string::npos);
      }
}

// The body force's strongest particle, which the body-force messages name: under a uniform body
// force (the soft stack's -1000 t / 0.02 m/s^2 on every block) every particle ties, and the
// lowest seed index, 0, is named in seed order and shuffled, on 1 and 2 threads.
BOOST_AUTO_TEST_CASE(the_strongest_body_force_names_the_lowest_seed_index) {
  for (const std::uint64_t shuffle : {std::uint64_t(0), std::uint64_t(5)})
    for (const int threads : {1, 2}) {
      const Scene scene = test::verification_scene("stack_soft.json",
                                                   {{"solver", {{"shuffle_particles", shuffle}}}});
      const Simulation sim(scene, 1);
      BodyForces forces(scene, threads);
      forces.evaluate(sim.particles(), 0.01);
      BOOST_TEST_INFO("shuffle " << shuffle << ", threads " << threads);
      BOOST_TEST(seed_index(sim.particles(), forces.strongest()) == 0u);
    }
}

BOOST_AUTO_TEST_SUITE_END()
