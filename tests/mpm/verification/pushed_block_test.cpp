// A block pressed onto a rigid `wall` and pushed along it (issue 53's verification set; Uintah's
// friction test does the same with surface loads): the elastic block of
// data/scenes/verification/sliding_block.json (2 x 4 x 2 mm, h = 0.5 mm, uGIMP + MUSL), released
// at rest on the x- wall with mu = 0.5, under a body force with a normal part g_n = 1e5 m/s^2
// into the wall and a tangential part g_t along y. Coulomb's law for the rigid block: it slides
// with a = g_t - mu g_n when g_t > mu g_n, and sticks (a = 0) otherwise.
//   pushed   g_t = 7.5e4: a = 2.5e4 m/s^2, v_y = a t. The sudden load sets the block ringing
//            normal to the wall, and the friction at its base rocks it, so the friction per step
//            follows the ringing normal impulse; asserted: the mean v_y within 0.08 a t_end of
//            a t at every step over 100 us, and within 2 % at the end (measured 0.020 and 1.3 %).
//   held     g_t = 4e4 < mu g_n: during the first ringing periods the normal impulse of a step
//            falls below g_t / mu and the block slips a little (a continuum suddenly loaded does
//            too); then it sticks. Asserted: |v_y| below 0.05 g_t t_end at every step, and over
//            the second half no acceleration along the push (mean below +0.02 g_t) and none
//            faster against it than kinetic friction stopping the early slip, mu g_n - g_t =
//            0.25 g_t (measured 0.027 g_t t_end and -0.025 g_t).
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

double mean_vy(const Particles& P) {
  double p = 0.0, m = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    p += P.mass[i] * P.v[i](1);
    m += P.mass[i];
  }
  return p / m;
}

struct Pushed {
  double worst = 0.0;    ///< largest |v_y - law| over the run [m/s]
  double largest = 0.0;  ///< largest |v_y| [m/s]
  double v_half = 0.0, v_end = 0.0, t_half = 0.0, t_end = 0.0;
};

Pushed push(double g_t, double mu, double g_n) {
  const Json patch = {{"objects", {{"block", {{"velocity", {0.0, 0.0, 0.0}}}}}},
                      {"grid", {{"wall_friction", {{"x-", mu}}}}},
                      {"solver", {{"gravity", {-g_n, g_t, 0.0}}}},
                      {"time", {{"max_time", 1.0e-4}}}};
  Simulation sim(test::verification_scene("sliding_block.json", patch));
  const double a = std::max(0.0, g_t - mu * g_n);
  Pushed r;
  while (!sim.finished()) {
    sim.step();
    const double vy = mean_vy(sim.particles());
    r.worst = std::max(r.worst, std::abs(vy - a * sim.time()));
    r.largest = std::max(r.largest, std::abs(vy));
    if (sim.time() <= 0.5e-4) {
      r.v_half = vy;
      r.t_half = sim.time();
    }
  }
  r.v_end = mean_vy(sim.particles());
  r.t_end = sim.time();
  return r;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pushed_block)

BOOST_AUTO_TEST_CASE(pushed_beyond_friction_it_slides_at_g_t_minus_mu_g_n) {
  const double g_n = 1.0e5, g_t = 7.5e4, mu = 0.5, a = g_t - mu * g_n;
  const Pushed r = push(g_t, mu, g_n);
  BOOST_TEST_MESSAGE("pushed: v_y " << r.v_end << " m/s at " << r.t_end << " s against a t = "
                                    << a * r.t_end << " m/s; worst |v_y - a t| " << r.worst
                                    << " m/s (" << r.worst / (a * r.t_end) << " a t_end)");
  BOOST_TEST(r.worst < 0.08 * a * r.t_end);
  BOOST_TEST(std::abs(r.v_end / (a * r.t_end) - 1.0) < 0.02);
}

BOOST_AUTO_TEST_CASE(pushed_below_friction_it_sticks) {
  const double g_n = 1.0e5, g_t = 4.0e4, mu = 0.5;
  const Pushed r = push(g_t, mu, g_n);
  const double mean_a = (r.v_end - r.v_half) / (r.t_end - r.t_half);
  BOOST_TEST_MESSAGE("held: largest |v_y| " << r.largest << " m/s (" << r.largest / (g_t * r.t_end)
                                            << " g_t t_end); mean acceleration over the second "
                                               "half "
                                            << mean_a << " m/s^2 (" << mean_a / g_t << " g_t)");
  BOOST_TEST(r.largest < 0.05 * g_t * r.t_end);
  // It does not accelerate along the push, and slows no faster than kinetic friction can stop
  // its early slip (mu g_n - g_t).
  BOOST_TEST(mean_a < 0.02 * g_t);
  BOOST_TEST(mean_a > -(mu * g_n - g_t));
}

BOOST_AUTO_TEST_SUITE_END()
