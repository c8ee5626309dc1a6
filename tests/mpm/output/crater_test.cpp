// The crater measure (mpm/output/crater.hpp, docs/mpm.md#output) on face layers written here,
// whose answers follow by hand:
// - a ring profile with a bowl, a raised rim and a flat far field: the rim is the first ring
//   below the half-depth level whose outer neighbour lies lower; depth = floor - rim height,
//   diameter = twice the rim ring's mean radius;
// - the same face moved rigidly by 1 mm: the same depth and diameter (issue 52: the measure from
//   initial positions added the plate's own motion to the depth), the far field 1 mm further;
// - a face that rises to its edge (no rim): no diameter, the depth below the far field (the
//   median), and a status that says so; a rigidly translating face: no crater at all;
// - in 3D without a given axis: the axis through the bowl's lower half, the centre of a
//   symmetric bowl.
#include "mpm/output/crater.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>

using namespace impact;
using namespace impact::mpm;
namespace tt = boost::test_tools;

namespace {

constexpr double kW = 1e-3;  // ring width [m]

// An axisymmetric face: two particles per ring k, at radii (k + 1/4) w and (k + 3/4) w, both with
// u = mm[k] millimetres (+ shift metres).
struct Face {
  std::vector<double> u, y, z;
};
Face rings_of(const std::vector<double>& mm, double shift = 0.0) {
  Face f;
  for (std::size_t k = 0; k < mm.size(); ++k) {
    for (const double at : {0.25, 0.75}) {
      f.u.push_back(mm[k] * 1e-3 + shift);
      f.y.push_back((double(k) + at) * kW);
      f.z.push_back(0.0);
    }
  }
  return f;
}

// A bowl 5 mm deep, walls down to a rim 0.2 mm above the original surface at ring 5, then the far
// field 0.3 mm into the target (the plate's motion) over 13 rings: the median is 0.3 mm.
std::vector<double> bowl() {
  std::vector<double> mm = {5.0, 4.8, 4.0, 2.0, 0.5, -0.2, 0.1};
  mm.resize(20, 0.3);
  return mm;
}

Crater axisymmetric(const Face& f) {
  return crater_of(f.u, f.y, f.z, kW, std::nullopt, true);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_crater)

BOOST_AUTO_TEST_CASE(the_rim_is_the_first_low_ring_past_the_half_depth_level) {
  const Crater c = axisymmetric(rings_of(bowl()));
  BOOST_TEST_MESSAGE(c.json("target", 0.0).dump());
  BOOST_TEST(c.status == "rim found");
  BOOST_TEST(c.floor_displacement == 5e-3);
  BOOST_TEST(c.far_field_displacement == 0.3e-3);
  // The rim: ring 5 (u = -0.2 mm < 2.65 mm, and ring 6 lies lower at 0.1 mm), mean radius 5.5 mm.
  BOOST_REQUIRE(c.diameter.has_value());
  BOOST_TEST(*c.rim_radius == 5.5e-3, tt::tolerance(1e-12));
  BOOST_TEST(*c.diameter == 11e-3, tt::tolerance(1e-12));
  BOOST_TEST(c.rim_displacement == -0.2e-3, tt::tolerance(1e-12));
  BOOST_TEST(c.depth == 5.2e-3, tt::tolerance(1e-12));
  // Inside the rim: rings 0-4 and ring 5's inner particle, 11 of 40.
  BOOST_TEST(c.crater_fraction == 11.0 / 40.0);
  BOOST_TEST(c.axis_y == 0.0);
  BOOST_TEST(c.axis_z == 0.0);
}

BOOST_AUTO_TEST_CASE(a_rigid_motion_of_the_target_changes_neither_depth_nor_diameter) {
  const Crater at_rest = axisymmetric(rings_of(bowl()));
  const Crater moved = axisymmetric(rings_of(bowl(), 1e-3));
  BOOST_TEST(moved.depth == at_rest.depth, tt::tolerance(1e-12));
  BOOST_TEST(*moved.diameter == *at_rest.diameter, tt::tolerance(1e-12));
  BOOST_TEST(moved.far_field_displacement == at_rest.far_field_displacement + 1e-3,
             tt::tolerance(1e-12));
  // What the measure from initial positions reported: the floor, 6 mm, against 5.2 mm.
  BOOST_TEST(moved.floor_displacement == 6e-3, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_face_without_a_rim_has_no_diameter_and_a_depth_below_the_far_field) {
  std::vector<double> mm;
  for (int k = 0; k < 20; ++k) mm.push_back(5.0 - 0.25 * k);  // falls to the edge: no rim
  const Crater c = axisymmetric(rings_of(mm));
  BOOST_TEST_MESSAGE(c.status);
  BOOST_TEST(!c.diameter.has_value());
  BOOST_TEST(c.json("plate", 0.0).at("diameter [m]").is_null());
  BOOST_TEST(c.status.find("no rim") == 0u);
  // The median of 40 values: the mean of rings 9 and 10's, 2.75 and 2.5 mm.
  BOOST_TEST(c.far_field_displacement == 2.625e-3, tt::tolerance(1e-12));
  BOOST_TEST(c.depth == 5e-3 - 2.625e-3, tt::tolerance(1e-12));

  // A face translating rigidly (every u 0.4 mm): no crater at all.
  const Crater rigid = axisymmetric(rings_of(std::vector<double>(20, 0.4)));
  BOOST_TEST(!rigid.diameter.has_value());
  BOOST_TEST(rigid.depth == 0.0);
  BOOST_TEST(rigid.far_field_displacement == 0.4e-3, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(the_axis_of_a_3d_crater_runs_through_the_lower_half_of_its_bowl) {
  // A square lattice of 0.5 mm about (y, z) = (11.4, -3.8) mm with a cone-shaped bowl of radius
  // 4 mm, 3 mm deep: the particles below the half-depth level lie symmetrically about the centre.
  const double cy = 11.4e-3, cz = -3.8e-3;
  std::vector<double> u, y, z;
  for (int i = -40; i <= 40; ++i) {
    for (int j = -40; j <= 40; ++j) {
      const double r = 0.5e-3 * std::hypot(i, j);
      u.push_back(r < 4e-3 ? 3e-3 * (1.0 - r / 4e-3) : 0.0);
      y.push_back(cy + 0.5e-3 * i);
      z.push_back(cz + 0.5e-3 * j);
    }
  }
  const Crater c = crater_of(u, y, z, kW, std::nullopt, false);
  BOOST_TEST(c.axis_y == cy, tt::tolerance(1e-12));
  BOOST_TEST(c.axis_z == cz, tt::tolerance(1e-12));
  BOOST_TEST(c.depth == 3e-3, tt::tolerance(1e-12));  // the rim at the original surface, u = 0
  // Given, the axis is taken as it is.
  const Crater given = crater_of(u, y, z, kW, std::array<double, 2>{0.0, 0.0}, false);
  BOOST_TEST(given.axis_y == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
