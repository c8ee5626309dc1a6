// Small solver runs for the `unit` label, so that the ASan + UBSan run (which takes `unit` only)
// exercises the whole step (P2G, grid update and faces, G2P, MUSL re-map, stress update, ledger)
// for both interpolations and both schemes: a few hundred particles, about twenty steps each.
// 1. Rigid translation at (300, -200, 100) m/s on a free grid, crossing cell faces: positions
//    exact to 1e-12 m, stress below 1e-3 Pa, energy constant to 1e-12 (the verification test does
//    the same at full length).
// 2. Elastic block (384 particles) moving at -10 m/s onto the symmetric x- face: momentum ledger
//    p - p0 - boundary impulse zero to 1e-12 of p0 at every step, finite fields, and the stress
//    the front leaves behind (mean over the particles it passed more than 2 us ago) equal to
//    -rho c_L |v0| within 5 % (measured 1.2-3.6 %: post-front ringing averaged over few particles);
//    the energy error of this impulsive start is reported (-1.6 % USL, +2.7 % MUSL after 20 steps).
#include <boost/test/unit_test.hpp>

#include "mpm/verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

Json patch(const char* interpolation, const char* scheme, Json scene) {
  scene.merge_patch(test::with_solver(interpolation, scheme));
  return scene;
}

void translate(const char* interpolation, const char* scheme) {
  const Json small = {
      {"objects",
       {{"block",
         {{"geometry", {{"lower", {0.02, 0.02, 0.02}}, {"upper", {0.035, 0.035, 0.035}}}},
          {"velocity", {300.0, -200.0, 100.0}}}}}},
      {"time", {{"max_time", 2.0e-5}}}};
  const Scene scene =
      test::verification_scene("rigid_translation.json", patch(interpolation, scheme, small));
  Simulation sim(scene);
  const std::vector<Vec3> x0 = sim.particles().x;
  const Vec3 v0 = scene.objects[0].velocity;
  const double e0 = sim.ledger().initial_energy();
  double worst_x = 0.0, worst_stress = 0.0, worst_energy = 0.0;
  while (!sim.finished()) {
    sim.step();
    const Particles& P = sim.particles();
    for (std::size_t p = 0; p < P.size(); ++p) {
      worst_x = std::max(worst_x, (P.x[p] - x0[p] - v0 * sim.time()).cwiseAbs().maxCoeff());
      worst_stress = std::max(worst_stress, P.state[p].stress.cwiseAbs().maxCoeff());
    }
    worst_energy = std::max(worst_energy, std::abs(sim.ledger().row().total_energy / e0 - 1.0));
  }
  BOOST_TEST_MESSAGE(interpolation << "/" << scheme << " translation: " << sim.particles().size()
                                   << " particles, " << sim.steps() << " steps, position "
                                   << worst_x << " m, stress " << worst_stress << " Pa, energy "
                                   << worst_energy);
  BOOST_TEST(sim.particles().size() == 216u);
  BOOST_TEST(sim.steps() >= 10);
  BOOST_TEST(worst_x < 1e-12);
  BOOST_TEST(worst_stress < 1e-3);
  BOOST_TEST(worst_energy < 1e-12);
}

void compress(const char* interpolation, const char* scheme) {
  const Json small = {
      {"objects",
       {{"block",
         {{"geometry", {{"lower", {0.0, 0.0, 0.0}}, {"upper", {0.03, 0.005, 0.005}}}},
          {"velocity", {-10.0, 0.0, 0.0}}}}}},
      {"grid", {{"upper", {0.04, 0.005, 0.005}}, {"cells", {16, 2, 2}}}},
      {"time", {{"max_time", 4.0e-6}}}};
  const Scene scene =
      test::verification_scene("elastic_wave.json", patch(interpolation, scheme, small));
  Simulation sim(scene);
  const Particles& P = sim.particles();
  const std::vector<Vec3> x0 = P.x;
  const Vec3 p0 = sim.ledger().initial_momentum();
  double worst_p = 0.0;
  bool finite = true;
  while (!sim.finished()) {
    sim.step();
    const LedgerRow r = sim.ledger().row();
    worst_p = std::max(worst_p, (r.momentum - p0 - r.boundary_impulse).norm() / p0.norm());
    for (std::size_t p = 0; p < P.size(); ++p) finite = finite && P.state[p].stress.allFinite();
  }
  const double c = test::longitudinal_wave_speed(scene);
  const double rho = scene.materials[0].material.model.params().density;
  const double passed = c * (sim.time() - 2.0e-6);  // the front passed X < this > 2 us ago
  double sum = 0.0;
  int count = 0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (x0[p](0) > passed) continue;
    sum += P.state[p].stress(0, 0);
    ++count;
  }
  const double behind = sum / count, exact = -rho * c * 10.0;
  const LedgerRow r = sim.ledger().row();
  BOOST_TEST_MESSAGE(interpolation << "/" << scheme << " compression: " << P.size()
                                   << " particles, " << sim.steps() << " steps, momentum ledger "
                                   << worst_p << ", stress behind the front " << behind << " Pa vs "
                                   << exact << " Pa, energy error " << r.energy_error);
  BOOST_TEST(P.size() == 384u);
  BOOST_TEST(sim.steps() >= 10);
  BOOST_TEST(finite);
  BOOST_TEST(worst_p < 1e-12);
  BOOST_TEST(count > 0);
  BOOST_TEST(std::abs(behind / exact - 1.0) < 0.05);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_step)

BOOST_AUTO_TEST_CASE(small_rigid_translation_is_exact) {
  for (const char* interpolation : {"linear", "gimp"})
    for (const char* scheme : {"usl", "musl"}) translate(interpolation, scheme);
}

BOOST_AUTO_TEST_CASE(small_elastic_compression_keeps_the_momentum_ledger) {
  for (const char* interpolation : {"linear", "gimp"})
    for (const char* scheme : {"usl", "musl"}) compress(interpolation, scheme);
}

BOOST_AUTO_TEST_SUITE_END()
