// The radial breathing mode of a long solid elastic cylinder on an axisymmetric grid, against its
// closed form, at 4 resolutions. With no axial strain (the x faces symmetric) the mode is
// u_r = A J1(k r) sin(w t), k = w / c_L, and a traction-free surface r = a makes
// sigma_rr = (lambda + 2 mu) du/dr + lambda u / r vanish there:
//   x J0(x) = ((1 - 2 nu) / (1 - nu)) J1(x),  x = k a,  so the period is T = 2 pi a / (x c_L)
// (the first root, x = 2.158 for the elastic 6061-T6 of the verification scenes, nu = 0.327; u_r
// solves the radial equation of motion u'' + u'/r - u/r^2 = -k^2 u, whose regular solution is J1,
// with 2 mu / (lambda + 2 mu) = (1 - 2 nu) / (1 - nu)). The test seeds v_r = V J1(k r) through the
// particles' velocities and measures the period from the zero crossings of the mode's projection
// sum_p m_p v_r,p J1(k r_p) over 4 periods, at 4, 8, 16 and 32 cells per radius (2 x 2 particles
// per cell, MUSL, CFL 0.5). Measured period errors, GIMP: 1.7e-3, 1.8e-4, 2.7e-5, 4.5e-6 (observed
// orders 3.3, 2.7, 2.6); linear: 1.7e-3, 1.8e-4, 2.7e-5, 4.3e-6 (3.3, 2.7, 2.6). Asserted, per
// shape: the error falls from each resolution to the next, the observed order of the finest pair is
// at least 2.2 (2.6 measured, less a margin), and the error at 32 cells per radius is below 1e-5.
// Both terms of Sulsky & Schreyer (1996) eqs. 14 and 20 carry this mode: without the hoop force
// (zeroed in particles_to_grid.cpp) the run's energy grows until the energy check stops it at step
// 5, and without L_tt (zeroed in grid_to_particles.cpp) the projection no longer crosses zero 8
// times: both fail here.
#include <gsl/gsl_sf_bessel.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

constexpr double kRadius = 0.01;      // a [m]
constexpr double kPeakSpeed = 0.5;    // V [m/s]: strain ~ V / c_L ~ 1e-4, linear elasticity
constexpr double kPeriodsRun = 4.25;  // enough for 8 zero crossings

struct Elastic {
  double c_longitudinal, poisson;
};

Elastic elastic_constants(const Scene& s) {
  const auto& p = s.materials.front().material.model.params();
  const double K = p.bulk_modulus, mu = p.shear_modulus;
  return {test::longitudinal_wave_speed(s), (3.0 * K - 2.0 * mu) / (2.0 * (3.0 * K + mu))};
}

