// A union's volume counts a part its parts share once (mpm/geometry/geometry.hpp
// union_overlap_shares): against closed forms for two overlapping spheres (the lens) and two
// overlapping circles in a plane-strain section, exact for parts whose bounding boxes do not meet.
// Summed, as before, the ramp scene's base box and tilted cylinder read 11 % too much volume.
#include "mpm/geometry/geometry.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "mpm/scene/planar_form.hpp"

using namespace impact;
using namespace impact::mpm;
namespace tt = boost::test_tools;

namespace {

constexpr double pi = std::numbers::pi;

Geometry sphere(double x, double r) {
  return Geometry{Sphere{Vec3(x, 0.0, 0.0), r}};
}
Geometry unite(Geometry a, Geometry b) {
  return Geometry{Union{{std::move(a), std::move(b)}}};
}

}  // namespace

// Two spheres of radius R whose centres are d apart share a lens of volume
// pi (4R + d) (2R - d)^2 / 12. The lattice samples the second sphere's 64^3 points: 0.5 %.
BOOST_AUTO_TEST_CASE(two_overlapping_spheres_count_their_lens_once) {
  const double R = 0.01;
  for (const double d : {0.5 * R, R, 1.5 * R}) {
    const double lens = pi * (4.0 * R + d) * std::pow(2.0 * R - d, 2) / 12.0;
    const double exact = 2.0 * 4.0 / 3.0 * pi * R * R * R - lens;
    BOOST_TEST_MESSAGE("d / R = " << d / R << ": " << volume(unite(sphere(0, R), sphere(d, R)))
                                  << " against " << exact);
    BOOST_TEST(volume(unite(sphere(0, R), sphere(d, R))) == exact, tt::tolerance(5e-3));
  }
}

// Parts whose bounding boxes do not meet are not sampled: the sum, to the last bit.
BOOST_AUTO_TEST_CASE(parts_apart_are_summed_exactly) {
  const double R = 0.01;
  BOOST_TEST(volume(unite(sphere(0, R), sphere(2.5 * R, R))) == 2.0 * volume(sphere(0, R)));
}

// A box inside a box is the outer box, whichever comes first.
BOOST_AUTO_TEST_CASE(a_part_inside_another_adds_nothing) {
  const Geometry outer{Box{Vec3(0, 0, 0), Vec3(0.02, 0.01, 0.01)}};
  const Geometry inner{Box{Vec3(0.003, 0.002, 0.001), Vec3(0.011, 0.007, 0.004)}};
  BOOST_TEST(volume(unite(outer, inner)) == volume(outer));
  BOOST_TEST(volume(unite(inner, outer)) == volume(outer), tt::tolerance(5e-3));
}

// A plane-strain section: two cylinders along z whose circles (radius R, centres d apart) share
// 2 R^2 acos(d / 2R) - (d / 2) sqrt(4 R^2 - d^2).
BOOST_AUTO_TEST_CASE(two_overlapping_circles_count_their_lens_once_in_a_section) {
  const double R = 0.01, d = 0.8 * R;
  const auto rod = [&](double x) {
    return Geometry{Cylinder{Vec3(x, 0.0, 0.0), Vec3(x, 0.0, 1.0), R}};
  };
  const double lens =
      2.0 * R * R * std::acos(d / (2.0 * R)) - 0.5 * d * std::sqrt(4 * R * R - d * d);
  BOOST_TEST(section_area(unite(rod(0.0), rod(d))) == 2.0 * pi * R * R - lens, tt::tolerance(5e-3));
}
