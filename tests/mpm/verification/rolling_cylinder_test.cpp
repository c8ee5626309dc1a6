// A cylinder on an incline (issue 53): data/scenes/verification/rolling_cylinder.json, an elastic
// disk (R = 2 mm, plane strain) released at rest on the x- `wall`, gravity g = 1e5 m/s^2 at
// theta = 30 degrees from the wall's normal (g_n = g cos(theta) into the wall, g_t = g sin(theta)
// along it, +y), uGIMP + MUSL, for T = 200 us.
//
// Closed forms (rigid-body dynamics of a solid cylinder, I = M R^2 / 2):
// - mu >= tan(theta) / 3: it rolls without slip, a = 2/3 g sin(theta) = g / 3, omega R = v;
// - below that it slides and spins: a = g (sin(theta) - mu cos(theta)); mu = 0.1: 0.4134 g;
// - frictionless: a = g sin(theta) = g / 2.
// Measures: the centre of mass's acceleration over the second half, (v_y(T) - v_y(T/2)) / (T/2),
// v_y = sum m v_y / M (the sudden load's start-up is over by then); the rolling ratio omega R / v_y
// at T, omega = (angular momentum about the centre of mass) / (sum m r^2); the share of steps in
// which the wall's impulse grows (the disk touches the wall).
// Measured at h = 0.25 / 0.125 mm (8 / 16 cells per radius):
// - slide 0.4134 g and frictionless 0.5000 g: the Coulomb correction's capacity is mu times the
//   normal impulse whatever the contact's quality, so this checks the books of the slide, exact;
// - roll (mu 0.5): acceleration -43 / -11 % over the second half, omega R / v 1.05 / 0.89, the
//   wall's impulse growing in 30 / 33 % of the steps. (Before the wall's re-map kept the step's
//   v* in stick only, grid/wall.cpp: -30 / -11 %, omega R / v 0.79 / 0.88; at h the disk now
//   grips more and spins a little faster than it rolls, at h/2 nothing moved.) The disk does not
//   roll cleanly: released stress-free under a sudden load, it rings on its line contact, hops (off
//   the wall for spells up to 16 us) and slips forward between the touches; the wall's catch of the
//   nodes that arrive under it is inelastic (grid/wall.cpp): energy_error -13 / -4.0 % of gravity's
//   work. The acceleration's error falls with h.
// Asserted: the slides within 0.5 %; the roll's acceleration within 45 % at h and 20 % at h/2,
// falling with h (0.7-fold or less); omega R / v in (0.7, 1.1) at h and (0.8, 1.05) at h/2.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Descent {
  double acceleration = 0.0;  ///< over the second half, in units of g
  double rolling = 0.0;       ///< omega R / v_y at the end
  double touching = 0.0;      ///< share of the steps in which the wall's impulse grew
  double energy_error = 0.0;  ///< energy_error at the end (over gravity's work, all that entered)
};

// Over the particles of object `disk` (-1: all of them; a rigid floor's are not the disk's).
double mean_velocity_y(const Particles& P, int disk = -1) {
  double M = 0.0, p = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (disk >= 0 && P.object[i] != disk) continue;
    M += P.mass[i];
    p += P.mass[i] * P.v[i](1);
  }
  return p / M;
}

// omega R / v_y: the spin about the centre of mass (the x-y plane) against the centre's speed.
double rolling_ratio(const Particles& P, double R, int disk = -1) {
  double M = 0.0;
  Vec3 c = Vec3::Zero(), v = Vec3::Zero();
  const auto skip = [&](std::size_t i) { return disk >= 0 && P.object[i] != disk; };
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (skip(i)) continue;
    M += P.mass[i];
    c += P.mass[i] * P.x[i];
    v += P.mass[i] * P.v[i];
  }
  c /= M;
  v /= M;
  double L = 0.0, I = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (skip(i)) continue;
    const Vec3 r = P.x[i] - c, u = P.v[i] - v;
    L += P.mass[i] * (r(0) * u(1) - r(1) * u(0));
    I += P.mass[i] * (r(0) * r(0) + r(1) * r(1));
  }
  // Rolling along +y on the x- wall (contact point at r = (-R, 0)): v + omega x r = 0 there, so
  // omega_z = v_y / R.
  return (L / I) * R / v(1);
}

Descent descend(double mu, int cells_x, int cells_y) {
  const Scene scene = test::verification_scene(
      "rolling_cylinder.json",
      {{"grid", {{"cells", {cells_x, cells_y}}, {"wall_friction", {{"x-", mu}}}}}});
  BOOST_REQUIRE(scene.grid.geometry == GridGeometry::plane_strain);
  Simulation sim(scene);
  const double T = scene.time.max_time, g = 1.0e5;
  double v_half = 0.0, t_half = -1.0, impulse = 0.0;
  long steps = 0, touching = 0;
  while (!sim.finished()) {
    sim.step();
    ++steps;
    const double J = sim.ledger().row().boundary_impulse(0);
    if (J > impulse + 1e-12 * std::abs(J)) ++touching;
    impulse = J;
    if (t_half < 0.0 && sim.time() >= 0.5 * T) {
      t_half = sim.time();
      v_half = mean_velocity_y(sim.particles());
    }
  }
  Descent d;
  d.acceleration = (mean_velocity_y(sim.particles()) - v_half) / (sim.time() - t_half) / g;
  d.rolling = rolling_ratio(sim.particles(), 0.002);
  d.touching = double(touching) / double(steps);
  d.energy_error = sim.ledger().row().energy_error;  // over the energy that entered: gravity's work
  return d;
}

