// A rigid wall face with Coulomb friction (grid.boundary = "wall", grid/wall.cpp) against
// Coulomb's law for a block sliding on it (data/scenes/verification/sliding_block.json): gravity
// g = 1e5 m/s^2 presses an elastic block onto the x- wall while it slides along y at v0 = 5 m/s.
// The friction force is mu M g, so the mean velocity is v_y = v0 - mu g t until t_stop = v0 /
// (mu g) = 200 us, and zero after (stick: the static limit mu M g exceeds the zero tangential
// load). The heat is the kinetic energy lost, 1/2 M (v0^2 - v_y^2), booked in friction_heat.
// Tolerances: v_y within 0.02 v0 of the law at every step (the sudden load sets the block
// vibrating normal to the wall; the friction per step follows the normal impulse, whose average
// is M g), |v_y| < 0.02 v0 once stopped, friction heat within 3 % of the lost energy.
// A mirror plane with a per-step |impulse| bound measured 1.5-2 times the law's deceleration:
// the one-sided wall is what makes this test pass (docs/scenes.md#grid).
// The same law holds on an upper face (x+, sliding along z: 1.1e-3 v0 over 120 us). The energy
// books close within 0.1 % of E0.
// The same block on a frictionless wall keeps v0 to 1e-9 relative, and a block pulled away from
// the wall by gravity leaves it freely (the wall never pulls; a mirror plane would hold it), and
// a block crushed onto it by 1e11 m/s^2 keeps its particles on the face, not behind it.
// The wall met at the particles (grid.wall_contact "particles") follows the same law within the
// same tolerances, books the heat within 1 % of the loss and closes the books within 0.002
// (measured 0.015 v0, +0.05 %, 4.7e-4). Beside a face that moves it may be rough (refused at
// the nodes): the block pushed along it books mu M g per metre slid.
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Motion {
  Vec3 velocity;  ///< mass-weighted mean [m/s]
  Vec3 lower;     ///< lowest particle position per axis [m]
};

