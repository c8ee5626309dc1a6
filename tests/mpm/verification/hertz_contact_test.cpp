// Hertz impact (issue 53), on an axisymmetric grid (uGIMP + MUSL): data/scenes/verification/
// hertz_wall.json, a 6061 sphere (R = 10 mm, linear hypoelastic) touching the frictionless x-
// `wall` at t = 0 and moving into it at 10 m/s, and hertz_spheres.json, two such spheres.
//
// Closed form (Johnson 1985, Contact Mechanics, sec. 11.4; a sphere on a rigid flat: E* = E /
// (1 - nu^2), R* = R, m* = m): the largest approach delta_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5),
// the peak force F_max = 4/3 E* sqrt(R) delta_max^(3/2) and the contact time t_c = 2.9432
// delta_max / v (the force is elastic, so the sphere leaves at v). Here delta_max = 0.113 mm,
// F_max = 12.45 kN, t_c = 33.4 us: quasi-static (t_c is ten times 2 R / c_L).
//
// The force is measured over windows of 0.25 us and the contact lasts while it exceeds 1 % of
// its peak; Hertz's own force does so for 0.968 t_c (32.4 us), the reference of the contact-time
// errors below. The pulse's shape, impulse / (F_max t_c), is 0.544 for Hertz and 2 / pi = 0.637
// for a linear spring's half sine.
// 1. The sphere on the wall. The force is the rate of the wall's impulse, the ledger's
//    boundary_impulse_x. Measured at h = 0.25 / 0.125 mm (40 / 80 cells per radius): t_c -28 /
//    -13.5 %, F_max +23 / +0.9 %, shape 0.634 / 0.642; restitution 0.994 / 0.998;
//    |energy_error| at most 0.13 / 0.06 %. The contact time converges; the pulse does not have
//    Hertz's shape yet (it is a spring's: the discrete sphere's tip is a staircase of particle
//    domains whose bottom step, about sqrt(R h) wide, 1.1 mm at h = 0.125 mm, is as wide as the
//    Hertz contact itself, a = sqrt(R delta_max) = 1.06 mm, so the sphere meets the wall as a
//    flat punch until the approach is several cells), so the peak force near Hertz's at h / 2 is
//    a crossing, not convergence: it is only bounded. Asserted: t_c within the bounds below and
//    falling with h, F_max within 30 %, the sphere leaves elastically.
// 2. Two spheres in frictionless multi-field contact (hertz_spheres.json, the same numbers: two
//    equal spheres at +-10 m/s are one sphere on a rigid flat at 10 m/s). The force is the
//    momentum the left sphere loses. Measured at h = 0.25 mm: t_c -42 %, F_max +54 %;
//    restitution 0.989; |energy_error| <= 0.18 % (1.8 % when the strain pass re-decided contact,
//    contact/contact.hpp); total momentum 1e-14 of p0. (Against t_c, by
//    per-step differences of a velocity gauge over the left sphere, at h = 0.5 / 0.25 / 0.125
//    mm: -55 / -45 / -37 %, F_max +83 / +53 / +34 %.) The contact is too stiff because it starts
//    too early: the approach test (contact/contact.hpp) takes two bodies as touching wherever
//    their stencils share a node and they approach, up to two cells before their surfaces meet,
//    so the discrete spheres meet as blunted bodies about a cell wide. Nairn's position check
//    (the bodies' nodal centres of mass closer than about 0.8 cells along the normal) brought
//    the same gauge figures to -26 / -22 / -11 % and F_max +4 / +3 / -2 %, but with uGIMP + MUSL
//    it left a layer of tip particles rattling with locked GPa stresses (energy_error +2.6 /
//    +7.8 / +3.0 %); it has not been landed (docs/mpm.md). Asserted: bounds that only catch a
//    regression of this documented defect, momentum exchanged exactly, an elastic rebound.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <utility>
#include <vector>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// One thread: these 2D grids of a few thousand particles run 2.4 times faster on one than on two
// (the pair by separation: 15 s against 36 s on the 2-core VM, 2026-12-06; the threads' own
// bit-identity is tested elsewhere).
constexpr int kThreads = 1;

struct Impact {
  double peak_force = 0.0;    // [N]
  double contact_time = 0.0;  // [s]
  double restitution = 0.0;   // -p_x(end) / p_x(0)
  double worst_energy_error = 0.0;
  double worst_momentum = 0.0;  // the pair's total axial momentum over the left sphere's initial
  double impulse = 0.0;         // the force's whole impulse [N s]
};

