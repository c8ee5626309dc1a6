// Coulomb friction between two bodies (physics.contact "friction", contact/contact.cpp) against
// Coulomb's law, on data/scenes/verification/block_on_block.json: a 2 x 4 x 2 mm elastic block
// on a larger one that rests on an x- wall (friction 1, so it stays put), gravity g_n = 1e5 m/s^2
// pressing both, contact mu = 0.25.
// 1. Sliding at v0 = 5 m/s along y: the friction force is mu M g_n, so the block's mean velocity
//    is v_y = v0 - mu g_n t over the 120 us (it would stop at 200 us), and the Coulomb heat
//    booked (m s (u0 . t) per node and field where it slips) equals its kinetic energy lost,
//    1/2 M (v0^2 - v_y^2). Asserted: v_y within 0.04 v0 of the law at every step (measured
//    0.030 at the worst step, 0.012 at every 10 us: the sudden load sets both blocks vibrating),
//    heat within 3 % of the loss (measured 1.9 %). With the sum of the mass gradients as the normal
//    (the default, `mass_gradients`) the normal tilts at the sliding block's leading edge, where
//    the lower block's flat face is the contact surface: the slide reads as an approach there, 0.9
//    m/s goes in the first 10 us and the block stops 1.6 times sooner than Coulomb's law (v_y 0.07
//    m/s at 120 us against 2.0), with 26 % of the loss unbooked. The scene sets `larger_volume`.
// 2. At rest, pushed along the interface by a body force g_t on both blocks (gravity (-g_n, g_t,
//    0)): the contact needs no rule of its own for bodies pressed together: their compressed
//    material pushes the interface nodes into each other at every step, and that approach bounds
//    the friction. Over 100 us, below mu (g_t = 0.15 g_n) the block sticks: its velocity relative
//    to the lower block stays below 5 % of the free slide's final g_t T at every step (measured
//    3.8 %: the elastic shear of the interface layer); above mu (g_t = 0.35 g_n) it slides at
//    (g_t - mu g_n) t within 2 % of g_t T (measured 0.8 %). With the `mass_gradients` normal the
//    pushed block's leading edge reads the slide as an approach and holds it: it never slides
//    (relative v_y 4e-4 m/s at 92 us where Coulomb's law gives 0.92).
// 3. The same slide cut in half by a `symmetric` plane z = 3 mm (both blocks are symmetric about
//    it): the half model is the whole one's upper half, so its bodies' velocities equal the
//    whole's and its heat is half the whole's, to round-off (asserted 1e-6 relative over 60 us;
//    the same cut of the single sliding block on its wall agrees to 1e-7 in energy_error).
//    Before contact saw the face layer as the mirror leaves it (contact.cpp, mirror_view), the
//    particles of one side gave the symmetric face nodes a normal velocity v_z that the slip
//    counted, friction went partly into it, and the half slid 1.1 % faster after 120 us.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;
namespace tt = boost::test_tools;

