// A body at rest on a rigid `wall` stays at rest and its books stay closed (issue 53): the elastic
// block of data/scenes/verification/sliding_block.json (2 x 4 x 2 mm, 6061-T6 made elastic,
// h = 0.5 mm, uGIMP + MUSL) released at rest, stress-free, on the frictionless x- wall under
// g = 1e5 m/s^2, for 1e4 steps (0.41 ms, about 260 periods 4 L / c_0 of its first mode along x,
// c_0 = sqrt(E / rho) the bar speed).
//
// Closed form: released stress-free, the block settles under its own weight and rings about the
// settled state. A linear body released from rest under a constant load reaches its largest
// kinetic energy at the settled state, where it equals the strain energy stored there: for a bar
// of length L, section A, Young's modulus E under its own weight M g (uniaxial stress, the sides
// free), U_s = (M g)^2 L / (6 E A) = 1.13e-8 J, and gravity has then done 2 U_s of work. The
// wall's catch of the face nodes is inelastic (grid/wall.cpp), so the ringing decays and at most
// its energy U_s leaves the books as the wall's residual; none may be created. Asserted: the run
// is not stopped; the kinetic energy stays below 1.5 U_s at every step and ends below 0.5 U_s;
// the books' residual in joules (Ledger::energy_excess, energy_error times the energy that has
// entered) stays within [-1.2 U_s, +0.25 U_s] (it rings: +0.16 U_s at most); the block's centre
// of mass sinks by less than 3 times the settled compression M g L / (2 E A) = 7.8e-9 m and never
// lifts off; no particle crosses the wall's plane. Measured: kinetic energy at most 1.04e-8 J (0.92
// U_s), residual -1.05e-8 J at most
// (-0.93 U_s: the ringing dissipated; -1.10e-8 J at 1.6 ms, unchanged from 1 ms), centre sank
// 9.6e-9 m at most. On main before issue 53 the same block started to rock and the energy check
// stopped it at 204 us (particle speed 0.26 m/s): the wall's hold, decided each step by the sign
// of the ringing face layer's velocity, was decided again on the MUSL re-map, and gravity's work
// was booked before the wall held its nodes.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <optional>
#include <string>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct State {
  double kinetic = 0.0;
  double centre_x = 0.0;
  double lowest = 1e30;
};

State state(const Particles& P) {
  State s;
  double m = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    s.kinetic += 0.5 * P.mass[i] * P.v[i].squaredNorm();
    s.centre_x += P.mass[i] * P.x[i](0);
    m += P.mass[i];
    s.lowest = std::min(s.lowest, P.x[i](0));
  }
  s.centre_x /= m;
  return s;
}

double total_mass(const Particles& P) {
  double M = 0.0;
  for (const double m : P.mass) M += m;
  return M;
}

