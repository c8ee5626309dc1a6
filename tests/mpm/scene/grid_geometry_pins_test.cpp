// What the grid geometry decides, pinned bit for bit (docs/scenes.md#2d-grids, docs/mpm.md):
// tests that no other test makes exact, written out as formulas here so that moving the
// geometry's terms into one catalogue (docs/notes/grid_geometry_plan.md) cannot change a bit.
// - the light-node rule (kLightNodeMassFraction, step/step.hpp): 3D and plane strain take the
//   lightest particle; axisymmetric the lightest mass per unit radius at the innermost radius;
// - a seeded particle's volume: its cell share, times 2 pi r on the axisymmetric grid;
// - the revolved body's mean velocity has no radial part, and that part is +0, not -0;
// - the memory estimate's particle count: the seeded section's area (2D) or the body's volume.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "../verification_helpers.hpp"
#include "mpm/output/observables.hpp"
#include "mpm/run/memory.hpp"
#include "mpm/step/step.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

const char* const kScenes[] = {"verification/two_spheres.json", "taylor/h8_axisymmetric.json",
                               "verification/rolling_cylinder.json"};

double cell_share(const Scene& s, const SceneObject& o) {
  const auto& ppc = o.particles_per_cell;
  return s.grid.spacing().prod() / (ppc[0] * ppc[1] * ppc[2]);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_grid_geometry_pins)

BOOST_AUTO_TEST_CASE(each_geometry_is_the_one_its_scene_names) {
  BOOST_TEST(int(test::shipped_scene(kScenes[0]).grid.geometry) == int(GridGeometry::three_d));
  BOOST_TEST(int(test::shipped_scene(kScenes[1]).grid.geometry) == int(GridGeometry::axisymmetric));
  BOOST_TEST(int(test::shipped_scene(kScenes[2]).grid.geometry) == int(GridGeometry::plane_strain));
}

BOOST_AUTO_TEST_CASE(the_light_node_mass_and_radius_follow_the_geometry) {
  for (const char* path : kScenes) {
    const Scene scene = test::shipped_scene(path);
    const Simulation sim(scene, 1);
    const Particles P = seed_particles(scene);
    BOOST_REQUIRE(P.size() > 0u);
    double light_mass = 0.0, light_radius = 0.0;
    if (scene.grid.geometry == GridGeometry::axisymmetric) {
      double per_radius = std::numeric_limits<double>::infinity();
      double innermost = per_radius;
      for (std::size_t p = 0; p < P.size(); ++p) {
        per_radius = std::min(per_radius, P.mass[p] / P.x[p](1));
        innermost = std::min(innermost, P.x[p](1));
      }
      light_radius = innermost;
      light_mass = kLightNodeMassFraction * (per_radius * innermost);
    } else {
      double lightest = std::numeric_limits<double>::infinity();
      for (const double m : P.mass) lightest = std::min(lightest, m);
      light_mass = kLightNodeMassFraction * lightest;
    }
    BOOST_TEST(sim.grid().settings().light_mass == light_mass, path);
    BOOST_TEST(sim.grid().settings().light_radius == light_radius, path);
    BOOST_TEST(light_mass > 0.0, path);
  }
}

BOOST_AUTO_TEST_CASE(a_particle_is_its_cell_share_or_the_ring_it_sweeps) {
  for (const char* path : kScenes) {
    const Scene scene = test::shipped_scene(path);
    const Particles P = seed_particles(scene);
    const bool ring = scene.grid.geometry == GridGeometry::axisymmetric;
    std::size_t wrong = 0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      const double share = cell_share(scene, scene.objects[P.object[p]]);
      const double v0 = ring ? 2.0 * std::numbers::pi * P.x[p](1) * share : share;
      if (P.volume0[p] != v0 || P.volume[p] != v0) ++wrong;
    }
    BOOST_TEST(wrong == 0u, path);
  }
}

BOOST_AUTO_TEST_CASE(the_revolved_bodys_mean_velocity_is_axial_with_a_positive_zero) {
  const Scene scene = test::shipped_scene(kScenes[1]);
  Particles P = seed_particles(scene);
  for (Vec3& v : P.v) v = Vec3(-50.0, -300.0, -7.0);  // radial and hoop parts cancel on rings
  const Json summary = Observables(scene, P, Communicator::one_rank()).summary(P);
  for (const auto& [name, o] : summary["objects"].items()) {
    const Json& v = o["mean_velocity [m/s]"];
    BOOST_TEST(v[0].get<double>() == -50.0, boost::test_tools::tolerance(1e-12));
    for (int d = 1; d < 3; ++d) {
      BOOST_TEST(v[d].get<double>() == 0.0, name);
      BOOST_TEST(!std::signbit(v[d].get<double>()), name);
    }
  }
  // On the plane-strain grid every component is physical.
  const Scene flat = test::shipped_scene(kScenes[2]);
  Particles Q = seed_particles(flat);
  for (Vec3& v : Q.v) v = Vec3(-50.0, -300.0, 0.0);
  const Json s2 = Observables(flat, Q, Communicator::one_rank()).summary(Q);
  for (const auto& [name, o] : s2["objects"].items())
    BOOST_TEST(o["mean_velocity [m/s]"][1].get<double>() == -300.0,
               boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(the_particle_estimate_counts_the_seeded_section_or_the_volume) {
  // The body of each scene lies inside its grid: the estimate is the formula below.
  for (const char* path : kScenes) {
    const Scene s = test::shipped_scene(path);
    const Vec3 h = s.grid.spacing();
    double n = 0.0;
    for (const SceneObject& o : s.objects) {
      const auto& ppc = o.particles_per_cell;
      const auto [lo, hi] = bounds(o.geometry);
      const Vec3 extent = (hi.cwiseMin(s.grid.upper) - lo.cwiseMax(s.grid.lower)).cwiseMax(0.0);
      if (s.grid.geometry == GridGeometry::three_d) {
        n += std::ceil(std::min(volume(o.geometry), extent.prod()) / h.prod() * ppc[0] * ppc[1] *
                       ppc[2]);
      } else {
        // Both 2D scenes hold one cylinder: along the axis x (its meridian half-section, length
        // times radius) or along z (its section, pi r^2).
        const auto& c = std::get<Cylinder>(o.geometry.shape);
        const double area = s.grid.geometry == GridGeometry::axisymmetric
                                ? (c.top - c.bottom).norm() * c.radius
                                : std::numbers::pi * c.radius * c.radius;
        n += std::ceil(std::min(area, extent(0) * extent(1)) / (h(0) * h(1)) * ppc[0] * ppc[1]);
      }
    }
    BOOST_TEST(estimated_particle_count(s) == n, path);
    // ... and close to what is seeded (the estimate is the section, not its staircase).
    const double seeded = double(seed_particles(s).size());
    BOOST_TEST(std::abs(n - seeded) <= 0.15 * seeded, path << ": " << n << " vs " << seeded);
  }
}

BOOST_AUTO_TEST_SUITE_END()