namespace {

struct Bodies {
  double mass[2] = {0.0, 0.0};
  Vec3 velocity[2] = {Vec3::Zero(), Vec3::Zero()};  ///< mass-weighted mean [m/s]
};

// Material 0: the lower block (left_al), 1: the sliding block (right_al).
Bodies bodies(const Particles& P) {
  Bodies b;
  Vec3 p[2] = {Vec3::Zero(), Vec3::Zero()};
  for (std::size_t i = 0; i < P.size(); ++i) {
    const int m = P.material[i];
    b.mass[m] += P.mass[i];
    p[m] += P.mass[i] * P.v[i];
  }
  for (int m = 0; m < 2; ++m) b.velocity[m] = p[m] / b.mass[m];
  return b;
}

// Case 1's slide over its first 40 us with the contact normal `normal`: the worst
// |v_y - (v0 - mu g t)| / v0 over the steps.
double worst_slide(const char* normal) {
  const double v0 = 5.0, g = 1.0e5, mu = 0.25;
  Simulation sim(test::verification_scene(
      "block_on_block.json",
      {{"physics", {{"contact", {{"normal", normal}}}}}, {"time", {{"max_time", 4.0e-5}}}}));
  double worst = 0.0;
  while (!sim.finished()) {
    sim.step();
    const double vy = bodies(sim.particles()).velocity[1](1);
    worst = std::max(worst, std::abs(vy - (v0 - mu * g * sim.time())) / v0);
  }
  BOOST_TEST_MESSAGE(normal << ": v_y against v0 - mu g t over 40 us, worst " << worst << " v0");
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(contact_friction)

// docs/mpm.md's guidance at the corner of a small body on a large flat one: `larger_volume` takes
// the large body's face as the contact surface (case 1 holds it to 0.04 v0); the separating plane
// (`logistic_regression`, fitted to the particles within about two cells of the node) comes within
// 0.1 v0 (measured 0.080); the sum of the mass gradients tilts at the corner, reads the slide as an
// approach and decelerates the block too fast (0.17 v0). With the plane fitted to the node's own
// support only it was 0.63 v0: the support cut the flat face off beside the corner.
BOOST_AUTO_TEST_CASE(at_a_small_bodys_corner_the_plane_comes_close_and_the_gradients_do_not) {
  BOOST_TEST(worst_slide("logistic_regression") < 0.1);
  BOOST_TEST(worst_slide("mass_gradients") > 0.1);
}

// A block on a ramp that is not grid-aligned (data/scenes/verification/ramp.json: a 20-degree end
// face of another body, frictionless, gravity 1e5 m/s^2 along -x), 25 us: Coulomb's law slides it
// down the ramp at g sin 20 deg. Each body's seeded surface is a staircase at the grid scale; at a
// pressed interface every node holds its own normal, and normals that differ from node to node
// hold every direction between them. With the mass gradients (and with the plane fitted to each
// node's own support) the block does not slide at all: asserted below 10 % of the law. The plane
// fitted to the wider cloud (step/contact_planes.cpp) lets it slide at more than 60 % of the law
// (measured in the message); the same ramp turned grid-aligned (gravity tilted instead) slides at
// 1.705 m/s against 1.71 in 50 us.
BOOST_AUTO_TEST_CASE(a_block_on_a_ramp_off_the_grid_slides_with_the_plane_not_with_the_gradients) {
  const double g = 1.0e5, angle = 20.0 * std::acos(-1.0) / 180.0, T = 2.5e-5;
  const Vec3 down(-std::sin(angle), std::cos(angle), 0.0);  // down the ramp: -x along the face
  const auto slide = [&](const char* normal) {
    Simulation sim(test::verification_scene(
        "ramp.json",
        {{"physics", {{"contact", {{"normal", normal}}}}}, {"time", {{"max_time", T}}}}));
    while (!sim.finished()) sim.step();
    const double speed = bodies(sim.particles()).velocity[1].dot(down);
    BOOST_TEST_MESSAGE(normal << ": down the ramp at " << speed << " m/s against Coulomb's "
                              << g * std::sin(angle) * T << " m/s, energy_error "
                              << sim.ledger().row().energy_error);
    return speed / (g * std::sin(angle) * T);
  };
  BOOST_TEST(slide("logistic_regression") > 0.6);
  BOOST_TEST(std::abs(slide("mass_gradients")) < 0.1);
}

// The ramp made rigid (`objects.left.rigid`, issue 53): against a rigid body the normal is its own
// surface, the gradient of its geometry's signed distance (mpm/geometry/surface_distance.hpp;
// contact.cpp normal_against_rigid). Over 25 us the block slides down the ramp at Coulomb's rate:
// frictionless g sin(theta), at contact mu 0.2 g (sin(theta) - 0.2 cos(theta)), with the friction
// heat mu m g cos(theta) times the slide's distance. At 20 degrees (the scene's ramp), and at 10
// and 45 (the ramp's axis turned about the slider's base, 2 mm long): asserted within 2 %
// (measured in the message: 1.000, 1.003, 1.000, 1.000; at 50 us and at h/2 1.000 too). Against
// the rigid body's mass gradient, a staircase off the grid's axes, it slid at 0.64 of the
// frictionless law at 20 degrees (50 us), against the plane fitted to the particles 0.76; with the
// geometry's normal taken only where it faced the slider's own staircase gradient (within 60
// degrees), at 0.56, and 0.43 at 10 degrees and h/2 (a new user's trial).
BOOST_AUTO_TEST_CASE(a_block_on_a_rigid_ramp_slides_at_coulombs_rate) {
  const double g = 1.0e5, T = 2.5e-5, pi = std::acos(-1.0);
  const Vec3 base(0.0045, 0.006, 0.003);  // the centre of the ramp's face, the slider's base
  for (const auto& [degrees, mu] : {std::pair{20.0, 0.0}, {20.0, 0.2}, {10.0, 0.0}, {45.0, 0.0}}) {
    const double angle = degrees * pi / 180.0;
    const Vec3 axis(std::cos(angle), std::sin(angle), 0.0), down(-axis(1), axis(0), 0.0);
    Json patch = {{"objects", {{"left", {{"rigid", true}}}}},
                  {"physics", {{"contact", {{"mu", mu}}}}},
                  {"time", {{"max_time", T}}}};
    if (degrees != 20.0) {  // the ramp's axis and the slider's, turned
      const auto point = [](const Vec3& x) { return Json{x(0), x(1), x(2)}; };
      patch["objects"]["left"]["geometry"]["parts"]["ramp"] = {
          {"bottom", point(base - 0.002 * axis)}, {"top", point(base)}};
      patch["objects"]["right"]["geometry"] = {{"bottom", point(base)},
                                               {"top", point(base + 0.0015 * axis)}};
    }
    Simulation sim(test::verification_scene("ramp.json", patch));
    const double mass = bodies(sim.particles()).mass[1];
    while (!sim.finished()) sim.step();
    const double a = g * (std::sin(angle) - mu * std::cos(angle));
    const double speed = bodies(sim.particles()).velocity[1].dot(down);
    const double heat = mu * mass * g * std::cos(angle) * 0.5 * a * T * T;
    const double booked = mu > 0.0 ? test::ledger_sink(sim.ledger(), "friction_heat") : 0.0;
    BOOST_TEST_MESSAGE("rigid ramp at " << degrees << " degrees, mu " << mu << ": down the ramp at "
                                        << speed / (a * T) << " of Coulomb's " << a * T
                                        << " m/s, friction heat " << booked << " J against " << heat
                                        << " J, energy_error " << sim.ledger().row().energy_error);
    BOOST_TEST(speed / (a * T) == 1.0, tt::tolerance(0.02));
    if (mu > 0.0) BOOST_TEST(booked == heat, tt::tolerance(0.05));
  }
}

// The same ramp on a graded grid (issue 56): the interface inside a box of cells twice as fine,
// growing by 1.5 per cell outside it, over 12.5 us. The plane's fit takes each node's own
// coordinates and its dual cell for the tent's reach (step/contact_planes.cpp); fitted in base
// cells about nodes placed as on the uniform grid, the block locked as with the gradients
// (-0.005 m/s against Coulomb's 0.855 at 25 us). The same bound as on the uniform grid: more
// than 60 % of Coulomb's law (measured in the message).
BOOST_AUTO_TEST_CASE(the_ramp_on_a_graded_grid_slides_with_the_plane) {
  const double g = 1.0e5, angle = 20.0 * std::acos(-1.0) / 180.0, T = 1.25e-5;
  const Vec3 down(-std::sin(angle), std::cos(angle), 0.0);
  const Json box = {{"lower", {0.004, 0.0045, 0.002}},
                    {"upper", {0.0055, 0.0075, 0.004}},
                    {"factor", 2},
                    {"growth", 1.5}};
  Simulation sim(test::verification_scene(
      "ramp.json", {{"grid", {{"refine", box}}}, {"time", {{"max_time", T}}}}));
  BOOST_TEST_REQUIRE(sim.scene().grid.graded());
  while (!sim.finished()) sim.step();
  const double speed = bodies(sim.particles()).velocity[1].dot(down);
  BOOST_TEST_MESSAGE("graded: down the ramp at " << speed << " m/s against Coulomb's "
                                                 << g * std::sin(angle) * T << " m/s, energy_error "
                                                 << sim.ledger().row().energy_error);
  BOOST_TEST(speed / (g * std::sin(angle) * T) > 0.6);
}

BOOST_AUTO_TEST_CASE(a_block_sliding_on_a_block_follows_coulombs_law_and_its_loss_is_heat) {
  const double v0 = 5.0, g = 1.0e5, mu = 0.25;
  Simulation sim(test::verification_scene("block_on_block.json"));
  BOOST_REQUIRE(sim.grid().fields() == 2);
  double worst = 0.0;
  while (!sim.finished()) {
    sim.step();
    const double vy = bodies(sim.particles()).velocity[1](1);
    worst = std::max(worst, std::abs(vy - (v0 - mu * g * sim.time())) / v0);
  }
  const Bodies b = bodies(sim.particles());
  const double vy = b.velocity[1](1);
  const double lost = 0.5 * b.mass[1] * (v0 * v0 - vy * vy);
  const double heat = test::ledger_sink(sim.ledger(), "friction_heat");
  BOOST_TEST_MESSAGE(sim.steps() << " steps: v_y against v0 - mu g t worst " << worst
                                 << " v0; lower block v_y " << b.velocity[0](1) << " m/s; heat "
                                 << heat << " J against " << lost << " J lost ("
                                 << heat / lost - 1.0 << ")");
  BOOST_TEST(worst < 0.04);
  BOOST_TEST(std::abs(heat / lost - 1.0) < 0.03);
}

BOOST_AUTO_TEST_CASE(a_block_pushed_along_the_interface_sticks_below_mu_and_slides_above) {
  const double gn = 1.0e5, mu = 0.25;
  for (const double ratio : {0.15, 0.35}) {
    const double gt = ratio * gn;
    Simulation sim(test::verification_scene(
        "block_on_block.json", {{"objects", {{"right", {{"velocity", {0.0, 0.0, 0.0}}}}}},
                                {"solver", {{"gravity", {-gn, gt, 0.0}}}},
                                {"time", {{"max_time", 1.0e-4}}}}));
    double worst = 0.0;
    while (!sim.finished()) {
      sim.step();
      const Bodies b = bodies(sim.particles());
      const double relative = b.velocity[1](1) - b.velocity[0](1);
      const double law = std::max(gt - mu * gn, 0.0) * sim.time();
      worst = std::max(worst, std::abs(relative - law) / (gt * sim.scene().time.max_time));
    }
    BOOST_TEST_MESSAGE("g_t = " << ratio << " g_n: relative v_y within " << worst
                                << " of g_t T of Coulomb's " << (ratio < mu ? "stick" : "slide"));
    BOOST_TEST(worst < (ratio < mu ? 0.05 : 0.02));
  }
}

BOOST_AUTO_TEST_CASE(a_symmetric_plane_along_the_slide_halves_the_books_and_nothing_else) {
  const Json shorter = {{"time", {{"max_time", 6.0e-5}}}};
  Json half = shorter;
  half["objects"] = {{"left", {{"geometry", {{"lower", {0.0, 0.001, 0.003}}}}}},
                     {"right", {{"geometry", {{"lower", {0.002, 0.002, 0.003}}}}}}};
  half["grid"] = {
      {"lower", {0.0, 0.0, 0.003}}, {"cells", {12, 24, 6}}, {"boundary", {{"z-", "symmetric"}}}};
  Simulation whole(test::verification_scene("block_on_block.json", shorter));
  Simulation cut(test::verification_scene("block_on_block.json", half));
  while (!whole.finished()) whole.step();
  while (!cut.finished()) cut.step();
  BOOST_REQUIRE(cut.steps() == whole.steps());
  const Bodies w = bodies(whole.particles()), c = bodies(cut.particles());
  const double heat_whole = test::ledger_sink(whole.ledger(), "friction_heat");
  const double heat_cut = test::ledger_sink(cut.ledger(), "friction_heat");
  BOOST_TEST_MESSAGE("whole: sliding v_y "
                     << w.velocity[1](1) << " m/s, heat " << heat_whole
                     << " J; half: v_y - whole's " << c.velocity[1](1) - w.velocity[1](1)
                     << " m/s (lower block " << c.velocity[0](1) - w.velocity[0](1)
                     << "), heat x 2 / whole's - 1 " << 2.0 * heat_cut / heat_whole - 1.0);
  BOOST_TEST(cut.particles().size() * 2 == whole.particles().size());
  for (int b = 0; b < 2; ++b)
    BOOST_TEST(std::abs(c.velocity[b](1) - w.velocity[b](1)) < 1e-6 * 5.0);  // v0 = 5 m/s
  BOOST_TEST(std::abs(2.0 * heat_cut / heat_whole - 1.0) < 1e-6);
}

BOOST_AUTO_TEST_SUITE_END()
