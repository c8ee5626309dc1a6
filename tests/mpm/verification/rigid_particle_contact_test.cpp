// Bodies meeting rigid objects at the particles (physics.contact.rigid_contact = "particles",
// contact/rigid_particle_contact.hpp), each case against a closed form:
// - a disk sliding in a frictionless rigid trough (rigid_trough.json): every normal force acts
//   through the disk's centre, so it does not turn (omega = 0), and its centre reaches the bottom
//   at the slide's sqrt(2 g (R - r)(1 - cos 30 deg)) = 25.88 m/s. At the nodes the contact patch
//   holds it as a pendulum about the trough's centre, omega r / v = r / (R - r) = 0.6 whatever h,
//   and it reaches only the pendulum's 23.8 m/s (docs/verification.md);
// - a block released at rest on a rigid floor under gravity: it stays there, its books closed and
//   its ringing not growing; with a force that jumps to k delta as a domain enters, each entry
//   and exit worked energy no motion paid for and the energy check stopped the run at 24 us;
// - a column (uniaxial strain) released at rest on a rigid floor stays there for a second, its
//   ringing at the closed form's scale and its books closed, by MUSL and USL: a pushed particle
//   that moved with another velocity than its strain sees made MUSL gain energy until the check
//   stopped it (contact/rigid_particle_contact.hpp);
// - a soft block thrown at 2.6 times its wave speed onto a rigid floor bounces off it, no
//   particle centre passing into the floor;
// - a block spanning the gap between two rigid blocks at rest keeps its energy (the exact bounce);
// - a rigid piston driven into an elastic bar pushes with the one-dimensional wave's force
//   rho c_L A V (Meyers 1994, sec. 2.2), its work booked as external work at its velocity;
// - a block seeded around a rigid pin, all at rest, stays at rest.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <optional>
#include <string>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// Small grids: one thread runs them faster than two (docs/performance.md#threads).
constexpr int kThreads = 1;

const Json kAtParticles = {{"physics", {{"contact", {{"rigid_contact", "particles"}}}}}};

Json at_particles(Json patch) {
  Json p = kAtParticles;
  p.merge_patch(patch);
  return p;
}

using test::BodyMotion;
using test::motion_of;
using test::object_index;

}  // namespace

BOOST_AUTO_TEST_SUITE(rigid_particle_contact)

BOOST_AUTO_TEST_CASE(a_disk_slides_down_a_frictionless_rigid_trough_without_turning) {
  const Scene scene = test::verification_scene("rigid_trough.json", kAtParticles);
  Simulation sim(scene, kThreads);
  const int disk = object_index(scene, "disk");
  const double r = 1.5e-3, R = 4.0e-3, g = 1.0e6;
  const double slide = std::sqrt(2.0 * g * (R - r) * (1.0 - std::cos(M_PI / 6.0)));  // 25.88 m/s
  double worst_spin = 0.0, fastest = 0.0, next_sample = 5.0e-6;
  while (!sim.finished()) {
    sim.step();
    if (sim.time() < next_sample) continue;  // every 5 us, as body_spin.py reads the snapshots
    next_sample += 5.0e-6;
    const BodyMotion b = motion_of(sim.particles(), disk);
    const double speed = b.velocity.norm();
    fastest = std::max(fastest, speed);
    worst_spin = std::max(worst_spin, std::abs(b.omega) * r / speed);
  }
  const LedgerRow row = sim.ledger().row();
  BOOST_TEST_MESSAGE(
      "disk in a frictionless rigid trough, h = 0.25 mm, contact at the particles: "
      "worst omega r / v "
      << worst_spin << " (nodes: 0.58-0.67; pendulum " << r / (R - r) << "), fastest " << fastest
      << " m/s (slide " << slide << "), energy_error " << row.energy_error << ", contact energy "
      << test::ledger_sink(sim.ledger(), "contact_energy") << " J/m");
  // Measured 0.095 here, 0.019 at h/2, 0.233 at 2h (docs/verification.md): bounded well below
  // the pendulum's 0.6 that the nodes give at every h.
  BOOST_TEST(worst_spin < 0.15);
  BOOST_TEST(fastest == slide, boost::test_tools::tolerance(0.04));  // 26.47: +2.3 %
  BOOST_TEST(std::abs(row.energy_error) < 0.02);
}