// Peak force and contact time from an impulse history J(t) [N s] (the wall's impulse, or the
// momentum one sphere has lost): the force dJ/dt over windows of 0.25 us, in contact while it
// exceeds 1 % of its peak (Hertz's own force is below that for the first and last 1.6 % of t_c).
void measure_force(const std::vector<double>& t, const std::vector<double>& J, Impact& r) {
  const double window = 0.25e-6;
  std::vector<double> force_time, force;
  for (std::size_t i = 0, j = 0; i < t.size(); ++i) {
    while (j < t.size() && t[j] < t[i] + window) ++j;
    if (j == t.size()) break;
    force_time.push_back(0.5 * (t[i] + t[j]));
    force.push_back((J[j] - J[i]) / (t[j] - t[i]));
  }
  for (const double f : force) r.peak_force = std::max(r.peak_force, f);
  double first = -1.0, last = -1.0;
  for (std::size_t i = 0; i < force.size(); ++i)
    if (force[i] > 0.01 * r.peak_force) {
      if (first < 0.0) first = force_time[i];
      last = force_time[i];
    }
  r.contact_time = last - first + window;  // the windows' centres lie half a window inside
  r.impulse = J.back();
}

// The sphere of hertz_wall.json on the wall, at cells_x x cells_y cells.
Impact wall_impact(int cells_x, int cells_y) {
  const Scene scene =
      test::verification_scene("hertz_wall.json", {{"grid", {{"cells", {cells_x, cells_y}}}}});
  BOOST_REQUIRE(scene.grid.geometry == GridGeometry::axisymmetric);
  Simulation sim(scene, kThreads);
  Impact r;
  const double p0 = sim.ledger().initial_momentum()(0);
  std::vector<double> t{0.0}, J{0.0};
  while (!sim.finished()) {
    sim.step();
    const LedgerRow row = sim.ledger().row();
    t.push_back(sim.time());
    J.push_back(row.boundary_impulse(0));
    r.worst_energy_error = std::max(r.worst_energy_error, std::abs(row.energy_error));
  }
  r.restitution = -sim.ledger().row().momentum(0) / p0;
  measure_force(t, J, r);
  return r;
}

// The left sphere's axial momentum [kg m/s] (object 0 of hertz_spheres.json).
double left_momentum(const Particles& P) {
  double p = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.object[i] == 0) p += P.mass[i] * P.v[i](0);
  return p;
}

// The two spheres of hertz_spheres.json; the force is the left sphere's loss of momentum, and
// `restitution` its final velocity over its initial one.
Impact sphere_pair_impact(const Json& patch = Json::object()) {
  const Scene scene = test::verification_scene("hertz_spheres.json", patch);
  Simulation sim(scene, kThreads);
  Impact r;
  const double p0 = left_momentum(sim.particles());
  std::vector<double> t{0.0}, J{0.0};
  while (!sim.finished()) {
    sim.step();
    t.push_back(sim.time());
    J.push_back(p0 - left_momentum(sim.particles()));
    r.worst_energy_error =
        std::max(r.worst_energy_error, std::abs(sim.ledger().row().energy_error));
    r.worst_momentum = std::max(r.worst_momentum, std::abs(sim.ledger().row().momentum(0)) / p0);
  }
  r.restitution = -left_momentum(sim.particles()) / p0;
  measure_force(t, J, r);
  return r;
}

// Johnson's closed form for the sphere on a rigid flat at 10 m/s (the pair's is the same).
struct Hertz {
  double force = 0.0, time = 0.0;
  /// The time Hertz's own force exceeds 1 % of its peak (the measure's threshold): near the
  /// touch delta = v t and F / F_max = (v t / delta_max)^(3/2), below 1 % for 0.01^(2/3)
  /// delta_max / v at each end, 3.2 % of t_c in all.
  double time_above_1_percent = 0.0;
  /// The pulse's shape, impulse / (F_max t_c): 0.544 for Hertz (J = 2 m v), 2 / pi = 0.637 for a
  /// linear spring's half sine.
  double shape = 0.0;
};
Hertz hertz(const Scene& scene) {
  const auto& p = scene.materials.front().material.model.params();
  const double E = test::youngs_modulus(scene), nu = test::poissons_ratio(scene);
  const double R = 0.01, v = 10.0, pi = std::acos(-1.0);
  const double m = p.density * 4.0 / 3.0 * pi * R * R * R;
  const double E_star = E / (1.0 - nu * nu);
  const double delta = std::pow(15.0 * m * v * v / (16.0 * E_star * std::sqrt(R)), 0.4);
  Hertz h;
  h.force = 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(delta, 1.5);
  h.time = 2.9432 * delta / v;
  h.time_above_1_percent = h.time - 2.0 * std::pow(0.01, 2.0 / 3.0) * delta / v;
  h.shape = 2.0 * m * v / (h.force * h.time);
  return h;
}

