// Contact between velocity fields on a 2D grid (docs/scenes.md#2d-grids), every contact type and
// both normals. A 2D grid stores one node plane along z, so the contact normal has no z
// component: the mass does not vary along z.
// 1. The report's sphere-cylinder case01 in axisymmetry (sphere centred on the axis at 1470 m/s,
//    the 3D twin's cells: 50 x 10 over the half-section, 2 x 2 particles per cell, friction
//    mu 1e-4, artificial viscosity, AllowNoTension with melting, create_new_particles) to 5 us at
//    multiplier 0.2 (84 steps), with each contact: single_velocity; friction (mu 1e-4 as shipped,
//    and mu 0.3 with the normal larger_volume); approach (mu 0 with mass_gradients, mu 0.3 with
//    larger_volume; friction mu 0.3 with logistic_regression). Asserted at every step: every
//    particle stays in the plane z = 0 with zero hoop velocity v_z, bit for bit; the axial momentum
//    closes, |p_x - p0_x - J_x| < 1e-9 |p0| (the 3D twin's closure, sphere_cylinder_short_test.cpp;
//    measured 1.3e-15); every sink column non-decreasing, and at the end the artificial viscosity's
//    work and the eroded energy are booked (> 0). At the end |energy_error| < 0.04 (the 3D case01's
//    tolerance; measured -0.0019 to -0.0055). With two fields, particles fail (55-59) and every
//    failed one is converted (create_new_particles). Before the normal was 2D, mass_gradient read
//    the nodes k +- 1, which a 2D grid does not store: their indices are the neighbours along y, so
//    the normal tilted out of the plane and the corrections gave particles hoop velocities up
//    to 4.2 m/s and moved them off z = 0 at every step of every multi-field run (at the grid's
//    first and last stored node the index left the array).
// 2. The oblique elastic blocks of contact_blocks.json in plane strain (the 3D blocks' x-y
//    section, 20 x 12 cells) at 2 x 10 m/s along x and +-5 m/s along y, free faces, 8 us, with
//    friction (mu 0.3, with mass_gradients and with logistic_regression) and approach (mu 0,
//    larger_volume): the momentum in the plane is conserved
//    to 1e-12 of one block's |p0| at every step (contact_blocks_test.cpp's bound), p_z is zero
//    exactly, every particle stays at z = 0 with v_z = 0, and the blocks rebound (the relative
//    normal velocity ends below -10 m/s, as in 3D).
#include <boost/test/unit_test.hpp>

#include <algorithm>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// case01.json on an axisymmetric grid (test::axisymmetric_case01_patch), no output.
Json axisymmetric_case01(double max_time) {
  Json patch = test::axisymmetric_case01_patch();
  patch["time"] = {{"max_time", max_time}, {"multiplier", 0.2}};
  patch["output"] = {{"snapshots", false}, {"gauges", nullptr}, {"crater", nullptr}};
  return patch;
}

// Whether every particle lies in the plane z = 0 and moves in it.
bool in_plane(const Particles& P) {
  for (std::size_t p = 0; p < P.size(); ++p)
    if (P.x[p](2) != 0.0 || P.v[p](2) != 0.0) return false;
  return true;
}

double largest_out_of_plane_speed(const Particles& P) {
  double v = 0.0;
  for (const Vec3& u : P.v) v = std::max(v, std::abs(u(2)));
  return v;
}

void axisymmetric_contact(const Json& contact) {
  Json patch = axisymmetric_case01(5.0e-6);
  patch["physics"] = {{"contact", contact}};
  const Scene scene = test::shipped_scene("sphere_cylinder/case01.json", patch);
  BOOST_REQUIRE(scene.grid.geometry == GridGeometry::axisymmetric);
  Simulation sim(scene);
  const double p0 = std::abs(sim.ledger().initial_momentum()(0));
  std::vector<double> previous = sim.ledger().row().sinks;
  double worst_closure = 0.0, worst_sink_decrease = 0.0, worst_vz = 0.0;
  long steps_off_plane = 0;
  while (!sim.finished()) {
    sim.step();
    const LedgerRow row = sim.ledger().row();
    worst_closure = std::max(
        worst_closure,
        std::abs(row.momentum(0) - sim.ledger().initial_momentum()(0) - row.boundary_impulse(0)) /
            p0);
    for (std::size_t i = 0; i < row.sinks.size(); ++i) {
      worst_sink_decrease = std::max(worst_sink_decrease, previous[i] - row.sinks[i]);
      previous[i] = row.sinks[i];
    }
    steps_off_plane += in_plane(sim.particles()) ? 0 : 1;
    worst_vz = std::max(worst_vz, largest_out_of_plane_speed(sim.particles()));
  }
  const LedgerRow row = sim.ledger().row();
  BOOST_TEST_MESSAGE("case01 axisymmetric, contact "
                     << contact.dump() << ": " << sim.particles().size() << " particles, "
                     << sim.steps() << " steps, " << sim.grid().fields() << " fields; energy_error "
                     << row.energy_error << ", max |p_x - p0_x - J_x|/|p0| " << worst_closure
                     << "; failed " << sim.failed_particles() << ", converted "
                     << sim.converted_particles() << "; steps off the plane " << steps_off_plane
                     << ", largest |v_z| " << worst_vz << " m/s");
  BOOST_TEST(steps_off_plane == 0);
  BOOST_TEST(worst_closure < 1e-9);
  BOOST_TEST(worst_sink_decrease == 0.0);
  // The artificial viscosity and the erosion act, and their energies are booked.
  const auto& names = sim.ledger().sink_names();
  for (const char* sink : {"viscous_work", "eroded_energy"}) {
    const auto it = std::find(names.begin(), names.end(), sink);
    BOOST_REQUIRE(it != names.end());
    const double booked = row.sinks[std::size_t(it - names.begin())];
    BOOST_TEST_MESSAGE("  " << sink << " " << booked << " J of E0 " << sim.ledger().initial_energy()
                            << " J");
    BOOST_TEST(booked > 0.0, sink);
  }
  BOOST_TEST(std::abs(row.energy_error) < 0.04);
  if (sim.grid().fields() > 1) {
    BOOST_TEST(sim.failed_particles() > 0);
    BOOST_TEST(sim.converted_particles() == sim.failed_particles());
  }
}

