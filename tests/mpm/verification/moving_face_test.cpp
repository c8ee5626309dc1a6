// A moving face (grid.face_velocity, docs/scenes.md#moving-faces): the x- face of
// data/scenes/verification/elastic_wave.json (a 6061 bar in uniaxial strain, elastic, c_L =
// 6118 m/s) moves into the bar at rest, a piston on an elastic half-space (the bar is 0.2 m long:
// the front reaches its end after 32.7 us, the runs stop at 20 us). Closed form (one-dimensional
// elastic wave from a boundary velocity V(t); e.g. Meyers 1994, Dynamic Behavior of Materials,
// sec. 2.2): the face carries sigma = -rho c_L V(t), so its impulse is rho c_L A int V dt, its
// work rho c_L A int V^2 dt, and the wave holds half of that as kinetic and half as strain
// energy. Measured (--log_level=message): constant V = 1 m/s, work -0.55 %, impulse -0.55 %;
// V = V0 sin(w t), work within <sin> of the closed form; energy_error 0.15 %.
// The same bar with the face still (a velocity 0 written out) runs with the bits of the scene
// without the key: a still face costs nothing.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstring>

#include "../verification_helpers.hpp"
#include "helpers/scene_refusal.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Books {
  double work = 0.0, impulse = 0.0, kinetic = 0.0, strain = 0.0, energy_error = 0.0;
  double worst_energy_error = 0.0, momentum_closure = 0.0, time = 0.0;
};

Books drive(const Json& patch) {
  Json p = {{"objects", {{"block", {{"velocity", {0.0, 0.0, 0.0}}}}}},
            {"time", {{"max_time", 2e-5}}}};
  p.merge_patch(patch);
  Simulation sim(test::verification_scene("elastic_wave.json", p));
  Books b;
  while (!sim.finished()) {
    sim.step();
    const LedgerRow r = sim.ledger().row();
    // After the first quarter: a sudden start books its first steps' velocity jump against the
    // little work done by then (78 % after one step of the constant piston, before the books'
    // scale took 1/2 M V(0)^2 of a face that starts moving; docs/mpm.md, energy_error).
    if (sim.time() > 0.25 * 2e-5)
      b.worst_energy_error = std::max(b.worst_energy_error, std::abs(r.energy_error));
    // The bar starts at rest: its momentum is what the face gave it.
    b.momentum_closure =
        std::max(b.momentum_closure, std::abs(r.momentum(0) - r.boundary_impulse(0)));
  }
  const LedgerRow r = sim.ledger().row();
  b.work = r.external_work;
  b.impulse = r.boundary_impulse(0);
  b.kinetic = r.kinetic_energy;
  b.strain = r.strain_energy;
  b.energy_error = r.energy_error;
  b.time = sim.time();
  return b;
}