Motion motion(const Particles& P) {
  Vec3 p = Vec3::Zero();
  double m = 0.0;
  Vec3 lower = Vec3::Constant(1e30);
  for (std::size_t i = 0; i < P.size(); ++i) {
    p += P.mass[i] * P.v[i];
    m += P.mass[i];
    lower = lower.cwiseMin(P.x[i]);
  }
  return {p / m, lower};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(wall_friction)

BOOST_AUTO_TEST_CASE(a_sliding_block_follows_coulombs_law_and_then_sticks) {
  const Scene scene = test::verification_scene("sliding_block.json");
  Simulation sim(scene);
  const double v0 = 5.0, g = 1.0e5, mu = 0.25, t_stop = v0 / (mu * g);
  double mass = 0.0;
  for (const double m : sim.particles().mass) mass += m;
  double worst_sliding = 0.0, worst_stopped = 0.0;
  while (!sim.finished()) {
    sim.step();
    const double vy = motion(sim.particles()).velocity(1);
    const double law = std::max(v0 - mu * g * sim.time(), 0.0);
    if (sim.time() < t_stop) {
      worst_sliding = std::max(worst_sliding, std::abs(vy - law) / v0);
    } else {
      worst_stopped = std::max(worst_stopped, std::abs(vy) / v0);
    }
  }
  const double vy = motion(sim.particles()).velocity(1);
  const double lost = 0.5 * mass * (v0 * v0 - vy * vy);
  const double heat = test::ledger_sink(sim.ledger(), "friction_heat");
  BOOST_TEST_MESSAGE(sim.steps() << " steps: v_y against v0 - mu g t worst " << worst_sliding
                                 << " v0 while sliding, " << worst_stopped
                                 << " v0 after the stop; friction heat " << heat << " J against "
                                 << lost << " J of kinetic energy lost (" << heat / lost - 1
                                 << "); energy_error " << sim.ledger().row().energy_error);
  BOOST_TEST(worst_sliding < 0.02);
  BOOST_TEST(worst_stopped < 0.02);
  BOOST_TEST(std::abs(heat / lost - 1.0) < 0.03);
}

BOOST_AUTO_TEST_CASE(a_wall_met_at_the_particles_follows_coulombs_law_and_keeps_the_books) {
  // The same block on the wall met at the particles (grid.wall_contact "particles"): a stick
  // spring per pushed particle, slipping onto mu F_n (contact/rigid_particle_contact.hpp); the
  // sudden load rings on the penalty layer. Coulomb's law as above, the heat the kinetic energy
  // lost, and the books closed: the slip's work is all heat (the walls at the nodes book their
  // catch as a residual, -0.0056 here).
  const Scene scene =
      test::verification_scene("sliding_block.json", {{"grid", {{"wall_contact", "particles"}}}});
  Simulation sim(scene, 1);  // a small grid: one thread runs it faster than two
  const double v0 = 5.0, g = 1.0e5, mu = 0.25, t_stop = v0 / (mu * g);
  const int block = test::object_index(scene, "block");
  const auto [worst_sliding, worst_stopped] = test::follow_along_y(
      sim, block, [&](double t) { return v0 - mu * g * t; }, t_stop, 0.0, v0);
  const auto [lost, heat, error] = test::slide_books(sim, block, v0);
  BOOST_TEST_MESSAGE("at the particles: v_y against v0 - mu g t worst "
                     << worst_sliding << " v0 while sliding, " << worst_stopped
                     << " v0 after the stop; friction heat " << heat << " J against " << lost
                     << " J of kinetic energy lost (" << heat / lost - 1 << "); energy_error "
                     << error);
  BOOST_TEST(worst_sliding < 0.02);
  BOOST_TEST(worst_stopped < 0.02);
  BOOST_TEST(std::abs(heat / lost - 1.0) < 0.01);
  BOOST_TEST(std::abs(error) < 0.002);
}

// The block of sliding_block.json at rest against the y- face, which moves at `face` [m/s], on
// the rough x- wall met at the particles (damped 0.3); `patch` on top.
Scene pushed_block(const Json& face, const Json& patch) {
  Json scene = {{"objects",
                 {{"block",
                   {{"geometry", {{"lower", {0.0, 0.0, 0.002}}, {"upper", {0.002, 0.004, 0.004}}}},
                    {"velocity", {0.0, 0.0, 0.0}}}}}},
                {"grid",
                 {{"boundary", {{"y-", "symmetric"}}},
                  {"face_velocity", {{"y-", face}}},
                  {"wall_contact", "particles"},
                  {"wall_penalty_damping", 0.3}}}};
  scene.merge_patch(patch);
  return test::verification_scene("sliding_block.json", scene);
}

BOOST_AUTO_TEST_CASE(a_moving_face_pushes_a_block_along_a_rough_wall_met_at_the_particles) {
  // A moving face beside a rough wall: refused at the nodes, whose edge nodes both would hold
  // (docs/scenes.md#moving-faces), allowed at the particles, where the wall holds no node. The
  // block of sliding_block.json, at rest against the y- face, pressed onto the x- wall (mu 0.25)
  // by a body force ramped over 20 us; the face pushes it along y, its speed ramped to V = 1 m/s
  // over 20 us. Once it slides steadily (the second half of 120 us) the wall's friction does
  // mu M g per metre slid: the heat equals mu M g times the block's travel, within 2 % (measured
  // 0.05 %), and the books close within 0.002 (2.2e-4). Where the block rings along y the stick
  // springs lag and the heat falls short: 0.90 with the face ramped over 2 us and the load at
  // once, 0.76 with the face at full speed (docs/scenes.md#moving-faces).
  const double g = 1.0e5, mu = 0.25, V = 1.0;
  const Scene scene =
      pushed_block("min(t/2e-5,1)*1.0",
                   {{"objects", {{"block", {{"body_force", {"-1e5*min(t/2e-5,1)", 0, 0}}}}}},
                    {"solver", {{"gravity", {0.0, 0.0, 0.0}}}},
                    {"time", {{"max_time", 1.2e-4}}}});
  Simulation sim(scene, 1);  // a small grid: one thread runs it faster than two
  const int block = test::object_index(scene, "block");
  double y_half = 0.0, heat_half = 0.0;
  while (!sim.finished()) {
    sim.step();
    if (y_half == 0.0 && sim.time() >= 6.0e-5) {
      y_half = test::motion_of(sim.particles(), block).centre(1);
      heat_half = test::ledger_sink(sim.ledger(), "friction_heat");
    }
  }
  const test::BodyMotion b = test::motion_of(sim.particles(), block);
  const double travel = b.centre(1) - y_half;
  const double heat = test::ledger_sink(sim.ledger(), "friction_heat") - heat_half;
  const double coulomb = mu * b.mass * g * travel;
  const double error = sim.ledger().row().energy_error;
  BOOST_TEST_MESSAGE("block pushed along the rough wall by the y- face: travel "
                     << travel << " m over the second half (face " << V * 6.0e-5 << " m), heat "
                     << heat << " J against mu M g travel " << coulomb << " J, energy_error "
                     << error);
  BOOST_TEST(heat == coulomb, boost::test_tools::tolerance(0.02));
  BOOST_TEST(travel == V * 6.0e-5, boost::test_tools::tolerance(0.05));
  BOOST_TEST(std::abs(error) < 0.002);
}

BOOST_AUTO_TEST_CASE(a_face_started_at_full_speed_under_a_sudden_load_runs) {
  // The same block and face, the face at V = 1 m/s from t = 0 and the load applied at once
  // (sliding_block.json's gravity; a new user's scene had the same as a body force). The face's
  // first steps strain the block before its work is booked, so the books' scale E_in must be at
  // least 1/2 M V^2, as for a moving rigid object (docs/mpm.md, energy_error): against the load's
  // first work alone the step-1 residual read +1872 and the energy check stopped the run.
  // Asserted: it runs 20 us, its worst |energy_error| over every step below 0.1 (measured 0.046,
  // the face's start-up residual; docs/scenes.md).
  Simulation sim(pushed_block(1.0, {{"time", {{"max_time", 2.0e-5}}}}), 1);
  double worst = 0.0;
  while (!sim.finished()) {
    sim.step();
    worst = std::max(worst, std::abs(sim.ledger().row().energy_error));
  }
  BOOST_TEST_MESSAGE("face at 1 m/s from the start, load at once: worst |energy_error| " << worst);
  BOOST_TEST(worst < 0.1);
}

BOOST_AUTO_TEST_CASE(an_upper_face_wall_follows_the_same_law) {
  // The block mirrored onto the x+ face (inward normal -x, gravity +x), sliding along z this
  // time: v_z = v0 - mu g t over the first 120 us, within 0.02 v0 as above.
  const Scene scene = test::verification_scene(
      "sliding_block.json",
      {{"objects",
        {{"block",
          {{"geometry", {{"lower", {0.002, 0.002, 0.002}}, {"upper", {0.004, 0.006, 0.004}}}},
           {"velocity", {0.0, 0.0, 5.0}}}}}},
       {"grid",
        {{"upper", {0.004, 0.01, 0.01}},
         {"cells", {8, 20, 20}},
         {"boundary", {{"x-", "free"}, {"x+", "wall"}}},
         {"wall_friction", {{"x-", nullptr}, {"x+", 0.25}}}}},
       {"solver", {{"gravity", {1.0e5, 0.0, 0.0}}}},
       {"time", {{"max_time", 1.2e-4}}}});
  Simulation sim(scene);
  const double v0 = 5.0, g = 1.0e5, mu = 0.25;
  double worst = 0.0;
  while (!sim.finished()) {
    sim.step();
    const Motion m = motion(sim.particles());
    worst = std::max(worst, std::abs(m.velocity(2) - (v0 - mu * g * sim.time())) / v0);
  }
  BOOST_TEST_MESSAGE("x+ wall: v_z against v0 - mu g t worst " << worst << " v0 over "
                                                               << sim.steps() << " steps");
  BOOST_TEST(worst < 0.02);
}

BOOST_AUTO_TEST_CASE(the_books_close_at_either_time_step) {
  // energy_error is the numerical residual of the friction step and the wall's inelastic catch:
  // it may not be positive (no energy made). Measured over the first 120 us: -0.18 % of E0 at
  // multiplier 0.5, -0.16 % at 0.25 (-0.26 % / -0.35 % before the re-map took the step's v* where
  // friction acted), and -0.24 % at h/2 (cells 16 x 40 x 24, multiplier 0.5).
  // Before issue 53 (the re-map decided afresh, gravity's work booked before the wall held) it
  // was +0.13 % and -0.01 %, and +0.37 % at h/2: growing, the phantom gravity work hiding the
  // catch. Before the touch test (grid/wall.cpp) +0.88 % and +0.25 %. Asserted: within
  // [-0.5 %, +0.05 %] at both.
  double error[2];
  for (const int k : {0, 1}) {
    const Scene scene = test::verification_scene(
        "sliding_block.json",
        {{"time", {{"multiplier", k == 0 ? 0.5 : 0.25}, {"max_time", 1.2e-4}}}});
    Simulation sim(scene);
    while (!sim.finished()) sim.step();
    error[k] = sim.ledger().row().energy_error;
  }
  BOOST_TEST_MESSAGE("energy_error at multiplier 0.5: " << error[0] << ", at 0.25: " << error[1]);
  for (const double e : error) {
    BOOST_TEST(e > -0.005);
    BOOST_TEST(e < 0.0005);
  }
}

BOOST_AUTO_TEST_CASE(a_frictionless_wall_lets_the_block_slide_on) {
  const Scene scene = test::verification_scene(
      "sliding_block.json",
      {{"grid", {{"wall_friction", {{"x-", 0.0}}}}}, {"time", {{"max_time", 1e-4}}}});
  Simulation sim(scene);
  double worst = 0.0;
  while (!sim.finished()) {
    sim.step();
    worst = std::max(worst, std::abs(motion(sim.particles()).velocity(1) / 5.0 - 1.0));
  }
  BOOST_TEST_MESSAGE("frictionless wall: v_y within " << worst << " of v0 over " << sim.steps()
                                                      << " steps");
  BOOST_TEST(worst < 1e-9);
}

BOOST_AUTO_TEST_CASE(the_wall_never_pulls) {
  // Gravity away from the wall: the block must accelerate freely at g (a mirror plane would hold
  // its face layer and pull it back). After t its mean x velocity is g t and its lowest particle
  // has moved g t^2 / 2 (within 2 %: the block starts stress-free and moves as a rigid body).
  const Scene scene = test::verification_scene(
      "sliding_block.json",
      {{"solver", {{"gravity", {1.0e5, 0.0, 0.0}}}}, {"time", {{"max_time", 5e-5}}}});
  Simulation sim(scene);
  const double x0 = motion(sim.particles()).lower(0);
  while (!sim.finished()) sim.step();
  const Motion m = motion(sim.particles());
  const double t = sim.time(), g = 1.0e5;
  BOOST_TEST_MESSAGE("pulled away: v_x " << m.velocity(0) << " m/s against g t = " << g * t
                                         << ", lowest particle moved " << m.lower(0) - x0
                                         << " m against g t^2/2 = " << 0.5 * g * t * t);
  BOOST_TEST(std::abs(m.velocity(0) / (g * t) - 1.0) < 0.02);
  BOOST_TEST(std::abs((m.lower(0) - x0) / (0.5 * g * t * t) - 1.0) < 0.02);
}

// Crushed onto the wall by 1e11 m/s^2 (multiplier 0.9, J down to 0.02 by 40 us), a face particle
// creeps onto the face, where the held node's velocity tends to zero, and crosses it by
// round-off: x = -6.8e-22 m stopped the run at step 1405 as "left the grid". A particle within
// 1e-12 of a cell of a face is put back on it (grid_to_particles.cpp): the run completes, and no
// particle is ever behind the wall.
BOOST_AUTO_TEST_CASE(a_particle_pressed_onto_the_wall_stays_on_it) {
  const Scene scene = test::verification_scene(
      "sliding_block.json", {{"solver", {{"gravity", {-1.0e11, 0.0, 0.0}}}},
                             {"time", {{"multiplier", 0.9}, {"max_time", 4e-5}}}});
  Simulation sim(scene);
  double lowest = 0.0;
  while (!sim.finished()) {
    sim.step();
    lowest = std::min(lowest, motion(sim.particles()).lower(0));
  }
  BOOST_TEST(sim.steps() > 1405);
  BOOST_TEST(sim.time() == 4e-5, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(lowest >= 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
