// Homogeneous elastic-plastic uniaxial-strain compression of Johnson-Cook 6061-T6. The test sets
// v_x = -rate X with the x- face symmetric (a mirror: v_x = -rate x is odd about it and is
// continued exactly into the ghost layer): a uniform stress exerts no force inside, so each
// particle keeps its velocity and the body deforms homogeneously, F_xx = 1 - rate t,
// L_xx = -rate / F_xx, until the release from the free x+ end arrives.
// Reference: an independent single-point integration calling ElasticPlastic::update with that L
// and the same step sizes (not the point driver). Asserted, for every particle the release has not
// reached, at every step: sigma_xx, sigma_yy within 0.5 % of the reference (relative to its
// |sigma_xx|) and, once the reference has yielded, the plastic strain within 0.5 %.
// "Not reached": X < length - (1.05 c_L t + 6 h). The discrete release front has a dispersive
// precursor that runs cells ahead of c_L t. Measured worst deviation (uGIMP/MUSL, stress / plastic
// strain) against the distance of the particle ahead of 1.05 c_L t: 2 h: 5.0e-3 / 1.4e-2,
// 3 h: 1.2e-3 / 4.2e-3, 4 h: 2.8e-4 / 1.2e-3, 5 h: 6.4e-5 / 3.1e-4, 6 h: 1.7e-5 / 7.8e-5,
// 7 h: 6.8e-6 / 1.9e-5, beyond 8 h flat at 3e-6 / 6e-6: the homogeneous interior follows the point
// path to 1e-5. The former 2 h margin counted the precursor as interior and read it as a 1.0-1.4 %
// plastic-strain error (docs/verification.md, MPM solver).
// Trilinear weights are checked up to the first cell crossing (afterwards the cell-crossing error
// is ~40 m/s per crossing: reported); that is before the reference yields, so only their stress is.
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"
#include "models/kinematics/deformation_gradient.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Deviation {
  double stress = 0.0, plastic_strain = 0.0;
};

Deviation compress(const char* interpolation, const char* scheme) {
  const Scene scene = test::verification_scene("uniaxial_compression.json",
                                               test::with_solver(interpolation, scheme));
  Simulation sim(scene);
  const double rate = 3000.0;  // 1/s: 1.8 % strain in 6 us, yield near 0.6 %
  Particles& P = sim.particles();
  const std::vector<Vec3> X = P.x;
  for (std::size_t p = 0; p < P.size(); ++p) P.v[p] = Vec3(-rate * X[p](0), 0, 0);
  sim.restart_ledger();
  const ElasticPlastic& model = scene.materials[0].material.model;
  PointState ref = model.initial_state(294.0);
  const double c = 1.05 * test::longitudinal_wave_speed(scene);  // margin: stiffer when compressed
  constexpr double kPrecursorCells = 6.0;  // the release front's dispersive precursor (see top)
  const double length = 0.1, h = sim.grid().spacing()(0);
  double worst = 0.0, worst_ep = 0.0, first_crossing = -1.0;
  std::size_t checked = 0, checked_plastic = 0;
  const bool linear = scene.solver.interpolation == LinearShape<>::kName;
  const auto cell = [&](const Vec3& x) { return static_cast<int>(std::floor(x(0) / h)); };
  while (!sim.finished()) {
    const double t0 = sim.time();
    sim.step();
    const double dt = sim.time() - t0;
    const Mat3 L = Vec3(-rate / ref.F(0, 0), 0, 0).asDiagonal();
    PointState next;
    BOOST_REQUIRE((
        model
            .update(ref, L, advance_deformation_gradient(ref.F, L, dt, FIntegration::forward_euler),
                    dt, next)
            .status == UpdateStatus::ok));
    ref = next;
    const double reach = c * sim.time() + kPrecursorCells * h;  // the release reaches no farther
    for (std::size_t p = 0; p < P.size() && first_crossing < 0.0; ++p) {
      if (cell(P.x[p]) != cell(X[p])) first_crossing = sim.time();
    }
    // Trilinear weights: once a particle has crossed a cell face the uniform stress no longer
    // sums to zero force (docs/verification.md, MPM solver): checked up to the first crossing only.
    if (linear && first_crossing >= 0.0) continue;
    for (std::size_t p = 0; p < P.size(); ++p) {
      if (X[p](0) > length - reach) continue;  // the wall is a mirror: no exclusion there
      ++checked;
      const Mat3& s = P.state[p].stress;
      const double scale = std::abs(ref.stress(0, 0));
      worst = std::max({worst, std::abs(s(0, 0) - ref.stress(0, 0)) / scale,
                        std::abs(s(1, 1) - ref.stress(1, 1)) / scale});
      if (ref.plastic_strain > 1e-3) {
        ++checked_plastic;
        worst_ep = std::max(worst_ep, std::abs(P.state[p].plastic_strain / ref.plastic_strain - 1));
      }
    }
  }
  BOOST_TEST_MESSAGE(interpolation
                     << "/" << scheme << ": reference sigma_xx " << ref.stress(0, 0) << " Pa, ep "
                     << ref.plastic_strain << "; worst stress deviation " << worst
                     << ", worst plastic-strain deviation " << worst_ep << " over " << checked
                     << " particle-steps (" << checked_plastic
                     << " plastic); first cell crossing at " << first_crossing << " s");
  BOOST_TEST(ref.plastic_strain > 0.005);  // the reference path did go plastic
  BOOST_TEST(checked > 0u);
  if (!linear) BOOST_TEST(checked_plastic > 1000u);  // the plastic-strain check did run
  return {worst, worst_ep};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_uniaxial_compression)

BOOST_AUTO_TEST_CASE(gimp_particles_follow_the_single_point_stress_and_plastic_strain_path) {
  for (const char* scheme : {"musl", "usl"}) {
    const Deviation d = compress("gimp", scheme);
    BOOST_TEST(d.stress < 0.005);
    BOOST_TEST(d.plastic_strain < 0.005);
  }
}

BOOST_AUTO_TEST_CASE(linear_particles_follow_it_until_the_first_cell_crossing) {
  for (const char* scheme : {"musl", "usl"}) {
    const Deviation d = compress("linear", scheme);
    BOOST_TEST(d.stress < 0.005);
  }
}

BOOST_AUTO_TEST_SUITE_END()