// rho c_L A of the bar [kg/s].
double impedance_area() {
  const Scene s = test::verification_scene("elastic_wave.json");
  const double rho = s.materials.front().material.model.params().density;
  return rho * test::longitudinal_wave_speed(s) * 0.0025 * 0.0025;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(moving_face)

BOOST_AUTO_TEST_CASE(a_piston_at_constant_speed_does_the_work_of_the_elastic_wave) {
  const double V = 1.0;
  const Books b = drive({{"grid", {{"face_velocity", {{"x-", V}}}}}});
  const double Z = impedance_area();
  const double work = Z * V * V * b.time, impulse = Z * V * b.time;
  BOOST_TEST_MESSAGE("piston at 1 m/s, t = "
                     << b.time << " s: work " << b.work << " J (closed " << work << "), impulse "
                     << b.impulse << " N s (" << impulse << "), kinetic " << b.kinetic
                     << " J, strain " << b.strain << " J, energy_error " << b.energy_error);
  BOOST_TEST(b.work == work, boost::test_tools::tolerance(0.01));
  BOOST_TEST(b.impulse == impulse, boost::test_tools::tolerance(0.01));
  BOOST_TEST(b.kinetic == 0.5 * work, boost::test_tools::tolerance(0.03));
  BOOST_TEST(b.strain == 0.5 * work, boost::test_tools::tolerance(0.03));
  BOOST_TEST(std::abs(b.energy_error) < 0.005);
  BOOST_TEST(b.worst_energy_error < 0.02);
  BOOST_TEST(b.momentum_closure <= 1e-12 * impulse);
}

BOOST_AUTO_TEST_CASE(a_velocity_history_written_as_an_expression_of_t_books_its_work) {
  // V = V0 sin(w t), one and a half half-periods in 20 us: the face pushes, then pulls.
  const double V0 = 2.0, w = 3.0 * std::acos(-1.0) / 2e-5;
  const Books b = drive({{"constants", {{"V0", V0}, {"w", w}}},
                         {"grid", {{"face_velocity", {{"x-", "V0*sin(w*t)"}}}}}});
  const double Z = impedance_area(), t = b.time;
  const double work = Z * V0 * V0 * (t / 2.0 - std::sin(2.0 * w * t) / (4.0 * w));
  const double impulse = Z * V0 * (1.0 - std::cos(w * t)) / w;
  BOOST_TEST_MESSAGE("V0 sin(w t): work " << b.work << " J (closed " << work << "), impulse "
                                          << b.impulse << " N s (" << impulse << "), energy_error "
                                          << b.energy_error);
  BOOST_TEST(b.work == work, boost::test_tools::tolerance(0.02));
  BOOST_TEST(b.impulse == impulse, boost::test_tools::tolerance(0.02));
  BOOST_TEST(std::abs(b.energy_error) < 0.005);
  BOOST_TEST(b.worst_energy_error < 0.02);
}

BOOST_AUTO_TEST_CASE(a_still_face_written_out_runs_with_the_bits_of_the_plain_mirror) {
  const Json moving_bar = {{"objects", {{"block", {{"velocity", {-1.0, 0.0, 0.0}}}}}},
                           {"time", {{"max_time", 5e-6}}}};
  Json still = moving_bar;
  still["grid"] = {{"face_velocity", {{"x-", 0.0}}}};
  Simulation a(test::verification_scene("elastic_wave.json", moving_bar));
  Simulation b(test::verification_scene("elastic_wave.json", still));
  while (!a.finished()) a.step();
  while (!b.finished()) b.step();
  const Particles &P = a.particles(), &Q = b.particles();
  BOOST_REQUIRE(P.size() == Q.size());
  bool same = true;
  for (std::size_t p = 0; p < P.size(); ++p)
    same = same && std::memcmp(P.x[p].data(), Q.x[p].data(), sizeof(Vec3)) == 0 &&
           std::memcmp(P.v[p].data(), Q.v[p].data(), sizeof(Vec3)) == 0;
  BOOST_TEST(same);
  BOOST_TEST(b.ledger().row().external_work == 0.0);
}

BOOST_AUTO_TEST_CASE(a_face_that_travels_beyond_a_quarter_cell_is_warned_of) {
  // 100 m/s for 20 us: 2 mm, against cells of 1.25 mm.
  const Scene s = test::verification_scene(
      "elastic_wave.json",
      {{"grid", {{"face_velocity", {{"x-", 100.0}}}}}, {"time", {{"max_time", 2e-5}}}});
  bool warned = false;
  for (const std::string& w : s.warnings)
    warned =
        warned || w.find("/grid/face_velocity/x-: the face travels up to") != std::string::npos;
  BOOST_TEST(warned);
  // A ramp from rest within a quarter cell: no warning.
  const Scene quiet = test::verification_scene(
      "elastic_wave.json", {{"grid", {{"face_velocity", {{"x-", "min(t/1e-6,1)"}}}}}});
  for (const std::string& w : quiet.warnings)
    BOOST_TEST(w.find("face_velocity") == std::string::npos);
  // A start at full speed, and a face pulling its first particle row off the grid: warned.
  const Scene sudden = test::verification_scene(
      "elastic_wave.json",
      {{"grid", {{"face_velocity", {{"x-", -20.0}}}}}, {"time", {{"max_time", 2e-5}}}});
  bool starts = false, pulls = false;
  for (const std::string& w : sudden.warnings) {
    starts = starts || w.find("the face starts at -20 m/s") != std::string::npos;
    pulls = pulls || w.find("the face moves outward by up to") != std::string::npos;
  }
  BOOST_TEST(starts);
  BOOST_TEST(pulls);
}

BOOST_AUTO_TEST_CASE(faces_that_cannot_move_as_asked_are_refused_naming_the_key) {
  // The bar's scene as a document (its extends resolved), broken by `patch`.
  const auto refused = [](const Json& patch, const std::string& expected) {
    Json doc = load_scene_document(std::string(IMPACT_SOURCE_DIR) +
                                   "/data/scenes/verification/elastic_wave.json");
    doc.merge_patch(patch);
    impact::testing::check_refused(doc, {expected});
  };
  // Beside a fixed face or a wall with friction: their edge nodes would be held by both.
  refused({{"grid", {{"face_velocity", {{"x-", 1.0}}}, {"boundary", {{"y-", "fixed"}}}}}},
          "/grid/face_velocity/x-: the face y- beside it is fixed");
  refused({{"grid",
            {{"face_velocity", {{"x-", 1.0}}},
             {"boundary", {{"y-", "wall"}}},
             {"wall_friction", {{"y-", 0.5}}}}}},
          "/grid/face_velocity/x-: the face y- beside it is a wall with friction");
  // Not finite during the run, and an empty text.
  refused({{"grid", {{"face_velocity", {{"x-", "sqrt(1e-5-t)"}}}}}},
          "/grid/face_velocity/x-: not finite at t = ");
  refused({{"grid", {{"face_velocity", {{"x-", ""}}}}}},
          "/grid/face_velocity/x-: expected a number or an expression of t, got an empty string");
}

BOOST_AUTO_TEST_SUITE_END()
