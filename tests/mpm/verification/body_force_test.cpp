// Body forces written as expressions (objects.<name>.body_force, docs/scenes.md#expressions), on
// the stress-free block of rigid_translation.json (12^3 cells, 2^3 particles a cell, free faces):
// (a) a uniform force that varies in time, b = (B sin(w t), 0, 0): every particle's velocity is
//     the explicit sum v0 + sum_n dt_n b(t^n) to 1e-12 (the force is evaluated at the start of the
//     step), within dt of the continuous v0 + B (1 - cos w t) / w, and the ledger's external work
//     is the kinetic energy gained: energy_error below 1e-12 at every step;
// (b) the expression "g" gives solver.gravity's motion and work to 1e-12 (the same force, added at
//     the particles instead of the nodes);
// (c) a force that varies over the body, b = (K (X - Xc), 0, 0), stretches it (no net impulse):
//     its work becomes kinetic and strain energy, and |energy_error| is the scheme's residual on a
//     block 4 cells wide, falling with h (at h/2 below the value at h; the same block set
//     vibrating by an initial velocity field without any force shows residuals of that size, 14 %
//     at h); the same on an axisymmetric rod pulled radially, b_r = K Y (a field of revolution).
//     Without the work booked at the particles energy_error would be -1 at every h.
// (d) An initial velocity written as an expression starts every particle at the formula's value
//     at its seed point (exactly: the same libm), and the ledger's E0 is the seed points' sum that
//     summary.json reports (mpm/scene/initial_fields.hpp).
// (e) output.exact_displacement: the translating block against its exact u = v0 t reads 0 to
//     round-off (1e-12 of the 6 mm it moved); against u = (v0 + (1, 0, 0) m/s) t it reads t m/s,
//     rms and max alike (every particle is off by the same vector).
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <utility>

#include "mpm/output/displacement_error.hpp"
#include "mpm/run/step_estimate.hpp"
#include "mpm/scene/initial_fields.hpp"

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

constexpr double kB = 2e6, kW = 3e4;  // [m/s^2], [1/s]: one period in 209 us

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_body_force)

