// Uniaxial-strain elastic wave: a block moving at v0 = -1 m/s onto the symmetric x- face, lateral
// faces symmetric. A compression front leaves the wall at c_L = sqrt((K + 4 mu/3)/rho) and brings
// the material to rest. Arrival at the particles starting 50, 100 and 150 mm from the wall (40, 80,
// 120 cells): the centroid of the particle's velocity rise, t_a = (x(end) - X) / v0 (the particle
// moves at v0 until t_a and, on average, stands still after it), asserted equal to X / c_L within
// 2 % at every station (measured <= 0.1 %); the front speed between the 50 and 150 mm stations is
// c_L within 2 %. Why the centroid: the discrete front is dispersive (an Airy-function profile
// whose width grows as t^(1/3)); the first moment of Ai is zero, so the centroid of the rise is at
// c_L t, but its half-way point lags c_L t by a width that grows as t^(1/3). The half-way time
// (-1 -> -0.5 m/s) is therefore reported, not asserted: it is 3.2 / 1.9 / 1.5 % late (uGIMP/MUSL)
// at 50 / 100 / 150 mm, a lag of 0.26 / 0.32 / 0.35 us growing with distance, not a start-up
// offset (the one-third point, Ai's integral from 0, is within 0.7 %). The stress left behind the
// front, averaged over the particles 20-80 mm from the wall, is -rho c_L |v0| within 2 % (linear
// elastic jump condition).
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

void wave(const char* interpolation, const char* scheme) {
  const Scene scene =
      test::verification_scene("elastic_wave.json", test::with_solver(interpolation, scheme));
  Simulation sim(scene);
  const double c = test::longitudinal_wave_speed(scene);
  const double rho = scene.materials[0].material.model.params().density;
  const Particles& P = sim.particles();
  const std::vector<double> stations = {0.05, 0.10, 0.15};
  std::vector<std::size_t> probe;
  for (double d : stations) {
    std::size_t best = 0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      if (std::abs(P.x[p](0) - d) < std::abs(P.x[best](0) - d)) best = p;
    }
    probe.push_back(best);
  }
  const double v0 = scene.objects[0].velocity(0);
  std::vector<double> centroid(stations.size(), 0.0);
  std::vector<Vec3> x0;
  for (std::size_t q : probe) x0.push_back(P.x[q]);
  std::vector<double> arrival(stations.size(), -1.0), third(stations.size(), -1.0);
  std::vector<double> v_prev(stations.size(), -1.0);
  double t_prev = 0.0, stress_behind = 0.0;
  while (!sim.finished()) {
    sim.step();
    for (std::size_t s = 0; s < stations.size(); ++s) {
      const double v = P.v[probe[s]](0);
      if (arrival[s] < 0.0 && v > -0.5) {
        arrival[s] = t_prev + (sim.time() - t_prev) * (-0.5 - v_prev[s]) / (v - v_prev[s]);
      }
      if (third[s] < 0.0 && v > -2.0 / 3.0) {
        third[s] = t_prev + (sim.time() - t_prev) * (-2.0 / 3.0 - v_prev[s]) / (v - v_prev[s]);
      }
      v_prev[s] = v;
    }
    t_prev = sim.time();
  }
  // Behind the front (20-80 mm: passed 16-27 us ago, no reflection yet), averaged over the
  // particles there: the post-front ringing of a single particle is +-3 % (reported).
  double sum = 0.0, lo = 0.0, hi = -1e300;
  int count = 0;
  lo = 1e300;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.x[p](0) < 0.02 || P.x[p](0) > 0.08) continue;
    sum += P.state[p].stress(0, 0);
    lo = std::min(lo, P.state[p].stress(0, 0));
    hi = std::max(hi, P.state[p].stress(0, 0));
    ++count;
  }
  stress_behind = sum / count;
  BOOST_TEST_MESSAGE("stress behind the front: single particle at 50 mm "
                     << P.state[probe[0]].stress(0, 0) << " Pa, range over 20-80 mm [" << lo << ", "
                     << hi << "] Pa");
  for (std::size_t s = 0; s < stations.size(); ++s) {
    const double d = x0[s](0);
    const double exact = d / c;
    centroid[s] = (P.x[probe[s]](0) - d) / v0;
    BOOST_TEST_MESSAGE(interpolation << "/" << scheme << ": X = " << d << " m, X/c_L " << exact
                                     << " s; centroid arrival " << centroid[s] << " s ("
                                     << (centroid[s] / exact - 1.0) * 100 << " %); half-way "
                                     << arrival[s] << " s (" << (arrival[s] / exact - 1.0) * 100
                                     << " %), one-third " << third[s] << " s ("
                                     << (third[s] / exact - 1.0) * 100 << " %)");
    BOOST_TEST(std::abs(centroid[s] / exact - 1.0) < 0.02);
  }
  const double speed = (x0[2](0) - x0[0](0)) / (centroid[2] - centroid[0]);
  BOOST_TEST_MESSAGE("front speed " << speed << " m/s vs c_L " << c << " m/s");
  BOOST_TEST(std::abs(speed / c - 1.0) < 0.02);
  BOOST_TEST_MESSAGE("stress behind the front " << stress_behind << " Pa vs -rho c v0 "
                                                << -rho * c * 1.0 << " Pa");
  BOOST_TEST(std::abs(stress_behind / (-rho * c) - 1.0) < 0.02);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_elastic_wave)

BOOST_AUTO_TEST_CASE(gimp_musl_front_arrives_at_the_longitudinal_wave_speed) {
  wave("gimp", "musl");
}
BOOST_AUTO_TEST_CASE(linear_usl_front_arrives_at_the_longitudinal_wave_speed) {
  wave("linear", "usl");
}

BOOST_AUTO_TEST_SUITE_END()