// The disk on the rigid floor of rolling_cylinder_rigid.json (contact by separation), on one
// thread (a small 2D grid: faster than two): the acceleration over the second half / g and
// omega R / v at the end.
Descent roll_on_rigid_floor(const Json& patch = Json::object()) {
  const Scene scene = test::verification_scene("rolling_cylinder_rigid.json", patch);
  Simulation sim(scene, 1);
  int disk = 0;
  while (scene.objects[std::size_t(disk)].name != "disk") ++disk;
  const double T = scene.time.max_time, g = 1.0e5;
  double v_half = 0.0, t_half = -1.0;
  while (!sim.finished()) {
    sim.step();
    if (t_half < 0.0 && sim.time() >= 0.5 * T) {
      t_half = sim.time();
      v_half = mean_velocity_y(sim.particles(), disk);
    }
  }
  Descent d;
  d.acceleration = (mean_velocity_y(sim.particles(), disk) - v_half) / (sim.time() - t_half) / g;
  d.rolling = rolling_ratio(sim.particles(), 0.002, disk);
  d.energy_error = sim.ledger().row().energy_error;
  return d;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(rolling_cylinder)

BOOST_AUTO_TEST_CASE(a_cylinder_slides_down_an_incline_at_coulombs_rate) {
  const double theta = std::acos(-1.0) / 6.0, mu = 0.1;
  const double slide = descend(mu, 18, 64).acceleration;
  const double free_slide = descend(0.0, 18, 64).acceleration;
  BOOST_TEST_MESSAGE("a / g: slide " << slide << " (closed form "
                                     << std::sin(theta) - mu * std::cos(theta) << "), frictionless "
                                     << free_slide << " (0.5)");
  BOOST_TEST(slide == std::sin(theta) - mu * std::cos(theta), boost::test_tools::tolerance(0.005));
  BOOST_TEST(free_slide == std::sin(theta), boost::test_tools::tolerance(0.005));
}

BOOST_AUTO_TEST_CASE(a_cylinder_on_an_incline_converges_to_rolling_without_slip) {
  const double roll = 2.0 / 3.0 * 0.5;
  const Descent coarse = descend(0.5, 18, 64), fine = descend(0.5, 36, 128);
  const double a_coarse = coarse.acceleration / roll - 1.0;
  const double a_fine = fine.acceleration / roll - 1.0;
  BOOST_TEST_MESSAGE("rolling, h = 0.25 / 0.125 mm: a / (2/3 g sin theta) - 1 = "
                     << a_coarse << " / " << a_fine << "; omega R / v " << coarse.rolling << " / "
                     << fine.rolling << "; touching " << coarse.touching << " / " << fine.touching
                     << " of the steps; energy_error / gravity's work " << coarse.energy_error
                     << " / " << fine.energy_error);
  BOOST_TEST(std::abs(a_coarse) < 0.45);
  BOOST_TEST(std::abs(a_fine) < 0.20);
  BOOST_TEST(std::abs(a_fine) < 0.7 * std::abs(a_coarse));
  BOOST_TEST(coarse.rolling > 0.7);
  BOOST_TEST(coarse.rolling < 1.1);
  BOOST_TEST(fine.rolling > 0.8);
  BOOST_TEST(fine.rolling < 1.05);
}

BOOST_AUTO_TEST_CASE(a_cylinder_rolls_on_a_rigid_floor_met_by_separation) {
  // A rigid floor in place of the wall (docs/scenes.md#rigid-objects), contact by separation:
  // -26 % at h, -9.8 % at h/2 (`mpm run data/scenes/verification/rolling_cylinder_rigid.json`,
  // and with --set '{"grid":{"cells":[40,128]}}'), against the wall's -43 / -11 %. By approach
  // the disk sticks on a patch up to two cells wide and hardly rolls: -81 / -82 %.
  const double roll = 2.0 / 3.0 * 0.5;
  const Descent d = roll_on_rigid_floor();
  const double a = d.acceleration / roll - 1.0;
  BOOST_TEST_MESSAGE("rolling on a rigid floor, h = 0.25 mm: a / (2/3 g sin theta) - 1 = "
                     << a << ", omega R / v " << d.rolling << ", energy_error " << d.energy_error);
  BOOST_TEST(std::abs(a) < 0.35);
  BOOST_TEST(d.rolling > 0.7);
  BOOST_TEST(d.rolling < 1.1);
  BOOST_TEST(std::abs(d.energy_error) < 0.02);
}

BOOST_AUTO_TEST_SUITE_END()