BOOST_AUTO_TEST_CASE(a_uniform_body_force_in_time_moves_the_block_as_its_explicit_sum) {
  Json patch = {{"constants", {{"B", kB}, {"w", kW}}},
                {"objects", {{"block", {{"body_force", {"B*sin(w*t)", 0, 0}}}}}}};
  const Scene scene = test::verification_scene("rigid_translation.json", patch);
  Simulation sim(scene, 2);
  const Vec3 v0 = scene.objects[0].velocity;
  double vx = v0(0), worst_error = 0.0, worst_spread = 0.0;
  while (!sim.finished()) {
    const double t = sim.time();
    sim.step();
    vx += (sim.time() - t) * kB * std::sin(kW * t);
    for (const Vec3& v : sim.particles().v)
      worst_spread = std::max(worst_spread, std::abs(v(0) - vx) / std::abs(vx));
    worst_error = std::max(worst_error, std::abs(sim.ledger().row().energy_error));
  }
  const double t = sim.time();
  const double exact = v0(0) + kB * (1.0 - std::cos(kW * t)) / kW;
  const LedgerRow r = sim.ledger().row();
  BOOST_TEST_MESSAGE("uniform b(t): " << sim.steps() << " steps, v_x " << vx << " m/s (continuous "
                                      << exact << "), worst particle " << worst_spread
                                      << ", energy_error " << worst_error << ", external work "
                                      << r.external_work << " J");
  BOOST_TEST(worst_spread <= 1e-12);
  BOOST_TEST(std::abs(vx - exact) <= 0.01 * kB / kW);  // first order in dt, dt w ~ 0.003
  BOOST_TEST(worst_error <= 1e-12);
  BOOST_TEST(r.external_work == r.kinetic_energy - sim.ledger().initial_energy(),
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(r.external_work > 0.1 * r.kinetic_energy);  // the test books real work
}

BOOST_AUTO_TEST_CASE(an_expression_equal_to_gravity_gives_gravitys_motion_and_work) {
  const Json gravity = {{"solver", {{"gravity", {2e5, -1e5, 0.0}}}}};
  const Json body = {{"constants", {{"g", 2e5}}},
                     {"objects", {{"block", {{"body_force", {"g", "-g/2", 0}}}}}}};
  Simulation a(test::verification_scene("rigid_translation.json", gravity), 2);
  Simulation b(test::verification_scene("rigid_translation.json", body), 2);
  while (!a.finished()) a.step();
  while (!b.finished()) b.step();
  BOOST_TEST_REQUIRE(a.steps() == b.steps());
  double worst_x = 0.0, worst_v = 0.0;
  for (std::size_t p = 0; p < a.particles().size(); ++p) {
    worst_x = std::max(worst_x, (a.particles().x[p] - b.particles().x[p]).norm());
    worst_v = std::max(worst_v, (a.particles().v[p] - b.particles().v[p]).norm());
  }
  const LedgerRow ra = a.ledger().row(), rb = b.ledger().row();
  BOOST_TEST_MESSAGE("gravity against its expression: "
                     << a.steps() << " steps, |dx| " << worst_x << " m, |dv| " << worst_v
                     << " m/s, work " << ra.external_work << " / " << rb.external_work << " J");
  BOOST_TEST(worst_x <= 1e-12 * 0.06);
  BOOST_TEST(worst_v <= 1e-12 * a.particles().v[0].norm());
  BOOST_TEST(rb.external_work == ra.external_work, boost::test_tools::tolerance(1e-12));
  BOOST_TEST((rb.external_impulse - ra.external_impulse).norm() <=
             1e-12 * ra.external_impulse.norm());
}

// The largest |energy_error| of a run, and its last ledger row.
static std::pair<double, LedgerRow> run_books(const Scene& scene) {
  Simulation sim(scene, 2);
  double worst = 0.0;
  while (!sim.finished()) {
    sim.step();
    worst = std::max(worst, std::abs(sim.ledger().row().energy_error));
  }
  return {worst, sim.ledger().row()};
}

BOOST_AUTO_TEST_CASE(a_body_force_over_the_body_strains_it_and_the_books_close) {
  // 3D: the block at rest, pulled apart along x about its centre X = 0.03 m, at h and h/2.
  std::array<double, 2> worst{};
  for (const int n : {12, 24}) {
    const Json patch = {
        {"constants", {{"K", 2e8}, {"Xc", 0.03}}},
        {"grid", {{"cells", {n, n, n}}}},
        {"time", {{"max_time", 1e-4}}},
        {"objects", {{"block", {{"velocity", {0, 0, 0}}, {"body_force", {"K*(X - Xc)", 0, 0}}}}}}};
    const Scene scene = test::verification_scene("rigid_translation.json", patch);
    const auto [error, r] = run_books(scene);
    worst[n / 24] = error;
    BOOST_TEST_MESSAGE("3D block under K (X - Xc), "
                       << n << " cells: external work " << r.external_work << " J, kinetic "
                       << r.kinetic_energy << " J, strain " << r.strain_energy
                       << " J, worst energy_error " << error);
    BOOST_TEST(r.external_work > 0.0);
    BOOST_TEST(r.strain_energy > 0.1 * r.external_work);  // it strains the block
    // Odd about Xc: no net impulse, to round-off of the one-sided sum M K (L/2) t.
    const double mass = 2700.0 * 8e-6;
    BOOST_TEST(std::abs(r.external_impulse(0)) <= 1e-12 * mass * 2e8 * 0.01 * 1e-4);
  }
  BOOST_TEST(worst[0] <= 0.25);
  BOOST_TEST(worst[1] < worst[0]);  // the scheme's residual, falling with h

  // Axisymmetric: a rod on the axis pulled outwards, b_r = K Y, at h and h/2.
  std::array<double, 2> worst_axi{};
  for (const int n : {4, 8}) {
    Json rod = load_scene_document(std::string(IMPACT_SOURCE_DIR) +
                                   "/data/scenes/verification/elastic_base.json");
    rod.merge_patch({{"grid",
                      {{"geometry", "axisymmetric"},
                       {"lower", {0.0, 0.0}},
                       {"upper", {0.04, 0.01}},
                       {"cells", {4 * n, n}},
                       {"boundary", {{"x+", "free"}, {"y+", "free"}}}}},
                     {"time", {{"max_time", 1e-4}}},
                     {"constants", {{"K", 4e8}}},
                     {"objects",
                      {{"rod",
                        {{"material", "elastic_al"},
                         {"geometry",
                          {{"type", "cylinder"},
                           {"bottom", {0.01, 0.0, 0.0}},
                           {"top", {0.03, 0.0, 0.0}},
                           {"radius", 0.005}}},
                         {"body_force", {0, "K*Y", 0}},
                         {"particles_per_cell", {2, 2}}}}}}});
    const auto [error, r] = run_books(read_scene(rod, "rod.json"));
    worst_axi[n / 8] = error;
    BOOST_TEST_MESSAGE("axisymmetric rod under b_r = K Y, "
                       << n << " cells radially: external work " << r.external_work << " J, strain "
                       << r.strain_energy << " J, worst energy_error " << error);
    BOOST_TEST(r.external_work > 0.0);
    BOOST_TEST(r.strain_energy > 0.1 * r.external_work);
  }
  BOOST_TEST(worst_axi[0] <= 0.4);
  BOOST_TEST(worst_axi[1] < worst_axi[0]);
}

BOOST_AUTO_TEST_CASE(an_initial_velocity_field_starts_each_particle_at_its_value) {
  const Json patch = {
      {"constants", {{"V", 40.0}, {"L", 0.02}}},
      {"objects", {{"block", {{"velocity", {"V*sin(pi*(X - 0.02)/L)", -5.0, "V*Y/L"}}}}}}};
  const Scene scene = test::verification_scene("rigid_translation.json", patch);
  Simulation sim(scene, 2);
  const Particles& P = sim.particles();
  double worst = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Vec3& x = P.x[p];
    const Vec3 v(40.0 * std::sin(std::numbers::pi * (x(0) - 0.02) / 0.02), -5.0,
                 40.0 * x(1) / 0.02);
    worst = std::max(worst, (P.v[p] - v).norm());
  }
  const InitialFields summary = initial_fields(scene, 0);
  BOOST_TEST_MESSAGE("velocity field: " << P.size() << " particles, worst |v - formula| " << worst
                                        << " m/s, E0 " << sim.ledger().initial_energy()
                                        << " J, peak " << summary.velocity_peak.transpose());
  BOOST_TEST(worst <= 1e-13);
  BOOST_TEST(sim.ledger().initial_energy() == summary.kinetic_energy,
             boost::test_tools::tolerance(1e-12));
  // The estimates' velocity: per component the largest magnitude, its sign kept.
  BOOST_TEST(scene.objects[0].velocity(1) == -5.0);
  BOOST_TEST(summary.velocity_peak(0) > 0.9 * 40.0);
  BOOST_TEST(summary.velocity_peak(2) > 40.0 * 0.02 / 0.02 * 1.5);  // Y up to 0.04 m
  BOOST_TEST(scene.objects[0].velocity(2) == summary.velocity_peak(2));
}

