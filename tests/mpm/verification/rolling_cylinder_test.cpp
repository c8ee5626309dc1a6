// A cylinder on an incline (issue 53): data/scenes/verification/rolling_cylinder.json, an elastic
// disk (R = 2 mm, plane strain) released at rest on the x- `wall`, gravity g = 1e5 m/s^2 at
// theta = 30 degrees from the wall's normal (g_n = g cos(theta) into the wall, g_t = g sin(theta)
// along it, +y), uGIMP + MUSL, for 200 us.
//
// Closed forms (rigid-body dynamics of a solid cylinder, I = M R^2 / 2):
// - mu >= tan(theta) / 3: it rolls without slip, a = 2/3 g sin(theta) = g / 3;
// - below that it slides and spins: a = g (sin(theta) - mu cos(theta)); mu = 0.1: 0.4134 g;
// - frictionless: a = g sin(theta) = g / 2.
// The acceleration is the centre of mass's mean one, v_y(T) / T with v_y = sum m v_y / M.
// Measured (v_y(T) / T / g): slip 0.4134 and frictionless 0.5000 at h = 0.25 mm (the Coulomb
// correction's capacity is the normal impulse, so the slide is exact); rolling (mu 0.5) 0.205 /
// 0.262 / 0.294 at h = 0.25 / 0.125 / 0.0625 mm, -38 / -21 / -12 %: first order. The rolling
// disk rings on its line contact after the sudden load (its centre's normal velocity reaches
// 0.4 m/s away from the wall at h = 0.25 mm) and the wall's catch of the nodes that arrive under
// it is inelastic (grid/wall.cpp): the energy_error reaches -5.8 / -3.0 / -2.2 % of gravity's
// work, and the torque the intermittent contact transmits is short. Asserted: the slide and the
// free slide within 0.5 %, the roll within 45 % at h and 25 % at h / 2 and falling with h (the
// h / 4 figure is a documented command, docs/verification.md).
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// The mean acceleration along the incline, v_y(T) / T, in units of g.
double mean_acceleration(double mu, int cells_x, int cells_y) {
  const Scene scene = test::verification_scene(
      "rolling_cylinder.json",
      {{"grid", {{"cells", {cells_x, cells_y}}, {"wall_friction", {{"x-", mu}}}}}});
  BOOST_REQUIRE(scene.grid.geometry == GridGeometry::plane_strain);
  Simulation sim(scene);
  while (!sim.finished()) sim.step();
  const Particles& P = sim.particles();
  double M = 0.0, p = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    M += P.mass[i];
    p += P.mass[i] * P.v[i](1);
  }
  return p / M / sim.time() / 1.0e5;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(rolling_cylinder)

BOOST_AUTO_TEST_CASE(a_cylinder_slides_down_an_incline_at_coulombs_rate) {
  const double theta = std::acos(-1.0) / 6.0, mu = 0.1;
  const double slide = mean_acceleration(mu, 18, 64);
  const double free_slide = mean_acceleration(0.0, 18, 64);
  BOOST_TEST_MESSAGE("a / g: slide " << slide << " (closed form "
                                     << std::sin(theta) - mu * std::cos(theta) << "), frictionless "
                                     << free_slide << " (0.5)");
  BOOST_TEST(slide == std::sin(theta) - mu * std::cos(theta), boost::test_tools::tolerance(0.005));
  BOOST_TEST(free_slide == std::sin(theta), boost::test_tools::tolerance(0.005));
}

BOOST_AUTO_TEST_CASE(a_cylinder_rolls_down_an_incline_converging_to_two_thirds_g_sin_theta) {
  const double roll = 2.0 / 3.0 * 0.5;
  const double coarse = mean_acceleration(0.5, 18, 64) / roll - 1.0;
  const double fine = mean_acceleration(0.5, 36, 128) / roll - 1.0;
  BOOST_TEST_MESSAGE("rolling: a / (2/3 g sin theta) - 1 = " << coarse << " at h = 0.25 mm, "
                                                             << fine << " at h = 0.125 mm");
  BOOST_TEST(std::abs(coarse) < 0.45);
  BOOST_TEST(std::abs(fine) < 0.25);
  BOOST_TEST(std::abs(fine) < 0.7 * std::abs(coarse));  // first order: measured 0.55
}

BOOST_AUTO_TEST_SUITE_END()