// The first positive root of f(x) = x J0(x) - ((1 - 2 nu)/(1 - nu)) J1(x), by bisection on
// [0.5, 3.8]: near 0, f ~ x (1 - beta / 2) > 0; it changes sign once before 3.8 (J0's first zero
// is 2.405, J1's 3.832).
double breathing_root(double nu) {
  const double beta = (1.0 - 2.0 * nu) / (1.0 - nu);
  const auto f = [&](double x) { return x * gsl_sf_bessel_J0(x) - beta * gsl_sf_bessel_J1(x); };
  double lo = 0.5, hi = 3.8;
  BOOST_REQUIRE(f(lo) > 0.0 && f(hi) < 0.0);
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// A slice of the cylinder one cell long along x, between symmetric x faces (no axial strain),
// `cells` cells per radius, two more cells of free space beyond r = a (y+ free).
Json breathing_scene(int cells, const char* interpolation, double max_time) {
  const double h = kRadius / cells;
  return {{"grid",
           {{"geometry", "axisymmetric"},
            {"lower", {0.0, 0.0}},
            {"upper", {h, kRadius + 2.0 * h}},
            {"cells", {1, cells + 2}},
            {"boundary", {{"x-", "symmetric"}, {"x+", "symmetric"}, {"y+", "free"}}}}},
          {"objects",
           {{"cylinder",
             {{"material", "elastic_al"},
              {"geometry",
               {{"type", "cylinder"},
                {"bottom", {0.0, 0.0, 0.0}},
                {"top", {h, 0.0, 0.0}},
                {"radius", kRadius}}},
              {"particles_per_cell", {2, 2}}}}}},
          {"solver", {{"interpolation", interpolation}, {"scheme", "musl"}}},
          {"time", {{"max_time", max_time}}}};
}

struct Breathing {
  double period = 0.0, exact = 0.0;
  double error() const { return std::abs(period / exact - 1.0); }
};

Breathing breathe(int cells, const char* interpolation) {
  const Scene probe =
      test::verification_scene("elastic_base.json", breathing_scene(cells, interpolation, 1e-6));
  const Elastic e = elastic_constants(probe);
  const double x = breathing_root(e.poisson), k = x / kRadius;
  Breathing b;
  b.exact = 2.0 * std::numbers::pi / (k * e.c_longitudinal);
  Simulation sim(test::verification_scene(
      "elastic_base.json", breathing_scene(cells, interpolation, kPeriodsRun * b.exact)));
  Particles& P = sim.particles();
  std::vector<double> weight(P.size());
  for (std::size_t p = 0; p < P.size(); ++p) {
    weight[p] = P.mass[p] * gsl_sf_bessel_J1(k * P.x[p](1));
    P.v[p] = Vec3(0.0, kPeakSpeed * gsl_sf_bessel_J1(k * P.x[p](1)), 0.0);
  }
  sim.restart_ledger();
  const auto projection = [&] {
    double q = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) q += weight[p] * P.v[p](1);
    return q;
  };
  std::vector<double> crossings;
  double t_prev = 0.0, q_prev = projection();
  while (!sim.finished()) {
    sim.step();
    const double q = projection();
    if ((q_prev > 0.0) != (q > 0.0))
      crossings.push_back(t_prev + (sim.time() - t_prev) * q_prev / (q_prev - q));
    t_prev = sim.time();
    q_prev = q;
  }
  BOOST_REQUIRE(crossings.size() >= 8u);
  b.period = 2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  BOOST_TEST_MESSAGE(interpolation << " " << cells << " cells per radius: x = " << x << ", period "
                                   << b.period << " s vs " << b.exact << " s, error " << b.error()
                                   << " (" << crossings.size() << " crossings, " << sim.steps()
                                   << " steps, energy_error " << sim.ledger().row().energy_error
                                   << ")");
  return b;
}

void check_convergence(const char* interpolation) {
  const std::vector<int> ladder = {4, 8, 16, 32};
  std::vector<double> errors;
  for (int n : ladder) errors.push_back(breathe(n, interpolation).error());
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log(errors[i - 1] / errors[i]) / std::log(2.0);
    BOOST_TEST_MESSAGE(interpolation << " observed order " << ladder[i - 1] << " -> " << ladder[i]
                                     << ": " << order);
    BOOST_TEST(errors[i] < errors[i - 1]);
  }
  const std::size_t last = errors.size() - 1;
  BOOST_TEST(std::log(errors[last - 1] / errors[last]) / std::log(2.0) >= 2.2);
  BOOST_TEST(errors[last] < 1e-5);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_axisymmetric_breathing)

BOOST_AUTO_TEST_CASE(the_root_of_the_frequency_equation_is_an_independently_computed_one) {
  // Bisection on the power series of J0 and J1 (60 terms, independent of GSL): nu = 0.25 gives
  // 2.069398, nu = 0.3 gives 2.125749.
  BOOST_TEST(std::abs(breathing_root(0.25) - 2.069398) < 1e-6);
  BOOST_TEST(std::abs(breathing_root(0.3) - 2.125749) < 1e-6);
}

BOOST_AUTO_TEST_CASE(gimp_period_converges_to_the_closed_form) {
  check_convergence("gimp");
}

BOOST_AUTO_TEST_CASE(linear_period_converges_to_the_closed_form) {
  check_convergence("linear");
}

BOOST_AUTO_TEST_SUITE_END()
