// seeds_a_point (mpm/scene/seed_points.hpp): looked for from the middle cell outwards, it must
// answer exactly as a count over the whole box in column order (count_seed_points > 0), for the
// boxes the reader checks (gauge regions, crater faces, the object's own bounding box), also where
// an earlier object claims the points (the recommended sphere-cylinder: the target's points inside
// the sphere are the sphere's).
#include <boost/test/unit_test.hpp>
#include <random>

#include "../verification_helpers.hpp"
#include "mpm/scene/seed_points.hpp"

using namespace impact::mpm;
using impact::Vec3;

BOOST_AUTO_TEST_SUITE(mpm_seed_points)

BOOST_AUTO_TEST_CASE(the_first_point_found_agrees_with_the_count) {
  const Scene scene = test::shipped_scene("sphere_cylinder/recommended.json");
  std::mt19937 random(52);
  const GridSpec& g = scene.grid;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int with = 0, without = 0;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const auto [lo, hi] = bounds(scene.objects[o].geometry);
    BOOST_TEST(seeds_a_point(scene, o) == (count_seed_points(scene, o, lo, hi) > 0));
    for (int n = 0; n < 300; ++n) {
      // Boxes from a point to a few cells across, anywhere in the grid and a little beyond.
      Vec3 a, b;
      for (int d = 0; d < 3; ++d) {
        const double span = g.upper(d) - g.lower(d);
        a(d) = g.lower(d) - 0.1 * span + 1.2 * span * unit(random);
        b(d) = a(d) + span * 0.2 * unit(random) * unit(random);
      }
      const bool counted = count_seed_points(scene, o, a, b) > 0;
      BOOST_TEST(seeds_a_point(scene, o, a, b) == counted);
      (counted ? with : without) += 1;
    }
  }
  // Both answers were asked for, many times.
  BOOST_TEST(with > 20);
  BOOST_TEST(without > 20);
}

// A body whose every seed point an earlier body claims gets none, whichever order the cells are
// visited in (the reader refuses such a scene: built here by hand); an empty box has none.
BOOST_AUTO_TEST_CASE(claimed_points_and_empty_boxes_are_none) {
  Scene scene = test::verification_scene("rigid_translation.json");
  SceneObject twin = scene.objects[0];  // the same block, after it: every point is the block's
  twin.name = "twin";
  scene.objects.push_back(twin);
  const auto [lo, hi] = bounds(scene.objects[1].geometry);
  BOOST_TEST(count_seed_points(scene, 0, lo, hi) == 512u);
  BOOST_TEST(count_seed_points(scene, 1, lo, hi) == 0u);
  BOOST_TEST(!seeds_a_point(scene, 1));
  BOOST_TEST(!seeds_a_point(scene, 1, lo, hi));
  BOOST_TEST(seeds_a_point(scene, 0));
  BOOST_TEST(!seeds_a_point(scene, 0, Vec3(0.05, 0.05, 0.05), Vec3(0.04, 0.06, 0.06)));
}

BOOST_AUTO_TEST_SUITE_END()
