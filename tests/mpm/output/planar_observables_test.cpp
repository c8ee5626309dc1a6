// summary.json's observables on an axisymmetric grid (docs/mpm.md#output, docs/scenes.md#2d-grids),
// where every particle is a ring about the x axis and y is its radius.
// The sphere-cylinder case01 in axisymmetry (sphere on the axis, 50 x 10 cells, crater in the
// target's face x = 15 mm) as seeded; then the face layer's particles within 6 mm of the axis are
// pushed one cell along +x (displaced: more than dx/2) and every particle is given an axial
// velocity of 100 m/s plus a radial one of 2000 y m/s (y in m).
// - mean_velocity: [100, 0, 0] per object. The rings' radial velocities cancel around each ring:
//   the revolved body's mean velocity is axial (as its momentum, which the ledger books along x
//   only). Before, the mass-weighted mean radial velocity was reported (target: 52 m/s here).
// - crater: the axis is the axis of symmetry, axis_yz = [0, 0], the rings' radius their distance
//   from it, so the width at half depth is that of the 6 mm step to within a ring width (the
//   radial cell edge), and the depth is the push, dx. Before,
//   the axis was the mean radius of the displaced rings (a circle, not a line, in the revolved
//   body): axis_yz [3.3 mm, 0] and a 4.95 mm diameter.
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"
#include "mpm/output/observables.hpp"

using namespace impact;
using namespace impact::mpm;

BOOST_AUTO_TEST_SUITE(mpm_planar_observables)

BOOST_AUTO_TEST_CASE(axisymmetric_mean_velocity_is_axial_and_the_crater_axis_is_the_axis) {
  const Json patch = test::axisymmetric_case01_patch();
  const Scene scene = test::shipped_scene("sphere_cylinder/case01.json", patch);
  BOOST_REQUIRE(scene.output.crater.has_value());
  Particles P = seed_particles(scene);
  const Observables observables(scene, P, Communicator::one_rank());
  const double dx = scene.grid.spacing()(0), face = scene.output.crater->face;
  const int target = scene.output.crater->object;
  double widest = 0.0;
  std::size_t displaced = 0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (int(P.object[p]) == target && std::abs(P.x[p](0) - face) <= dx && P.x[p](1) < 6e-3) {
      P.x[p](0) += dx;
      widest = std::max(widest, P.x[p](1));
      ++displaced;
    }
    P.v[p] = Vec3(100.0, 2000.0 * P.x[p](1), 0.0);
  }
  const Json summary = observables.summary(P);
  BOOST_TEST_MESSAGE(summary.dump(1));
  for (const auto& [name, o] : summary["objects"].items()) {
    const Json& v = o["mean_velocity [m/s]"];
    BOOST_TEST(std::abs(v[0].get<double>() - 100.0) < 1e-9, name);
    BOOST_TEST(v[1].get<double>() == 0.0, name);
    BOOST_TEST(v[2].get<double>() == 0.0, name);
  }
  const Json& crater = summary["crater"];
  BOOST_TEST(displaced > 0u);
  BOOST_TEST(crater["axis_yz [m]"][0].get<double>() == 0.0);
  BOOST_TEST(crater["axis_yz [m]"][1].get<double>() == 0.0);
  BOOST_TEST(crater["depth [m]"].get<double>() == dx, boost::test_tools::tolerance(1e-12));
  const double ring = crater["ring_width [m]"].get<double>();
  BOOST_TEST(ring == scene.grid.spacing()(1));
  // The width at half depth of a 6 mm step, seen through rings of width w: within w of it.
  const double diameter = crater["half_depth_diameter [m]"].get<double>();
  BOOST_TEST(std::abs(diameter - 12e-3) <= 2.0 * ring, diameter);
  BOOST_TEST(widest < 6e-3);
}

BOOST_AUTO_TEST_SUITE_END()