// U_s = (M g)^2 L / (6 E A): the strain energy of the block (L = 2 mm along the load, A = 4 x 2
// mm^2) settled under its own weight M g as a bar (the first test case's comment).
double settled_strain_energy(const Scene& scene, double M, double g) {
  const double L = 0.002, A = 0.004 * 0.002;
  return (M * g) * (M * g) * L / (6.0 * test::youngs_modulus(scene) * A);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(resting_contact)

BOOST_AUTO_TEST_CASE(a_block_at_rest_on_a_wall_stays_at_rest_with_closed_books) {
  const Json at_rest = {{"objects", {{"block", {{"velocity", {0.0, 0.0, 0.0}}}}}},
                        {"grid", {{"wall_friction", {{"x-", 0.0}}}}},
                        {"time", {{"max_time", 1.0}}}};
  const Scene scene = test::verification_scene("sliding_block.json", at_rest);
  Simulation sim(scene);
  const double E = test::youngs_modulus(scene);
  const double L = 0.002, A = 0.004 * 0.002, g = 1.0e5;
  const double M = total_mass(sim.particles());
  const double U_s = settled_strain_energy(scene, M, g);
  const double settle = M * g * L / (2.0 * E * A);
  const State first = state(sim.particles());
  double worst_kinetic = 0.0, lowest_error = 0.0, highest_error = 0.0, lowest = first.lowest;
  double sink = 0.0;
  for (int n = 0; n < 10000 && !sim.finished(); ++n) {
    try {
      sim.step();
    } catch (const std::exception& e) {
      BOOST_FAIL("stopped at step " << sim.steps() << ", " << sim.time() << " s: " << e.what());
    }
    const State s = state(sim.particles());
    worst_kinetic = std::max(worst_kinetic, s.kinetic);
    lowest_error = std::min(lowest_error, sim.ledger().energy_excess());
    highest_error = std::max(highest_error, sim.ledger().energy_excess());
    lowest = std::min(lowest, s.lowest);
    sink = std::max(sink, first.centre_x - s.centre_x);
  }
  const State last = state(sim.particles());
  BOOST_TEST_MESSAGE(sim.steps() << " steps to " << sim.time() << " s: kinetic energy at most "
                                 << worst_kinetic << " J (U_s = " << U_s << " J), at the end "
                                 << last.kinetic << " J; residual in [" << lowest_error << ", "
                                 << highest_error << "] J; centre sank at most " << sink
                                 << " m (settled: " << settle << " m), at the end "
                                 << first.centre_x - last.centre_x << " m");
  BOOST_TEST(sim.steps() == 10000);
  BOOST_TEST(worst_kinetic < 1.5 * U_s);
  BOOST_TEST(last.kinetic < 0.5 * U_s);
  BOOST_TEST(lowest_error > -1.2 * U_s);
  BOOST_TEST(highest_error < 0.25 * U_s);
  BOOST_TEST(sink < 3.0 * settle);
  BOOST_TEST(first.centre_x - last.centre_x > -settle);  // it never lifts off
  BOOST_TEST(lowest >= -1e-9);                           // no particle crosses the wall's plane
}

BOOST_AUTO_TEST_CASE(a_block_at_rest_on_a_rough_wall_is_not_stopped_when_it_rings_back_up) {
  // The block above on the x- wall with friction 0.5 and 10. Released stress-free, it rings:
  // gravity's work rises to about 3.7e-8 J and falls back to 0 each time the block returns to its
  // start height. Measured against the energy that had entered at that instant (6e-12 J), the
  // ringing's 1e-8 J of motion read as growth +1700 and the energy-growth check stopped the run
  // at 8 us as "unstable"; the check's reference is now the largest energy that has entered
  // (simulation/diagnosis.cpp). Asserted: 1e4 steps run, and the mechanical residual kinetic +
  // strain - gravity's work stays below +0.25 U_s (measured +0.14 U_s at most at mu 0.5 and 10,
  // ending at -0.86 U_s: the catch damps the ringing). Before the re-map took the step's v* where
  // the wall's friction acted (grid/wall.cpp), friction pumped the ringing: +1.1 U_s at mu 0.5,
  // +3.2 U_s at mu 10, and at mu 1 +4.5 U_s and a stop at 105 us.
  for (const double mu : {0.5, 10.0}) {
    const Json rough = {{"objects", {{"block", {{"velocity", {0.0, 0.0, 0.0}}}}}},
                        {"grid", {{"wall_friction", {{"x-", mu}}}}},
                        {"time", {{"max_time", 1.0}}}};
    const Scene scene = test::verification_scene("sliding_block.json", rough);
    Simulation sim(scene);
    const double U_s = settled_strain_energy(scene, total_mass(sim.particles()), 1.0e5);
    double highest = -1e30;
    for (int n = 0; n < 10000 && !sim.finished(); ++n) {
      try {
        sim.step();
      } catch (const std::exception& e) {
        BOOST_FAIL("mu " << mu << ": stopped at step " << sim.steps() << ", " << sim.time()
                         << " s: " << e.what());
      }
      highest = std::max(
          highest, sim.ledger().energy_excess() - test::ledger_sink(sim.ledger(), "friction_heat"));
    }
    BOOST_TEST_MESSAGE(
        "mu " << mu << ": " << sim.steps() << " steps; mechanical residual at most " << highest
              << " J, at the end "
              << sim.ledger().energy_excess() - test::ledger_sink(sim.ledger(), "friction_heat")
              << " J; friction heat " << test::ledger_sink(sim.ledger(), "friction_heat") << " J");
    BOOST_TEST(sim.steps() == 10000);
    BOOST_TEST(highest < 0.25 * U_s);
  }
}

BOOST_AUTO_TEST_CASE(a_block_at_rest_in_a_corner_stays_at_rest) {
  // The same block in the corner of two (x-, z-) and of three (x-, y-, z-) walls with friction
  // mu = 0.25 on each, gravity 1e5 m/s^2 along the bisector (trisector), released at rest: the
  // walls' normal forces alone hold it, so friction has nothing to do once the sudden load has
  // settled. Scale: the strain energy U_c = sum_i (M g_i)^2 L_i / (6 E A_i) of the settled block
  // loaded along each axis as the bar above. Asserted: the run is not stopped in 1e4 steps (3e4,
  // 1.23 ms, in the three-wall corner);
  // kinetic energy below 1.5 U_c; the mechanical residual kinetic + strain - gravity's work
  // (energy_error without the friction heat) within [-1.2 U_c, +0.25 U_c]; the friction heat
  // booked after the first 100 us grows by less than 0.02 U_c (measured: not at all; 1.1e-9 J and
  // 4.0e-9 J booked while the sudden load settles). With the heat booked as m s max(0, v0 . t) on
  // every slipping node the two-wall corner booked 1.1e-8 J by 250 us, the mechanical energy
  // losing none of it, and the energy check stopped the run (grid/wall.cpp). Before the re-map
  // took the step's v* where friction acted, the three-wall corner's free top edges slipped at
  // about 3 mm/s while the block rang and booked heat without end (2.2e-8 J by 1.4 ms); the
  // energy check, with the walls' heat in it, stopped the run at 1.01 ms.
  for (const bool three : {false, true}) {
    const double g = 1.0e5, c = g / std::sqrt(three ? 3.0 : 2.0);
    const Json corner = {
        {"objects",
         {{"block",
           {{"velocity", {0.0, 0.0, 0.0}},
            {"geometry",
             {{"lower", {0.0, three ? 0.0 : 0.002, 0.0}},
              {"upper", {0.002, three ? 0.004 : 0.006, 0.002}}}}}}}},
        {"grid",
         {{"boundary", {{"y-", three ? "wall" : "free"}, {"z-", "wall"}}},
          {"wall_friction",
           {{"x-", 0.25}, {"y-", three ? Json(0.25) : Json(nullptr)}, {"z-", 0.25}}}}},
        {"solver", {{"gravity", {-c, three ? -c : 0.0, -c}}}},
        {"time", {{"max_time", 1.0}}}};
    const Scene scene = test::verification_scene("sliding_block.json", corner);
    Simulation sim(scene);
    const double E = test::youngs_modulus(scene);
    const double Lx = 0.002, Ly = 0.004, Lz = 0.002;
    const double M = total_mass(sim.particles());
    const double U_c = (M * c) * (M * c) / (6.0 * E) *
                       (Lx / (Ly * Lz) + Lz / (Lx * Ly) + (three ? Ly / (Lx * Lz) : 0.0));
    double worst_kinetic = 0.0, lowest_error = 0.0, highest_error = 0.0, heat_settled = -1.0;
    const auto heat_now = [&] { return test::ledger_sink(sim.ledger(), "friction_heat"); };
    const int steps = three ? 30000 : 10000;
    for (int n = 0; n < steps && !sim.finished(); ++n) {
      try {
        sim.step();
      } catch (const std::exception& e) {
        BOOST_FAIL((three ? "three" : "two") << "-wall corner stopped at step " << sim.steps()
                                             << ", " << sim.time() << " s: " << e.what());
      }
      worst_kinetic = std::max(worst_kinetic, state(sim.particles()).kinetic);
      const double mechanical = sim.ledger().energy_excess() - heat_now();  // [J]
      lowest_error = std::min(lowest_error, mechanical);
      highest_error = std::max(highest_error, mechanical);
      if (heat_settled < 0.0 && sim.time() > 1.0e-4) heat_settled = heat_now();
    }
    const double heat = heat_now();
    BOOST_TEST_MESSAGE((three ? "three" : "two")
                       << "-wall corner, " << sim.steps() << " steps to " << sim.time()
                       << " s: kinetic energy at most " << worst_kinetic << " J (U_c = " << U_c
                       << " J); friction heat " << heat_settled << " J at 100 us, " << heat
                       << " J at the end; mechanical residual in [" << lowest_error << ", "
                       << highest_error << "] J");
    BOOST_TEST(sim.steps() == steps);
    BOOST_TEST(worst_kinetic < 1.5 * U_c);
    BOOST_TEST(heat - heat_settled < 0.02 * U_c);
    BOOST_TEST(lowest_error > -1.2 * U_c);
    BOOST_TEST(highest_error < 0.25 * U_c);
  }
}

BOOST_AUTO_TEST_CASE(a_soft_block_resting_on_a_wall_in_plane_strain_never_climbs) {
  // resting_block_plane_strain.json: a soft neo-Hookean block (0.1 x 0.1 m, E = 1e7 Pa, nu = 0.3,
  // rho0 = 1000 kg/m^3, h = 12.5 mm) released at rest on the frictionless y- wall under 1000
  // m/s^2: it settles to a strain of about 1 %, its face layer moving a twentieth of a cell.
  // Scale: U_s = (M g)^2 L / (6 E' W) per metre, E' = E / (1 - nu^2) (plane strain, the sides
  // free), the settled strain energy and the sudden load's largest kinetic energy. The ledger
  // books the neo-Hookean solid's stored energy sum V0 W(F) (stress_update.cpp), so the residual
  // is the energy the discrete body really gained or lost. Asserted over 6000 steps (0.32 s,
  // about 30 periods of the first mode): the run is not stopped; the kinetic energy stays below
  // 1.2 U_s; the residual in J/m (Ledger::energy_excess) below +0.2 U_s over the run, below +0.1
  // U_s over its second half, and above -1.2 U_s (the catch damps at most the ringing).
  // Measured: kinetic at most 0.98 U_s; residual in [-0.21, +0.11] U_s, +0.033 U_s at most over
  // the second half, -0.13 U_s at the end. When the ghost outside the wall moved inward at the
  // interior node's normal speed even while the face node was held, the image was rectified,
  // the ringing pushed the block off the wall on average, and it climbed: +0.51 U_s by 0.32 s
  // (with the strain energy booked by the stress power's quadrature, +0.33 U_s, and +1.2 U_s by
  // 1 s; beside a symmetric x- face the energy check stopped it at 3.2 s; grid/wall.cpp).
  const Scene scene = test::verification_scene("resting_block_plane_strain.json");
  Simulation sim(scene);
  const double E = test::youngs_modulus(scene), nu = test::poissons_ratio(scene);
  const double L = 0.1, W = 0.1, g = 1000.0;
  const double M = total_mass(sim.particles());  // kg per metre
  const double U_s = (M * g) * (M * g) * L / (6.0 * E / (1.0 - nu * nu) * W);
  double worst_kinetic = 0.0, lowest_error = 0.0, highest_error = 0.0, highest_late = -1e30;
  for (int n = 0; n < 6000 && !sim.finished(); ++n) {
    try {
      sim.step();
    } catch (const std::exception& e) {
      BOOST_FAIL("stopped at step " << sim.steps() << ", " << sim.time() << " s: " << e.what());
    }
    worst_kinetic = std::max(worst_kinetic, state(sim.particles()).kinetic);
    lowest_error = std::min(lowest_error, sim.ledger().energy_excess());
    highest_error = std::max(highest_error, sim.ledger().energy_excess());
    if (n >= 3000) highest_late = std::max(highest_late, sim.ledger().energy_excess());
  }
  BOOST_TEST_MESSAGE(sim.steps() << " steps to " << sim.time() << " s: kinetic energy at most "
                                 << worst_kinetic / U_s << " U_s (U_s = " << U_s
                                 << " J/m); residual in [" << lowest_error / U_s << ", "
                                 << highest_error / U_s << "] U_s, at most " << highest_late / U_s
                                 << " U_s over the second half, at the end "
                                 << sim.ledger().energy_excess() / U_s << " U_s");
  BOOST_TEST(sim.steps() == 6000);
  BOOST_TEST(worst_kinetic < 1.2 * U_s);
  BOOST_TEST(highest_error < 0.2 * U_s);
  BOOST_TEST(highest_late < 0.1 * U_s);
  BOOST_TEST(lowest_error > -1.2 * U_s);
}

BOOST_AUTO_TEST_CASE(a_stack_whose_middle_block_slid_moves_as_one_and_keeps_its_books) {
  // stack_friction.json: three elastic 6061 blocks (2 mm thick; 6, 4 and 2 mm wide along y)
  // stacked on the frictionless x- wall in plane strain, a body force of 1e5 m/s^2 along -x
  // ramped on over 20 us, mu 0.3 between the blocks (h = 0.25 mm). The middle block starts
  // sliding along y at v0 = 0.05 m/s. Closed form: friction between the blocks stops the slip
  // within a few us (mu g_n = 3e4 m/s^2), the wall takes no tangential force, so the stack then
  // moves as one at m_mid v0 / M with kinetic energy (m_mid v0)^2 / (2 M) = KE0 m_mid / M
  // (9.0e-6 J/m; the load's ringing adds about 3e-9 J/m), and momentum along y is conserved.
  // Friction dissipates at most the rest, KE0 (1 - m_mid / M) = 1.8e-5 J/m, and nothing after
  // the slip has stopped. Asserted over 0.12 ms (about 5900 steps): the run is not stopped;
  // momentum along y to 1e-9 of m_mid v0; the final kinetic energy within [0.95, 1.15] of the
  // closed form; the friction heat in [0.7, 1.0] of the dissipation and growing by less than
  // 1e-3 of itself after 40 us; abs(energy_error) below 5e-3. Measured: kinetic 1.03, heat 0.86
  // of the dissipation and +1.7e-4 of itself after 40 us, energy_error within +-3.2e-3. Before the
  // strain pass kept the step's stick (contact/contact.cpp), the re-map read slip at the stuck
  // interfaces and friction pumped the stack: heat +13 % after 40 us, kinetic 1.33, energy_error
  // +4.9 % at 0.12 ms and +39 % at 0.3 ms; unseeded, the resting stack rattled after 20 000
  // steps and the energy check stopped it at step 24 576.
  const double v0 = 0.05;
  const Json sliding = {{"objects", {{"mid", {{"velocity", {0.0, v0, 0.0}}}}}},
                        {"time", {{"max_time", 1.2e-4}}}};
  const Scene scene = test::verification_scene("stack_friction.json", sliding);
  Simulation sim(scene);
  const Particles& P = sim.particles();
  double M = 0.0, m_mid = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    M += P.mass[i];
    if (P.v[i](1) != 0.0) m_mid += P.mass[i];
  }
  const double KE0 = 0.5 * m_mid * v0 * v0;
  const double KE_stack = KE0 * m_mid / M, dissipated = KE0 - KE_stack;
  const auto heat = [&] {
    for (const auto& [name, value] : sim.ledger().checked_sinks())
      if (name == "friction_heat") return value;
    return 0.0;
  };
  double worst_error = 0.0, heat_at_40us = -1.0;
  while (!sim.finished()) {
    try {
      sim.step();
    } catch (const std::exception& e) {
      BOOST_FAIL("stopped at step " << sim.steps() << ", " << sim.time() << " s: " << e.what());
    }
    worst_error = std::max(worst_error, std::abs(sim.ledger().row().energy_error));
    if (heat_at_40us < 0.0 && sim.time() >= 4e-5) heat_at_40us = heat();
  }
  double p_y = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) p_y += P.mass[i] * P.v[i](1);
  const double kinetic = state(P).kinetic;
  BOOST_TEST_MESSAGE(sim.steps() << " steps to " << sim.time() << " s: kinetic " << kinetic
                                 << " J/m = " << kinetic / KE_stack << " of the stack's, heat "
                                 << heat() / dissipated << " of the dissipation, +"
                                 << heat() / heat_at_40us - 1.0 << " of itself after 40 us; "
                                 << "abs(energy_error) at most " << worst_error);
  BOOST_TEST(sim.time() >= 1.2e-4 * (1.0 - 1e-12));
  BOOST_TEST(std::abs(p_y - m_mid * v0) < 1e-9 * m_mid * v0);
  BOOST_TEST(kinetic > 0.95 * KE_stack);
  BOOST_TEST(kinetic < 1.15 * KE_stack);
  BOOST_TEST(heat() > 0.7 * dissipated);
  BOOST_TEST(heat() < dissipated);
  BOOST_TEST(heat() < (1.0 + 1e-3) * heat_at_40us);
  BOOST_TEST(worst_error < 5e-3);
}

