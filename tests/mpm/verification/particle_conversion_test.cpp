// create_new_particles: a particle that fails moves to its material's companion velocity field
// (mpm/step/stress_update.cpp) keeping mass, velocity, stress and history. Scene: the two blocks
// of contact_blocks.json with friction contact (mu 0.1), artificial viscosity,
// create_new_particles, erosion KeepStress and do_melting (every optional path of the step: the
// test is labelled `unit` so that the ASan + UBSan run covers contact, viscosity and conversion),
// the right block seeded at 1000 K (above the 925 K melting temperature), so every right-block
// particle fails by melting on the first step and no left-block particle ever fails (elastic, 294
// K). One thread, so that the ledger's sums and the ones here add the same terms in the same order.
// Asserted:
//   - converted_particles() = failed_particles() = the right block's particle count after step 1,
//     and every right-block particle is in Scene::companion_field(right material), every left
//     one in its parent field, at every later step;
//   - conversion changes only the field index: after the first step (the one that converts) every
//     particle's position, velocity, mass, volume, stress, plastic strain, temperature and failure
//     flag equal, bit for bit, those of the same run without create_new_particles; the ledger's
//     kinetic energy and momentum (summed in grid-to-particles BEFORE the stress update that
//     converts) equal the sums over the particles AFTER Simulation::step() returns, every step,
//     to n eps relative (n particles: the worst round-off of a sum of n terms, here 3.4e-13; the
//     ledger sums in chunks of 512 particles, the check in storage order; a particle's share lost
//     in the conversion would be about 1 / n = 3e-4);
//   - total particle mass unchanged (exactly) and the mass now in the companion field equals the
//     right block's mass;
//   - total momentum |p - p0 - J_b| <= 1e-12 p_block every step (free faces: J_b = 0), with the
//     companion field taking part in the contact.
//   - the sinks (viscous_work, friction_heat) never decrease, and |energy_error| < 5 % of E0 at
//     the end (the converted block's field meets the left block's through the contact
//     projection, which takes kinetic energy:
//     docs/mpm.md#velocity-fields-and-contact-physicscontact-contact).
#include <boost/test/unit_test.hpp>

#include <limits>
#include <sstream>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

BOOST_AUTO_TEST_SUITE(mpm_particle_conversion)

namespace {

const Json kPatch = Json::parse(R"({
      "physics": {"contact": {"type": "friction", "mu": 0.1}, "create_new_particles": true,
                  "erosion": "KeepStress", "do_melting": true,
                  "artificial_viscosity": {"enabled": true}},
      "objects": {"right": {"temperature": 1000.0}},
      "time": {"max_time": 1.0e-6}})");

}  // namespace

BOOST_AUTO_TEST_CASE(the_converting_step_changes_only_the_field_index) {
  Json off = kPatch;
  off["physics"]["create_new_particles"] = false;
  Simulation with(test::verification_scene("contact_blocks.json", kPatch), 1);
  Simulation without(test::verification_scene("contact_blocks.json", off), 1);
  with.step();
  without.step();
  const Particles& A = with.particles();
  const Particles& B = without.particles();
  BOOST_REQUIRE(with.converted_particles() > 0);
  BOOST_REQUIRE(A.size() == B.size());
  long moved = 0;
  bool same = true;
  for (std::size_t p = 0; p < A.size(); ++p) {
    moved += A.field[p] != B.field[p];
    same = same && A.x[p] == B.x[p] && A.v[p] == B.v[p] && A.mass[p] == B.mass[p] &&
           A.volume[p] == B.volume[p] && A.state[p].stress == B.state[p].stress &&
           A.state[p].plastic_strain == B.state[p].plastic_strain &&
           A.state[p].temperature == B.state[p].temperature &&
           A.state[p].failed == B.state[p].failed;
  }
  BOOST_TEST(moved == with.converted_particles());
  BOOST_TEST(same);
}