BOOST_AUTO_TEST_CASE(a_block_released_at_rest_on_a_rigid_floor_stays_there) {
  // The 2 x 4 x 2 mm block of sliding_block_rigid.json at rest, gravity 1e5 m/s^2 along -x into
  // the floor, applied at once; frictionless; h = 0.5 mm.
  const Scene scene = test::verification_scene(
      "sliding_block_rigid.json",
      at_particles({{"physics", {{"contact", {{"mu", 0.0}}}}},
                    {"objects", {{"block", {{"velocity", {0.0, 0.0, 0.0}}}}}},
                    {"time", {{"max_time", 1.0e-4}}}}));
  Simulation sim(scene, kThreads);
  const int block = object_index(scene, "block");
  const double g = 1.0e5, h = 0.5e-3, t_end = 1.0e-4;
  const BodyMotion start = motion_of(sim.particles(), block);
  double early_kinetic = 0.0, late_kinetic = 0.0, worst_sink = 0.0, worst_error = 0.0;
  while (!sim.finished()) {
    sim.step();
    const BodyMotion b = motion_of(sim.particles(), block);
    if (sim.time() <= 0.25 * t_end) early_kinetic = std::max(early_kinetic, b.kinetic_energy);
    if (sim.time() >= 0.75 * t_end) late_kinetic = std::max(late_kinetic, b.kinetic_energy);
    worst_sink = std::max(worst_sink, start.centre(0) - b.centre(0));
    worst_error = std::max(worst_error, std::abs(sim.ledger().row().energy_error));
  }
  const LedgerRow row = sim.ledger().row();
  const double weight_impulse = start.mass * g * sim.time();
  BOOST_TEST_MESSAGE("block at rest on a rigid floor, contact at the particles, "
                     << sim.steps() << " steps: kinetic energy at most " << early_kinetic
                     << " J in the first quarter, " << late_kinetic
                     << " J in the last; sank at most " << worst_sink << " m; worst energy_error "
                     << worst_error << " (end " << row.energy_error << "); the floor's impulse "
                     << row.boundary_impulse(0) << " N s against the weight's " << weight_impulse
                     << " N s");
  BOOST_TEST(sim.steps() > 2000);  // 1e-4 s: it completes
  // Nothing grows: a force that jumps to k delta as a domain enters pumped the ringing until the
  // energy check stopped the run at 24 us.
  BOOST_TEST(late_kinetic <= 1.2 * early_kinetic);
  BOOST_TEST(worst_error < 0.05);
  // The onset's compliance lets it settle 1.0 um (0.002 h) into the floor, and no further.
  BOOST_TEST(worst_sink < 0.005 * h);
  BOOST_TEST(row.boundary_impulse(0) == weight_impulse, boost::test_tools::tolerance(0.02));
}

