// Two identical elastic spheres meeting head-on at +-10 m/s in a single velocity field (no
// contact algorithm: the grid couples them), on a free grid. Asserted: the total momentum stays
// zero to 1e-12 of one sphere's momentum at every step (P2G/G2P conserve momentum exactly and the
// internal forces sum to zero). Reported: each sphere's velocity after the collision (rebound)
// and the energy lost (a single velocity field sticks the spheres: the collision is inelastic).
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

void collide(const char* interpolation, const char* scheme) {
  const Scene scene =
      test::verification_scene("two_spheres.json", test::with_solver(interpolation, scheme));
  Simulation sim(scene);
  const Particles& P = sim.particles();
  double m_left = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) m_left += P.object[p] == 0 ? P.mass[p] : 0.0;
  const double p_one = m_left * 10.0;
  double worst = sim.ledger().initial_momentum().norm() / p_one;
  while (!sim.finished()) {
    sim.step();
    worst = std::max(worst, sim.ledger().row().momentum.norm() / p_one);
  }
  Vec3 p_left = Vec3::Zero();
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.object[p] == 0) p_left += P.mass[p] * P.v[p];
  }
  const LedgerRow row = sim.ledger().row();
  BOOST_TEST_MESSAGE(interpolation
                     << "/" << scheme << ": " << sim.steps() << " steps, " << P.size()
                     << " particles; max |p|/p_sphere " << worst << "; left sphere velocity after "
                     << sim.time() * 1e6 << " us: " << p_left(0) / m_left << " m/s (was 10); KE "
                     << row.kinetic_energy << " J, strain energy " << row.strain_energy
                     << " J, energy lost " << -row.energy_error * 100 << " % of "
                     << sim.ledger().initial_energy() << " J");
  BOOST_TEST(worst < 1e-12);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_two_spheres)

BOOST_AUTO_TEST_CASE(gimp_musl_total_momentum_stays_zero_every_step) {
  collide("gimp", "musl");
}
BOOST_AUTO_TEST_CASE(linear_usl_total_momentum_stays_zero_every_step) {
  collide("linear", "usl");
}

BOOST_AUTO_TEST_SUITE_END()
