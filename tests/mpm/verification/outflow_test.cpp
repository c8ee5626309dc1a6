// grid.outflow (item 8): a stress-free block flying out through a free face of the grid
// at 400 m/s. With "remove" each particle that crosses the edge leaves the simulation and its
// mass, momentum and kinetic energy go to the ledger's outflow columns, so at every step
//   momentum + outflow_momentum = p0 to 1e-12 |p0| (nothing else acts: free faces, no stress),
//   kinetic + strain + outflow_kinetic_energy = E0 to 1e-12 E0 (energy_error = 0: the block stays
//   rigid while it leaves layer by layer),
// and at the end all the block's mass is outflow and no particle in play is left. A removed
// particle keeps its mass and velocity through the step's MUSL re-map: emptied before it, it
// left the nodal masses of the step without its momentum, the nodes slowed down and strained the
// rest of the block (strain energy 20 J of E0 1742 J at the first removal, energy_error 0.033).
// With "stop" (the default) the first particle to leave stops the run with a message naming the
// particle and the setting that lets it go.
#include <boost/test/unit_test.hpp>
#include <numeric>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

Json patch_for(const char* outflow) {
  Json patch = Json::parse(R"({"objects": {"block": {"velocity": [400.0, 30.0, -20.0]}},
                              "time": {"max_time": 1.5e-4}})");
  patch["grid"]["outflow"] = outflow;
  return patch;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_outflow)

BOOST_AUTO_TEST_CASE(removed_particles_carry_their_mass_momentum_and_energy_into_the_ledger) {
  const Scene scene = test::verification_scene("rigid_translation.json", patch_for("remove"));
  Simulation sim(scene);
  const Particles& P = sim.particles();
  const double total_mass = std::accumulate(P.mass.begin(), P.mass.end(), 0.0);
  const Vec3 p0 = sim.ledger().initial_momentum();
  const double e0 = sim.ledger().initial_energy();
  double worst_momentum = 0.0, halfway_mass = 0.0, worst_error = 0.0;
  while (!sim.finished()) {
    sim.step();
    const LedgerRow r = sim.ledger().row();
    worst_momentum = std::max(worst_momentum, (r.momentum + r.outflow_momentum - p0).norm());
    worst_error = std::max(worst_error, std::abs(r.energy_error));
    if (r.outflow_mass > 0.0 && r.outflow_mass < total_mass) halfway_mass = r.outflow_mass;
  }
  const LedgerRow r = sim.ledger().row();
  BOOST_TEST_MESSAGE("outflow: " << sim.removed_particles() << " of " << P.size()
                                 << " particles removed, momentum " << worst_momentum / p0.norm()
                                 << ", energy_error " << worst_error);
  BOOST_TEST(halfway_mass > 0.0);  // the block left layer by layer while the rest ran on
  BOOST_TEST(sim.removed_particles() == static_cast<long>(P.size()));
  BOOST_TEST(r.outflow_mass == total_mass, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(r.kinetic_energy == 0.0);
  BOOST_TEST(worst_momentum <= 1e-12 * p0.norm());
  BOOST_TEST(worst_error <= 1e-12);
  BOOST_TEST(r.outflow_kinetic_energy == e0, boost::test_tools::tolerance(1e-12));
}

// Once every particle has left, nothing is left to integrate: the run goes to max_time in one
// step, gravity or not. With gravity the body-force step (mpm/step/time_step.cpp) kept it
// stepping: 1e6 m/s^2 on the 5 mm cells limits the step to 5e-5 s, some 200 empty steps to 1e-2 s.
BOOST_AUTO_TEST_CASE(an_empty_grid_finishes_in_one_step_under_gravity) {
  Json patch = patch_for("remove");
  patch["time"]["max_time"] = 1e-2;
  patch["solver"]["gravity"] = {1e6, 0.0, 0.0};
  Simulation sim(test::verification_scene("rigid_translation.json", patch));
  const long n = static_cast<long>(sim.particles().size());
  long steps_when_empty = -1;
  while (!sim.finished()) {
    sim.step();
    if (steps_when_empty < 0 && sim.removed_particles() == n) steps_when_empty = sim.steps();
  }
  BOOST_TEST_REQUIRE(steps_when_empty > 0);
  BOOST_TEST(sim.steps() - steps_when_empty <= 1);
  BOOST_TEST(sim.time() == 1e-2, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(by_default_a_particle_leaving_the_grid_stops_the_run_and_is_named) {
  const Scene scene = test::verification_scene("rigid_translation.json", patch_for("stop"));
  BOOST_TEST((scene.grid.outflow == Outflow::stop));
  BOOST_TEST((test::verification_scene("rigid_translation.json").grid.outflow == Outflow::stop));
  Simulation sim(scene);
  BOOST_CHECK_EXCEPTION(while (!sim.finished()) sim.step(), SolverFailure,
                        [](const SolverFailure& e) {
                          const std::string m = e.what();
                          return m.find("particle") != std::string::npos &&
                                 m.find("left the grid") != std::string::npos &&
                                 m.find("grid.outflow = \"remove\"") != std::string::npos;
                        });
}

BOOST_AUTO_TEST_SUITE_END()