// The walls met at the particles (grid.wall_contact "particles",
// contact/rigid_particle_contact.hpp): a penalty against each wall's plane with a stick spring per
// pushed particle, its layer damped at 0.3 of critical (grid.wall_penalty_damping). Where the walls
// at the nodes lose what enters.

BOOST_AUTO_TEST_CASE(a_block_under_a_tilted_load_sticks_to_a_wall_met_at_the_particles) {
  // The block at rest on the x- wall at mu 1 under gravity (-1e5, 5e4, 0) m/s^2 applied at once:
  // g_t / g_n = 0.5 < mu, so it sticks. The walls at the nodes hold it but lose half of the energy
  // that enters (energy_error -0.50 by 500 us, docs/verification.md); undamped at the particles
  // it rings off the wall and slides away (0.8 m/s by 500 us). Asserted over 300 us: the centre's
  // walk along y after the load settles (from 100 us) below 5 nm, a few times the stick springs'
  // settled stretch (layers g_t h^2 / (4 c_L^2) = 0.7 nm), and the books closed within 1e-3 of
  // the energy that entered. Measured: 0.9 nm, -3.7e-5.
  const Json tilted = {{"objects", {{"block", {{"velocity", {0.0, 0.0, 0.0}}}}}},
                       {"grid",
                        {{"wall_friction", {{"x-", 1.0}}},
                         {"wall_contact", "particles"},
                         {"wall_penalty_damping", 0.3}}},
                       {"solver", {{"gravity", {-1.0e5, 5.0e4, 0.0}}}},
                       {"time", {{"max_time", 3.0e-4}}}};
  const Scene scene = test::verification_scene("sliding_block.json", tilted);
  Simulation sim(scene, 1);  // a small grid: one thread runs it faster than two
  const int block = test::object_index(scene, "block");
  std::optional<double> settled;  // the centre's y at 100 us [m]
  double worst = 0.0;
  while (!sim.finished()) {
    sim.step();
    worst = std::max(worst, std::abs(sim.ledger().row().energy_error));
    if (!settled && sim.time() > 1.0e-4)
      settled = test::motion_of(sim.particles(), block).centre(1);
  }
  const double walk = test::motion_of(sim.particles(), block).centre(1) - settled.value();
  const LedgerRow r = sim.ledger().row();
  BOOST_TEST_MESSAGE("tilted load at once, mu 1, at the particles, damped: walked "
                     << walk << " m along y after 100 us; energy_error " << r.energy_error
                     << " (worst " << worst << "); friction heat "
                     << test::ledger_sink(sim.ledger(), "friction_heat") << " J, contact_damping "
                     << test::ledger_sink(sim.ledger(), "contact_damping") << " J");
  BOOST_TEST(std::abs(walk) < 5.0e-9);
  BOOST_TEST(std::abs(r.energy_error) < 1.0e-3);
}