void plane_strain_blocks(const Json& contact) {
  const Json patch = {
      {"grid",
       {{"geometry", "plane_strain"},
        {"lower", {0.0, 0.0}},
        {"upper", {0.02, 0.012}},
        {"cells", {20, 12}},
        {"boundary", {{"z-", nullptr}, {"z+", nullptr}}}}},
      {"objects",
       {{"left",
         {{"geometry", {{"lower", {0.004, 0.002, -0.002}}, {"upper", {0.010, 0.010, 0.002}}}},
          {"particles_per_cell", {2, 2}}}},
        {"right",
         {{"geometry", {{"lower", {0.010, 0.002, -0.002}}, {"upper", {0.016, 0.010, 0.002}}}},
          {"particles_per_cell", {2, 2}}}}}},
      {"physics", {{"contact", contact}}}};
  const Scene scene = test::verification_scene("contact_blocks.json", patch);
  BOOST_REQUIRE(scene.grid.geometry == GridGeometry::plane_strain);
  Simulation sim(scene);
  const Particles& P = sim.particles();
  double m_left = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) m_left += P.object[p] == 0 ? P.mass[p] : 0.0;
  const double p_block = m_left * std::sqrt(10.0 * 10.0 + 5.0 * 5.0);
  const Vec3 p0 = sim.ledger().initial_momentum();
  double worst = 0.0;
  long steps_off_plane = 0;
  while (!sim.finished()) {
    sim.step();
    const LedgerRow row = sim.ledger().row();
    worst = std::max(worst, (row.momentum - p0 - row.boundary_impulse).norm() / p_block);
    steps_off_plane += in_plane(P) && row.momentum(2) == 0.0 ? 0 : 1;
  }
  Vec3 v_left = Vec3::Zero(), v_right = Vec3::Zero();
  double m_right = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    (P.object[p] == 0 ? v_left : v_right) += P.mass[p] * P.v[p];
    m_right += P.object[p] == 0 ? 0.0 : P.mass[p];
  }
  const double approach = v_left(0) / m_left - v_right(0) / m_right;
  BOOST_TEST_MESSAGE("contact_blocks plane strain, contact "
                     << contact.dump() << ": " << P.size() << " particles, " << sim.steps()
                     << " steps; max |p - p0|/p_block " << worst << ", relative normal velocity "
                     << approach << " m/s (was +20), energy_error "
                     << sim.ledger().row().energy_error << "; steps off the plane "
                     << steps_off_plane);
  BOOST_TEST(worst < 1e-12);
  BOOST_TEST(steps_off_plane == 0);
  BOOST_TEST(approach < -10.0);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_planar_contact)

BOOST_AUTO_TEST_CASE(axisymmetric_single_velocity) {
  axisymmetric_contact({{"type", "single_velocity"}, {"mu", nullptr}});
}

BOOST_AUTO_TEST_CASE(axisymmetric_friction_mass_gradients) {
  axisymmetric_contact({{"type", "friction"}, {"mu", 1.0e-4}});
}

BOOST_AUTO_TEST_CASE(axisymmetric_friction_larger_volume) {
  axisymmetric_contact({{"type", "friction"}, {"mu", 0.3}, {"normal", "larger_volume"}});
}

BOOST_AUTO_TEST_CASE(axisymmetric_approach_mass_gradients) {
  axisymmetric_contact({{"type", "approach"}, {"mu", 0.0}});
}

BOOST_AUTO_TEST_CASE(axisymmetric_approach_larger_volume) {
  axisymmetric_contact({{"type", "approach"}, {"mu", 0.3}, {"normal", "larger_volume"}});
}

BOOST_AUTO_TEST_CASE(plane_strain_friction) {
  plane_strain_blocks({{"type", "friction"}, {"mu", 0.3}});
}

BOOST_AUTO_TEST_CASE(plane_strain_approach_larger_volume) {
  plane_strain_blocks({{"type", "approach"}, {"mu", 0.0}, {"normal", "larger_volume"}});
}

BOOST_AUTO_TEST_CASE(axisymmetric_friction_logistic_regression) {
  axisymmetric_contact({{"type", "friction"}, {"mu", 0.3}, {"normal", "logistic_regression"}});
}

BOOST_AUTO_TEST_CASE(plane_strain_friction_logistic_regression) {
  plane_strain_blocks({{"type", "friction"}, {"mu", 0.3}, {"normal", "logistic_regression"}});
}

BOOST_AUTO_TEST_SUITE_END()