BOOST_AUTO_TEST_CASE(melted_particles_move_to_the_companion_field_conserving_mass_momentum_energy) {
  const Scene scene = test::verification_scene("contact_blocks.json", kPatch);
  BOOST_REQUIRE(scene.field_count() == 4);
  Simulation sim(scene, /*threads=*/1);
  const Particles& P = sim.particles();
  const int right_material = scene.objects[1].material;
  const int companion = scene.companion_field(right_material);
  BOOST_REQUIRE(companion != scene.parent_field(right_material));
  double mass0 = 0.0, right_mass = 0.0, p_block = 0.0;
  long right_count = 0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    mass0 += P.mass[p];
    if (P.object[p] == 1) {
      right_mass += P.mass[p];
      ++right_count;
    }
  }
  p_block = right_mass * scene.objects[1].velocity.norm();
  const Vec3 p0 = sim.ledger().initial_momentum();
  double worst_ke = 0.0, worst_p = 0.0, worst_closure = 0.0, worst_sink_decrease = 0.0;
  std::vector<double> previous = sim.ledger().row().sinks;
  while (!sim.finished()) {
    sim.step();
    for (std::size_t i = 0; i < previous.size(); ++i) {
      worst_sink_decrease =
          std::max(worst_sink_decrease, previous[i] - sim.ledger().row().sinks[i]);
      previous[i] = sim.ledger().row().sinks[i];
    }
    double ke = 0.0, mass = 0.0, companion_mass = 0.0;
    Vec3 momentum = Vec3::Zero();
    bool fields_ok = true;
    for (std::size_t p = 0; p < P.size(); ++p) {
      const double m = P.mass[p];
      ke += 0.5 * m * P.v[p].squaredNorm();  // the ledger's expression (grid_to_particles.cpp)
      momentum += m * P.v[p];
      mass += m;
      if (P.field[p] == companion) companion_mass += m;
      const int expected = P.object[p] == 1 ? companion : scene.parent_field(P.material[p]);
      fields_ok = fields_ok && P.field[p] == expected;
    }
    const LedgerRow row = sim.ledger().row();
    worst_ke = std::max(worst_ke, std::abs(ke - row.kinetic_energy) / row.kinetic_energy);
    worst_p = std::max(worst_p, (momentum - row.momentum).norm() / p_block);
    worst_closure =
        std::max(worst_closure, (row.momentum - p0 - row.boundary_impulse).norm() / p_block);
    BOOST_TEST(fields_ok);
    BOOST_TEST(mass == mass0);
    BOOST_TEST(companion_mass == right_mass);
    BOOST_TEST(sim.converted_particles() == right_count);
    BOOST_TEST(sim.failed_particles() == right_count);
  }
  const LedgerRow row = sim.ledger().row();
  std::ostringstream sinks;
  for (std::size_t i = 0; i < row.sinks.size(); ++i)
    sinks << ", " << sim.ledger().sink_names()[i] << " " << row.sinks[i] << " J";
  BOOST_TEST_MESSAGE("conversion: " << P.size() << " particles, " << sim.steps() << " steps, "
                                    << sim.converted_particles() << " converted ("
                                    << sim.failed_particles() << " failed); max |KE_ledger - "
                                    << "KE_after|/KE " << worst_ke << ", max |p_ledger - "
                                    << "p_after|/p_block " << worst_p
                                    << ", max |p - p0 - J_b|/p_block " << worst_closure
                                    << "; energy_error " << row.energy_error << sinks.str());
  BOOST_TEST(sim.converted_particles() > 0);
  // Round-off of a sum of n terms, whatever its order (the ledger's chunks against this loop).
  const double sum_round_off = double(P.size()) * std::numeric_limits<double>::epsilon() / 2.0;
  BOOST_TEST(worst_ke <= sum_round_off);
  BOOST_TEST(worst_p <= sum_round_off);
  BOOST_TEST(worst_closure <= 1e-12);
  BOOST_TEST(worst_sink_decrease == 0.0);
  BOOST_TEST(std::abs(row.energy_error) < 0.05);
}

BOOST_AUTO_TEST_SUITE_END()