BOOST_AUTO_TEST_CASE(the_exact_displacement_measures_the_particles) {
  for (const double off : {0.0, 1.0}) {
    Json patch = {{"constants", {{"off", off}}},
                  {"output", {{"exact_displacement", {"(30 + off)*t", "-20*t", "10*t"}}}}};
    const Scene scene = test::verification_scene("rigid_translation.json", patch);
    Simulation sim(scene, 2);
    DisplacementError error(scene, Communicator::one_rank());
    const std::vector<double> at_start = error.read(sim.particles(), 0.0);
    BOOST_TEST(at_start[0] == 0.0);
    BOOST_TEST(at_start[1] == 0.0);
    while (!sim.finished()) sim.step();
    const double t = sim.time();
    const std::vector<double> e = error.read(sim.particles(), t);
    BOOST_TEST_MESSAGE("exact displacement off by " << off << " m/s: rms " << e[0] << " m, max "
                                                    << e[1] << " m at t = " << t << " s");
    BOOST_TEST(DisplacementError::columns().size() == e.size());
    if (off == 0.0) {
      BOOST_TEST(e[1] <= 1e-12 * 0.006);
    } else {
      BOOST_TEST(e[0] == off * t, boost::test_tools::tolerance(1e-9));
      BOOST_TEST(e[1] == off * t, boost::test_tools::tolerance(1e-9));
    }
  }
}

// (f) What stops: a body force that turns non-finite during the run stops it at that step naming
//     the object's key, its expressions, the particle's X and t; one that pushes the step below
//     time.min_dt names the body-force step; `mpm check`'s estimate takes the body force at t = 0
//     (1e12 m/s^2 on 5 mm cells at multiplier 0.5: sqrt(0.5 x 0.005 / 1e12) = 5e-8 s).
BOOST_AUTO_TEST_CASE(a_body_force_that_breaks_stops_the_run_naming_it) {
  const auto failure_of = [](const Json& patch) -> std::string {
    Simulation sim(test::verification_scene("rigid_translation.json", patch), 1);
    try {
      while (!sim.finished()) sim.step();
    } catch (const SolverFailure& e) {
      return e.what();
    }
    return "";
  };
  const std::string nan =
      failure_of({{"objects", {{"block", {{"body_force", {"t > 1e-5 ? sqrt(-1) : 0", 0, 0}}}}}}});
  BOOST_TEST_MESSAGE(nan);
  BOOST_TEST(nan.find("/objects/block/body_force = [\"t > 1e-5 ? sqrt(-1) : 0\"") !=
             std::string::npos);
  BOOST_TEST(nan.find("not finite") != std::string::npos);
  BOOST_TEST(nan.find("at X = [") != std::string::npos);

  const std::string huge =
      failure_of({{"time", {{"min_dt", 1e-9}}},
                  {"objects", {{"block", {{"body_force", {"t > 1e-5 ? 1e20 : 0", 0, 0}}}}}}});
  BOOST_TEST_MESSAGE(huge);
  BOOST_TEST(huge.find("the body-force step") != std::string::npos);

  const Scene strong = test::verification_scene(
      "rigid_translation.json", {{"objects", {{"block", {{"body_force", {"1e12", 0, 0}}}}}}});
  const StepEstimate e = estimate_steps(strong);
  BOOST_TEST(e.gravity_limited);
  BOOST_TEST(e.dt == std::sqrt(0.5 * 0.005 / 1e12), boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