BOOST_AUTO_TEST_CASE(a_block_in_a_three_wall_corner_met_at_the_particles_keeps_its_books) {
  // A 2 mm cube in the corner of the x-, y- and z- walls, mu 0.3 on each, pressed by a body force
  // of 1e5 m/s^2 along the trisector ramped over 20 us. The walls at the nodes lose 9.7 % of what
  // enters (a new user's trial; 8^3 cells: -0.0965 by 300 us). Asserted over 300 us: the books
  // closed within 1e-3 at the end, the kinetic energy after the ramp below U_c (the settled strain
  // energy's scale, as in the corner case above), and the centre within 2 um of its start (the
  // penalty's compliant layer). Measured: +1.9e-4; 0.06 U_c; 0.65 um.
  const double c = 1.0e5 / std::sqrt(3.0), ramp = 2.0e-5;
  const std::string b = "-" + std::to_string(c) + "*min(1,t/" + std::to_string(ramp) + ")";
  const Json corner = {
      {"objects",
       {{"block",
         {{"velocity", {0.0, 0.0, 0.0}},
          {"geometry", {{"lower", {0.0, 0.0, 0.0}}, {"upper", {0.002, 0.002, 0.002}}}},
          {"body_force", {b, b, b}}}}}},
      {"grid",
       {{"upper", {0.004, 0.004, 0.004}},
        {"cells", {8, 8, 8}},
        {"boundary", {{"y-", "wall"}, {"z-", "wall"}}},
        {"wall_friction", {{"x-", 0.3}, {"y-", 0.3}, {"z-", 0.3}}},
        {"wall_contact", "particles"},
        {"wall_penalty_damping", 0.3}}},
      {"solver", {{"gravity", {0.0, 0.0, 0.0}}}},
      {"time", {{"max_time", 3.0e-4}}}};
  const Scene scene = test::verification_scene("sliding_block.json", corner);
  Simulation sim(scene, 1);  // a small grid: one thread runs it faster than two
  const int block = test::object_index(scene, "block");
  const double L = 0.002, E = test::youngs_modulus(scene);
  const double M = total_mass(sim.particles());
  const double U_c = 3.0 * (M * c) * (M * c) * L / (6.0 * E * L * L);
  const Vec3 start = test::motion_of(sim.particles(), block).centre;
  double late_kinetic = 0.0, moved = 0.0;
  while (!sim.finished()) {
    sim.step();
    const test::BodyMotion m = test::motion_of(sim.particles(), block);
    moved = std::max(moved, (m.centre - start).norm());
    if (sim.time() > 2.0 * ramp) late_kinetic = std::max(late_kinetic, m.kinetic_energy);
  }
  const LedgerRow r = sim.ledger().row();
  BOOST_TEST_MESSAGE("three-wall corner at the particles, mu 0.3, ramped, damped: energy_error "
                     << r.energy_error << "; kinetic energy after the ramp at most " << late_kinetic
                     << " J (U_c " << U_c << " J); centre moved " << moved
                     << " m at most; friction heat "
                     << test::ledger_sink(sim.ledger(), "friction_heat") << " J, contact energy "
                     << test::ledger_sink(sim.ledger(), "contact_energy") << " J");
  BOOST_TEST(std::abs(r.energy_error) < 1.0e-3);
  BOOST_TEST(late_kinetic < U_c);
  BOOST_TEST(moved < 2.0e-6);
}

BOOST_AUTO_TEST_SUITE_END()