// The pair's contact-time and peak-force errors against Hertz's, logged with its books.
std::pair<double, double> errors_against_hertz(const char* label, const Impact& pair,
                                               const Hertz& closed) {
  const double t_err = pair.contact_time / closed.time_above_1_percent - 1.0;
  const double f_err = pair.peak_force / closed.force - 1.0;
  BOOST_TEST_MESSAGE(label << ", h = 0.25 mm: t_c " << t_err << ", F_max " << f_err << ", e "
                           << pair.restitution << ", |energy_error| <= " << pair.worst_energy_error
                           << ", |total p_x| / p0 <= " << pair.worst_momentum);
  return {t_err, f_err};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(hertz_contact)

BOOST_AUTO_TEST_CASE(a_sphere_on_a_wall_meets_hertz_and_converges_with_the_cell_size) {
  const Hertz closed = hertz(test::verification_scene("hertz_wall.json"));
  const double F_hertz = closed.force, t_hertz = closed.time;
  BOOST_TEST(t_hertz == 3.341e-5, boost::test_tools::tolerance(0.002));  // the scene's numbers
  BOOST_TEST(F_hertz == 1.245e4, boost::test_tools::tolerance(0.002));

  const Impact coarse = wall_impact(96, 48), fine = wall_impact(192, 96);
  const double t_err_coarse = coarse.contact_time / closed.time_above_1_percent - 1.0;
  const double t_err_fine = fine.contact_time / closed.time_above_1_percent - 1.0;
  const double f_err_coarse = coarse.peak_force / F_hertz - 1.0;
  const double f_err_fine = fine.peak_force / F_hertz - 1.0;
  const auto shape = [](const Impact& r) { return r.impulse / (r.peak_force * r.contact_time); };
  BOOST_TEST_MESSAGE(
      "Hertz: t_c " << t_hertz << " s (" << closed.time_above_1_percent
                    << " s above 1 % of the peak), F_max " << F_hertz << " N, shape "
                    << closed.shape << "; h = 0.25 mm: t_c " << t_err_coarse << ", F_max "
                    << f_err_coarse << ", shape " << shape(coarse) << ", e " << coarse.restitution
                    << ", |energy_error| <= " << coarse.worst_energy_error << "; h = 0.125 mm: t_c "
                    << t_err_fine << ", F_max " << f_err_fine << ", shape " << shape(fine) << ", e "
                    << fine.restitution << ", |energy_error| <= " << fine.worst_energy_error);
  BOOST_TEST(std::abs(t_err_coarse) < 0.35);
  BOOST_TEST(std::abs(t_err_fine) < 0.2);
  BOOST_TEST(std::abs(t_err_fine) < 0.7 * std::abs(t_err_coarse));  // falling with h
  // The peak force is not converging yet (+23 % then +0.9 %: the pulse keeps a flat punch's
  // shape, 0.64 against Hertz's 0.544, while its duration grows), so only bounded.
  BOOST_TEST(std::abs(f_err_coarse) < 0.3);
  BOOST_TEST(std::abs(f_err_fine) < 0.3);
  for (const Impact& r : {coarse, fine}) {
    BOOST_TEST(r.restitution > 0.99);  // elastic: the sphere leaves at the speed it came
    BOOST_TEST(r.restitution < 1.0 + 1e-3);
    BOOST_TEST(r.worst_energy_error < 0.005);
  }
}

BOOST_AUTO_TEST_CASE(two_spheres_in_contact_meet_within_the_documented_distance_of_hertz) {
  const Hertz closed = hertz(test::verification_scene("hertz_spheres.json"));
  const Impact pair = sphere_pair_impact({{"time", {{"max_time", 3.0e-5}}}});  // ends by 20 us
  const auto [t_err, f_err] = errors_against_hertz("two spheres", pair, closed);
  BOOST_TEST(pair.worst_momentum < 1e-12);  // the contact exchanges momentum, creates none
  BOOST_TEST(pair.restitution > 0.98);
  BOOST_TEST(pair.restitution < 1.0 + 1e-3);
  BOOST_TEST(pair.worst_energy_error < 0.005);
  BOOST_TEST(std::abs(t_err) < 0.5);
  BOOST_TEST(std::abs(f_err) < 0.6);
}

// With `contact.detection = "separation"` (the bodies' gap along the fitted plane, Nairn,
// Hammerquist & Smith 2020) the two spheres start to touch where their particles' domains meet,
// as the sphere on the wall does: they meet Hertz as it does at this h (t_c -28 %, F_max +23 %
// on the wall; the pair -28 % and +23 %, and -14 % and +0.9 % at h = 0.125 mm as the wall's -13.5
// % and +0.9 %: `mpm run` of the scene with --set '{"grid":{"cells":[336,96]},...}'). The
// bounds are the wall's at this h; the approach test's -42 % and +53 % fail them. Run to 30 us:
// the pulse ends by 24 us.
BOOST_AUTO_TEST_CASE(two_spheres_meet_hertz_as_on_a_wall_when_contact_waits_for_the_particles) {
  const Hertz closed = hertz(test::verification_scene("hertz_spheres.json"));
  const Impact pair = sphere_pair_impact(
      {{"time", {{"max_time", 3.0e-5}}},
       {"physics",
        {{"contact", {{"normal", "logistic_regression"}, {"detection", "separation"}}}}}});
  const auto [t_err, f_err] = errors_against_hertz("two spheres by separation", pair, closed);
  BOOST_TEST(pair.worst_momentum < 1e-12);
  BOOST_TEST(pair.restitution > 0.99);
  BOOST_TEST(pair.restitution < 1.0 + 1e-3);
  BOOST_TEST(pair.worst_energy_error < 0.005);
  BOOST_TEST(std::abs(t_err) < 0.35);
  BOOST_TEST(std::abs(f_err) < 0.3);
}

BOOST_AUTO_TEST_SUITE_END()