BOOST_AUTO_TEST_CASE(a_column_stays_at_rest_on_a_rigid_floor_for_a_second) {
  // resting_column_rigid.json: a soft column (uniaxial strain) under gravity applied at once.
  // Closed forms: the floor's impulse is the weight's, rho g W L t; the column rings about its
  // settled state with a kinetic energy of at most the energy stored there (a load applied at
  // once does twice the work the springs keep): its own U_s = (rho g)^2 W L^3 / (6 M), and the
  // onset layer's, whose force grows as delta^2, F delta_c / 3 stored for F delta_c of work, so
  // U_s + 2 F delta_c / 3 with delta_c = (h / 2) sqrt(rho g L / M) (the piston's formula below).
  // Before the pushed particles moved with the velocity their strain sees, MUSL gained energy
  // until the check stopped the run at step 3917, and USL ended at +0.645.
  for (const char* scheme : {"musl", "usl"}) {
    const Scene scene =
        test::verification_scene("resting_column_rigid.json", {{"solver", {{"scheme", scheme}}}});
    Simulation sim(scene, kThreads);
    const double rho = 1000.0, g = 1000.0, W = 0.025, L = 0.1, h = 0.0125, t_end = 1.0;
    const int column = object_index(scene, "block");
    const auto& p = scene.materials[scene.objects[column].material].material.model.params();
    const double M = p.bulk_modulus + 4.0 / 3.0 * p.shear_modulus;
    const double F = rho * g * L * W;  // [N/m]
    const double U_s = rho * g * rho * g * W * L * L * L / (6.0 * M);
    const double delta_c = 0.5 * h * std::sqrt(rho * g * L / M);
    const double ringing = U_s + 2.0 / 3.0 * F * delta_c;  // [J/m]
    double early = 0.0, late = 0.0, worst = 0.0, most = -1.0;
    while (!sim.finished()) {
      sim.step();
      const LedgerRow r = sim.ledger().row();
      if (sim.time() <= 0.25 * t_end) early = std::max(early, r.kinetic_energy);
      if (sim.time() >= 0.75 * t_end) late = std::max(late, r.kinetic_energy);
      worst = std::max(worst, std::abs(r.energy_error));
      most = std::max(most, r.energy_error);
    }
    const LedgerRow r = sim.ledger().row();
    BOOST_TEST_MESSAGE(scheme << ": column at rest on a rigid floor, " << sim.steps()
                              << " steps: kinetic energy at most " << early << " J/m in the first "
                              << "quarter, " << late << " in the last (closed form of the "
                              << "ringing " << ringing << "); energy_error worst " << worst
                              << ", highest " << most << ", end " << r.energy_error
                              << "; the floor's impulse " << r.boundary_impulse(1) << " N s/m ("
                              << F * sim.time() << ")");
    BOOST_TEST(sim.time() == t_end, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(late <= early);           // nothing grows
    BOOST_TEST(early <= 1.1 * ringing);  // the ringing's scale: at most its bound, 1.195 J/m
    BOOST_TEST(most < 0.05);             // never gains: MUSL at most 0.036, USL 0.032 at the start
    if (std::string(scheme) == "musl") BOOST_TEST(worst < 0.05);
    // USL damps the ringing: it ends at -0.32 with the column settled (the nodes: -0.18).
    if (std::string(scheme) == "usl") BOOST_TEST(r.energy_error > -0.35);
    BOOST_TEST(r.boundary_impulse(1) == F * sim.time(), boost::test_tools::tolerance(0.01));
  }
}

BOOST_AUTO_TEST_CASE(a_soft_block_faster_than_its_waves_does_not_pass_through_a_rigid_floor) {
  // The soft block of resting_block_plane_strain.json (c0 = 116 m/s) thrown at 300 m/s onto a
  // rigid floor three cells thick, no gravity. A penalty of c0 alone let it through (a new
  // user's trial: at 300 m/s the run stopped on a particle stretched to J = 9 below the floor,
  // at 1000 m/s the whole block left through the grid's far face): the closing speed the scene
  // starts with now stiffens it (contact/rigid_particle_contact.hpp, "speed").
  const double V = 300.0, h = 0.0125;
  const Scene scene = test::verification_scene(
      "resting_block_plane_strain.json",
      at_particles(
          {{"materials",
            {{"floor_al",
              {{"file", std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json"}}}}},
           {"objects",
            {{"block", {{"velocity", {0.0, -V, 0.0}}}},
             {"floor",
              {{"material", "floor_al"},
               {"rigid", true},
               {"geometry",
                {{"type", "box"}, {"lower", {0.0, -0.0375, -0.5}}, {"upper", {0.2, 0.0, 0.5}}}}}}}},
           {"grid",
            {{"lower", {0.0, -0.0375}},
             {"upper", {0.2, 0.15}},
             {"cells", {16, 15}},
             {"boundary", {{"y-", "free"}}}}},
           {"physics", {{"contact", {{"type", "friction"}}}}},
           {"solver", {{"gravity", {0.0, 0.0, 0.0}}}},
           {"time", {{"max_time", 5.0e-4}}}}));
  Simulation sim(scene, kThreads);
  const int block = object_index(scene, "block");
  const double p0 =
      motion_of(sim.particles(), block).velocity(1) * motion_of(sim.particles(), block).mass;
  double deepest = 0.0, worst_closure = 0.0;
  while (!sim.finished()) {
    sim.step();
    const Particles& P = sim.particles();
    for (std::size_t p = 0; p < P.size(); ++p)
      if (P.object[p] == block) deepest = std::min(deepest, P.x[p](1));
    const LedgerRow r = sim.ledger().row();
    worst_closure = std::max(worst_closure, std::abs(r.momentum(1) - p0 - r.boundary_impulse(1)));
  }
  const BodyMotion end = motion_of(sim.particles(), block);
  BOOST_TEST_MESSAGE("soft block at " << V << " m/s onto a rigid floor, " << sim.steps()
                                      << " steps: deepest particle centre " << deepest
                                      << " m (floor at 0, h " << h << "), leaves at "
                                      << end.velocity(1) << " m/s, energy_error "
                                      << sim.ledger().row().energy_error);
  // Measured -0.41 h: the impact's pressure needs an overlap beyond the domain's reach. Past the
  // floor's middle (1.5 h) a particle would be pushed out of its far side.
  BOOST_TEST(deepest > -0.5 * h);
  BOOST_TEST(end.velocity(1) > 0.0);                  // it bounced
  BOOST_TEST(worst_closure <= 1e-12 * std::abs(p0));  // the floor's push is the momentum's change
}

BOOST_AUTO_TEST_CASE(a_block_spanning_two_rigid_blocks_keeps_its_energy) {
  Simulation sim(test::verification_scene("spanning_block_rigid.json", kAtParticles), kThreads);
  double worst = 0.0;
  while (!sim.finished()) {
    sim.step();
    worst = std::max(worst, std::abs(sim.ledger().row().energy_error));
  }
  const double last = sim.ledger().row().energy_error;
  BOOST_TEST_MESSAGE("spanning block, contact at the particles: worst abs(energy_error) "
                     << worst << ", at the end " << last << " (nodes: 0.063 / -0.021)");
  BOOST_TEST(worst < 0.05);
  BOOST_TEST(std::abs(last) < 0.02);
}

BOOST_AUTO_TEST_CASE(a_rigid_piston_at_the_particles_pushes_as_the_elastic_wave_does) {
  // At 2 m/s, so that the power's check does not coincide with the push's.
  const double V = 2.0;
  const Scene scene = test::verification_scene(
      "rigid_piston.json",
      at_particles({{"objects", {{"piston", {{"velocity", {V, 0.0, 0.0}}}}}}}));
  Simulation sim(scene, kThreads);
  const double t_end = 2.0e-5, h = 1.25e-3;
  double worst_closure = 0.0, late_time = 0.0, late_impulse = 0.0, late_work = 0.0;
  while (!sim.finished()) {
    sim.step();
    const LedgerRow r = sim.ledger().row();
    worst_closure = std::max(worst_closure, std::abs(r.momentum(0) - r.boundary_impulse(0)));
    if (late_time == 0.0 && sim.time() >= 0.9 * t_end) {
      late_time = sim.time();
      late_impulse = r.boundary_impulse(0);
      late_work = r.external_work;
    }
  }
  const double rho = scene.materials.front().material.model.params().density;
  const double c = test::longitudinal_wave_speed(scene);
  const double Z = rho * c * 0.0025 * 0.0025;  // rho c_L A
  const LedgerRow r = sim.ledger().row();
  const double t = sim.time(), span = t - late_time;
  const double push = (r.boundary_impulse(0) - late_impulse) / span;
  const double power = (r.external_work - late_work) / span;
  // The onset's layer carries the wave's pressure rho c V at the overlap (h / 2) sqrt(V / c)
  // (contact/rigid_particle_contact.hpp: k delta^2 / (2 delta_s) = p A_p): the bar's end
  // follows the piston that far behind, and its impulse lags by that overlap over V.
  const double lag = 0.5 * h * std::sqrt(V / c) / V;
  BOOST_TEST_MESSAGE("rigid piston at " << V << " m/s at the particles, t = " << t << " s: impulse "
                                        << r.boundary_impulse(0) << " N s (closed " << Z * V * t
                                        << ", with the lag of " << lag << " s " << Z * V * (t - lag)
                                        << "), push over the last tenth " << push << " N (closed "
                                        << Z * V << "), power " << power << " W (" << Z * V * V
                                        << "), energy_error " << r.energy_error);
  BOOST_TEST(r.boundary_impulse(0) == Z * V * (t - lag), boost::test_tools::tolerance(0.03));
  BOOST_TEST(push == Z * V, boost::test_tools::tolerance(0.05));
  BOOST_TEST(power == Z * V * V, boost::test_tools::tolerance(0.05));
  BOOST_TEST(std::abs(r.energy_error) < 0.005);
  BOOST_TEST(worst_closure <= 1e-12 * Z * V * t_end);  // the bar's momentum: the piston's push
}

BOOST_AUTO_TEST_CASE(a_block_seeded_around_a_rigid_pin_stays_at_rest) {
  // Plane strain: an elastic 2 mm block seeded around a rigid pin of radius 0.7 mm that cuts it
  // (the pin named first keeps the shared points), all at rest. Nothing acts: it stays so.
  Json patch = {
      {"materials",
       {{"pin_al", {{"file", std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json"}}}}},
      {"objects",
       {{"a_pin",
         {{"material", "pin_al"},
          {"rigid", true},
          {"geometry",
           {{"type", "cylinder"},
            {"bottom", {0.002, 0.002, -0.5}},
            {"top", {0.002, 0.002, 0.5}},
            {"radius", 0.0007}}}}},
        {"block",
         {{"material", "elastic_al"},
          {"geometry",
           {{"type", "box"}, {"lower", {0.001, 0.001, -0.5}}, {"upper", {0.003, 0.003, 0.5}}}},
          {"velocity", {0.0, 0.0, 0.0}}}}}},
      {"grid",
       {{"geometry", "plane_strain"},
        {"lower", {0.0, 0.0}},
        {"upper", {0.004, 0.004}},
        {"cells", {16, 16}},
        {"boundary", {{"x-", "free"}, {"x+", "free"}, {"y-", "free"}, {"y+", "free"}}}}},
      {"physics", {{"contact", {{"type", "friction"}, {"mu", 0.0}}}}},
      {"time", {{"max_time", 2.0e-6}}}};
  Simulation sim(test::verification_scene("elastic_base.json", at_particles(patch)), kThreads);
  const double start = test::ledger_sink(sim.ledger(), "contact_energy");
  double kinetic = 0.0;
  while (!sim.finished()) {
    sim.step();
    kinetic = std::max(kinetic, sim.ledger().row().kinetic_energy);
  }
  BOOST_TEST_MESSAGE("block around a rigid pin at rest: contact energy at t = 0 "
                     << start << " J/m, largest kinetic energy " << kinetic << " J/m");
  // Clipped only by the block's own box, the domains around the pin overlapped it by up to a
  // quarter cell: 1522 J/m at t = 0, and 700 J/m of kinetic energy.
  BOOST_TEST(start == 0.0);
  BOOST_TEST(kinetic == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()

// Coulomb friction at the particles (contact.mu > 0: a stick spring anchored where the particle
// sticks, and a return map; contact/rigid_particle_contact.hpp). The loads are ramped over T: the
// penalty's compliant layer, undamped, rings under a sudden load, and a block that hops on it
// walks down a slope between touches (docs/verification.md).
//
// The block of sliding_block_rigid.json (2 x 4 x 2 mm, h = 0.5 mm) launched at 5 m/s along y,
// pressed by a body force ramped to 1e5 m/s^2 along -x over T = 20 us, mu = 0.25: Coulomb's law
// gives v_y = v0 - mu g (t - T / 2) (after T), a stop at t = v0 / (mu g) + T / 2 = 210 us, and
// then it stays stopped; the kinetic energy it loses is the slip's heat.
constexpr double kRamp = 2.0e-5;  // T [s]
Json ramped_body_force(double g_n, double g_t, double ramp) {
  const auto ramped = [&](double g) {
    return std::to_string(g) + "*min(t/" + std::to_string(ramp) + ",1)";
  };
  return {{"body_force", {ramped(-g_n), ramped(g_t), 0}}};
}
// The integral of a load ramped over T to its full value, per unit of it: min(t, T)^2 / (2 T) +
// max(t - T, 0).
double ramped_time(double t, double ramp) {
  return t < ramp ? t * t / (2.0 * ramp) : t - 0.5 * ramp;
}

BOOST_AUTO_TEST_CASE(a_block_sliding_on_a_rigid_floor_with_friction_follows_coulomb_and_sticks) {
  const double v0 = 5.0, g = 1.0e5, mu = 0.25, t_stop = v0 / (mu * g) + 0.5 * kRamp;
  Json block = ramped_body_force(g, 0.0, kRamp);
  block["velocity"] = {0.0, v0, 0.0};
  // The floor's own mu, contact.mu 0: the anchors must not wait for contact.mu.
  const Scene scene = test::verification_scene(
      "sliding_block_rigid.json",
      at_particles({{"objects", {{"block", block}, {"floor", {{"mu", mu}}}}},
                    {"physics", {{"contact", {{"mu", 0.0}}}}},
                    {"solver", {{"gravity", {0, 0, 0}}}}}));
  Simulation sim(scene, kThreads);
  const int id = object_index(scene, "block");
  const auto [worst_sliding, worst_stopped] = test::follow_along_y(
      sim, id, [&](double t) { return v0 - mu * g * ramped_time(t, kRamp); }, t_stop, 0.0, v0);
  const auto [lost, heat, energy_error] = test::slide_books(sim, id, v0);
  BOOST_TEST_MESSAGE("rigid floor at the particles, mu 0.25: v_y against Coulomb worst "
                     << worst_sliding << " v0 while sliding, " << worst_stopped
                     << " v0 after the stop; friction heat " << heat << " J against " << lost
                     << " J of kinetic energy lost; energy_error " << energy_error);
  BOOST_TEST(worst_sliding < 0.02);
  BOOST_TEST(worst_stopped < 0.005);
  BOOST_TEST(std::abs(heat / lost - 1.0) < 0.03);
  BOOST_TEST(std::abs(energy_error) < 0.01);
}

// The same block released at rest under a load ramped over T = 200 us to g_n = 1e5 m/s^2 into the
// floor and g_t = 0.2 g_n along it: with mu = 0.25 > g_t / g_n it sticks, its velocity at the
// ringing's scale; with mu = 0.15 it slides at a = g_t - mu g_n = 0.05 g_n once loaded, v_y =
// a (t - T / 2). Both from the same code path: only mu differs. A rate-only law (f_t capped at
// m_p |u_t| / dt) would creep at about H g_t / c0 = 0.006 m/s. The slow ramp: the compliant
// layer rings less, and a block that rings on it walks down the slope (over 50 us: 0.25 um in
// the 100 us after it, about 5 um per ms).
BOOST_AUTO_TEST_CASE(a_block_under_a_tangential_load_sticks_below_mu_g_n_and_slides_above_it) {
  const double g_n = 1.0e5, g_t = 0.2 * g_n, ramp = 2.0e-4, t_end = 4.0e-4;
  for (const double mu : {0.25, 0.15}) {
    Json block = ramped_body_force(g_n, g_t, ramp);
    block["velocity"] = {0.0, 0.0, 0.0};
    const Scene scene = test::verification_scene(
        "sliding_block_rigid.json", at_particles({{"physics", {{"contact", {{"mu", mu}}}}},
                                                  {"objects", {{"block", block}}},
                                                  {"solver", {{"gravity", {0, 0, 0}}}},
                                                  {"time", {{"max_time", t_end}}}}));
    Simulation sim(scene, kThreads);
    const int id = object_index(scene, "block");
    const double a = mu > g_t / g_n ? 0.0 : g_t - mu * g_n;
    double worst = 0.0;            // |v_y - a (t - T / 2)| [m/s] once loaded
    std::optional<double> loaded;  // the centre's y when the load is full [m]
    while (!sim.finished()) {
      sim.step();
      if (sim.time() < ramp) continue;
      const BodyMotion b = motion_of(sim.particles(), id);
      if (!loaded) loaded = b.centre(1);
      worst = std::max(worst, std::abs(b.velocity(1) - a * ramped_time(sim.time(), ramp)));
    }
    // How far the centre moved along y once loaded, against the law's distance.
    const double moved = motion_of(sim.particles(), id).centre(1) - *loaded;
    const double law = 0.5 * a * (t_end - ramp) * (t_end - ramp) + a * 0.5 * ramp * (t_end - ramp);
    const LedgerRow r = sim.ledger().row();
    const double slid = 0.05 * g_n * ramped_time(t_end, ramp);  // v_y at mu = 0.15, at the end
    BOOST_TEST_MESSAGE("block under g_t = 0.2 g_n ramped over 200 us, mu = "
                       << mu << ": worst |v_y - a (t - T/2)| " << worst << " m/s (v_y at mu 0.15 "
                       << slid << " m/s at the end), moved " << moved << " m once loaded (law "
                       << law << " m), energy_error " << r.energy_error << ", friction heat "
                       << test::ledger_sink(sim.ledger(), "friction_heat") << " J");
    BOOST_TEST(worst < 0.02 * slid);
    // Stuck, it moves far less than the rate-only law's creep (0.006 m/s over 200 us: 1.2 um);
    // sliding, the law's distance.
    if (a == 0.0)
      BOOST_TEST(std::abs(moved) < 0.1e-6);
    else
      BOOST_TEST(moved == law, boost::test_tools::tolerance(0.03));
    BOOST_TEST(std::abs(r.energy_error) < 0.01);
  }
}

// A block at rest dropped onto a rigid floor that slides under it at V = 2 m/s along y (the load
// ramped over 20 us to 1e5 m/s^2, mu 0.3): friction drags it up to the floor's speed at mu g,
// v_y = mu g (t - T / 2), reached at 77 us, and then it rides along. As in any Coulomb start,
// the slip's heat equals the kinetic energy the block gains, 1/2 M V^2, and the floor's work,
// f . V summed, is twice that. The anchors are carried with the floor.
BOOST_AUTO_TEST_CASE(a_block_dropped_on_a_sliding_rigid_floor_is_dragged_to_its_speed) {
  const double V = 2.0, g = 1.0e5, mu = 0.3;
  Json block = ramped_body_force(g, 0.0, kRamp);
  block["velocity"] = {0.0, 0.0, 0.0};
  const Scene scene = test::verification_scene(
      "sliding_block_rigid.json",
      at_particles(
          {{"physics", {{"contact", {{"mu", mu}}}}},
           {"objects",
            {{"block", block},
             {"floor",
              {{"velocity", {0.0, V, 0.0}}, {"geometry", {{"upper", {0.001, 0.008, 0.006}}}}}}}},
           {"solver", {{"gravity", {0, 0, 0}}}},
           {"time", {{"max_time", 1.5e-4}}}}));
  Simulation sim(scene, kThreads);
  const int id = object_index(scene, "block");
  const double t_lock = V / (mu * g) + 0.5 * kRamp;
  double worst_dragged = 0.0, worst_riding = 0.0;
  while (!sim.finished()) {
    sim.step();
    const double vy = motion_of(sim.particles(), id).velocity(1);
    if (sim.time() < t_lock)
      worst_dragged =
          std::max(worst_dragged, std::abs(vy - mu * g * ramped_time(sim.time(), kRamp)) / V);
    else if (sim.time() > 1.1 * t_lock)
      worst_riding = std::max(worst_riding, std::abs(vy - V) / V);
  }
  const BodyMotion b = motion_of(sim.particles(), id);
  const double gained = 0.5 * b.mass * V * V;
  const double heat = test::ledger_sink(sim.ledger(), "friction_heat");
  const LedgerRow r = sim.ledger().row();
  BOOST_TEST_MESSAGE(
      "block dragged by a rigid floor at 2 m/s, mu 0.3: v_y against mu g (t - T/2) "
      "worst "
      << worst_dragged << " V, riding " << worst_riding << " V; heat " << heat
      << " J, floor's work " << r.external_work << " J against 1/2 M V^2 = " << gained
      << " J; energy_error " << r.energy_error);
  BOOST_TEST(worst_dragged < 0.05);
  BOOST_TEST(worst_riding < 0.03);
  BOOST_TEST(heat == gained, boost::test_tools::tolerance(0.03));
  BOOST_TEST(r.external_work == 2.0 * gained, boost::test_tools::tolerance(0.03));
  BOOST_TEST(std::abs(r.energy_error) < 0.01);
}

// The disk of rolling_cylinder_rigid.json (plane strain, R = 2 mm, 8 cells per radius) on its
// rigid floor met at the particles, a load ramped over T = 20 us to 1e5 m/s^2 at 30 degrees from
// the floor's normal, mu = 0.5 > tan(30 deg) / 3: it rolls without slip at a = 2/3 g sin(30 deg)
// = g / 3, v_y = a (t - T / 2), spinning at omega_z R = v_y (the floor below it, at -x). Without
// friction it would slide at g / 2 and not turn; on a `wall` it rolls at -43 % of a
// (rolling_cylinder_test).
BOOST_AUTO_TEST_CASE(a_disk_rolls_down_a_rigid_incline_at_the_particles_without_slip) {
  const double g = 1.0e5, R = 2.0e-3, a = g / 3.0;
  const Scene scene = test::verification_scene(
      "rolling_cylinder_rigid.json",
      at_particles({{"physics", {{"contact", {{"normal", nullptr}, {"detection", nullptr}}}}},
                    {"objects",
                     {{"disk", ramped_body_force(g * std::cos(M_PI / 6.0), g * std::sin(M_PI / 6.0),
                                                 kRamp)}}},
                    {"solver", {{"gravity", {0, 0, 0}}}},
                    {"time", {{"max_time", 1.0e-4}}}}));
  Simulation sim(scene, kThreads);
  const int disk = object_index(scene, "disk");
  while (!sim.finished()) sim.step();
  const BodyMotion b = motion_of(sim.particles(), disk);
  const double t = sim.time(), rolling = a * ramped_time(t, kRamp);
  const LedgerRow r = sim.ledger().row();
  BOOST_TEST_MESSAGE("disk rolling on a rigid incline at the particles, t = "
                     << t << " s: v_y " << b.velocity(1) << " m/s (rolling " << rolling
                     << ", sliding " << 1.5 * rolling << "), omega R " << b.omega * R
                     << " m/s, energy_error " << r.energy_error << ", friction heat "
                     << test::ledger_sink(sim.ledger(), "friction_heat") << " J/m");
  BOOST_TEST(b.velocity(1) == rolling, boost::test_tools::tolerance(0.05));
  BOOST_TEST(b.omega * R == b.velocity(1), boost::test_tools::tolerance(0.05));
  BOOST_TEST(std::abs(r.energy_error) < 0.01);
}

// The penalty's damping (contact.penalty_damping, opt-in): the block of sliding_block_rigid.json
// at rest under gravity applied at once, tilted 10 degrees from the floor's normal, mu 0.3 >
// tan(10 deg) = 0.18, 300 us. Undamped, the compliant layer rings (the block off the floor for
// spells) and the stuck block walks down the slope between touches: 33 um in 500 us in a new
// user's trial. Damped at 0.3 of each particle's critical damping the layer's ringing dies out and
// the block stays where it settled; the dashpots' work on the particles' motion is booked
// (contact_damping), so the books close (booked as c u_n^2 dt from the FLIP velocity: +0.20).
BOOST_AUTO_TEST_CASE(a_damped_penalty_keeps_a_suddenly_loaded_block_stuck_on_a_slope) {
  const double g = 1.0e5, theta = 10.0 * M_PI / 180.0, t_end = 3.0e-4;
  double walked[2] = {0.0, 0.0}, late[2] = {0.0, 0.0};
  for (const double zeta : {0.0, 0.3}) {
    Json contact = {{"mu", 0.3}};
    if (zeta > 0.0) contact["penalty_damping"] = zeta;
    const Scene scene = test::verification_scene(
        "sliding_block_rigid.json",
        at_particles({{"physics", {{"contact", contact}}},
                      {"objects", {{"block", {{"velocity", {0.0, 0.0, 0.0}}}}}},
                      {"solver", {{"gravity", {-g * std::cos(theta), g * std::sin(theta), 0.0}}}},
                      {"time", {{"max_time", t_end}}}}));
    Simulation sim(scene, kThreads);
    const int id = object_index(scene, "block");
    std::optional<double> settled;  // the centre's y at t_end / 3 [m]
    double late_kinetic = 0.0, early_kinetic = 0.0;
    while (!sim.finished()) {
      sim.step();
      const BodyMotion b = motion_of(sim.particles(), id);
      if (sim.time() < t_end / 3.0) early_kinetic = std::max(early_kinetic, b.kinetic_energy);
      if (sim.time() >= t_end / 3.0 && !settled) settled = b.centre(1);
      if (sim.time() >= 2.0 * t_end / 3.0) late_kinetic = std::max(late_kinetic, b.kinetic_energy);
    }
    const double moved = motion_of(sim.particles(), id).centre(1) - *settled;
    walked[zeta > 0.0 ? 1 : 0] = moved;
    late[zeta > 0.0 ? 1 : 0] = late_kinetic;
    const LedgerRow r = sim.ledger().row();
    const double damped = zeta > 0.0 ? test::ledger_sink(sim.ledger(), "contact_damping") : 0.0;
    BOOST_TEST_MESSAGE("block on a 10-degree slope, mu 0.3, load at once, penalty_damping "
                       << zeta << ": walked " << moved << " m over the last 200 us, kinetic "
                       << early_kinetic << " J first third, " << late_kinetic
                       << " J last third; contact_damping " << damped << " J; energy_error "
                       << r.energy_error);
    BOOST_TEST(std::abs(r.energy_error) < 0.01);
    if (zeta > 0.0) BOOST_TEST(damped > 0.0);
  }
  BOOST_TEST(std::abs(walked[1]) < 0.02 * std::abs(walked[0]));  // undamped, it walks
  // Damped, what rings on is the block's own elastic ringing, below its settled strain energy
  // (M g)^2 L / (6 E A) = 1.1e-8 J; undamped, the layer's ringing grows on the slope.
  BOOST_TEST(late[1] < 0.01 * late[0]);
}
