// The signed distance to a shape's surface and its outward normal (mpm/geometry/
// surface_distance.hpp), what contact reads as a rigid object's own surface: against closed forms
// for each shape, and for every shape the property that defines them, x - d n lies on the surface
// (distance zero there to 1e-12 of the shape's size) at points all around it.
#include "mpm/geometry/surface_distance.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <random>

using namespace impact;
using namespace impact::mpm;
namespace tt = boost::test_tools;

namespace {

// True where a and b agree to `tol` in every component.
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  return (a - b).cwiseAbs().maxCoeff() <= tol;
}

// Points all around g's bounding box (twice its size): x - d n must lie on the surface and the
// sign of d must agree with inside() (away from the surface, where round-off decides).
// `outside_only`: the projection at the points outside only (a union's parts, deep in a joint).
void check_projection(const Geometry& g, const char* what, bool outside_only = false) {
  const bool prism_z = false;
  const auto [lo, hi] = bounds(g);
  const Vec3 mid = 0.5 * (lo + hi), half = hi - lo;
  const double size = half.maxCoeff();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0, failed = 0;
  for (int k = 0; k < 2000; ++k) {
    Vec3 x = mid + Vec3(u(rng) * half(0), u(rng) * half(1), u(rng) * half(2));
    const SurfaceDistance s = surface_distance(g, x, prism_z);
    if (s.outward.squaredNorm() == 0.0) continue;  // no direction defined there
    ++checked;
    const double on = outside_only && s.distance < 0.0
                          ? 0.0
                          : surface_distance(g, x - s.distance * s.outward, prism_z).distance;
    const bool sign_agrees = std::abs(s.distance) < 1e-9 * size || (s.distance < 0) == inside(g, x);
    const bool unit = std::abs(s.outward.norm() - 1.0) < 1e-12;
    if (std::abs(on) > 1e-12 * size || !sign_agrees || !unit) {
      if (failed++ < 3)
        BOOST_TEST_MESSAGE(what << ": x = " << x.transpose() << " d = " << s.distance
                                << " n = " << s.outward.transpose() << " -> " << on);
    }
  }
  BOOST_TEST_MESSAGE(what << ": " << checked << " points, " << failed << " off the surface");
  BOOST_TEST(checked > 1500);
  BOOST_TEST(failed == 0);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(surface_distance_suite)

BOOST_AUTO_TEST_CASE(a_box_gives_its_nearest_face_edge_or_corner) {
  const Geometry box{Box{Vec3(0, 0, 0), Vec3(2, 1, 4)}};
  // Above the top face, beside an edge (the diagonal), inside near the top.
  SurfaceDistance s = surface_distance(box, Vec3(1, 1.5, 2));
  BOOST_TEST(s.distance == 0.5, tt::tolerance(1e-14));
  BOOST_TEST(near(s.outward, Vec3(0, 1, 0)));
  s = surface_distance(box, Vec3(3, 2, 2));
  BOOST_TEST(s.distance == std::sqrt(2.0), tt::tolerance(1e-14));
  BOOST_TEST(near(s.outward, Vec3(1, 1, 0) / std::sqrt(2.0)));
  s = surface_distance(box, Vec3(1, 0.9, 2));
  BOOST_TEST(s.distance == -0.1, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, Vec3(0, 1, 0)));
  // On an edge the two faces share the normal; midway through the slab no direction is defined.
  s = surface_distance(box, Vec3(2, 1, 2));
  BOOST_TEST(near(s.outward, Vec3(1, 1, 0) / std::sqrt(2.0)));
  s = surface_distance(box, Vec3(1, 0.5, 2));
  BOOST_TEST(s.distance == -0.5, tt::tolerance(1e-14));
  BOOST_TEST(near(s.outward, Vec3::Zero()));
  // A prism along z: near its z face the nearest face is still a side.
  s = surface_distance(box, Vec3(1, 0.8, 3.99), true);
  BOOST_TEST(s.distance == -0.2, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, Vec3(0, 1, 0)));
  check_projection(box, "box");
}

BOOST_AUTO_TEST_CASE(a_sphere_gives_its_radius) {
  const Geometry ball{Sphere{Vec3(1, 2, 3), 0.5}};
  const SurfaceDistance s = surface_distance(ball, Vec3(1, 2, 3) + 0.2 * Vec3(0.6, 0.8, 0));
  BOOST_TEST(s.distance == -0.3, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, Vec3(0.6, 0.8, 0)));
  BOOST_TEST(near(surface_distance(ball, Vec3(1, 2, 3)).outward, Vec3::Zero()));
  check_projection(ball, "sphere");
}

// The ramp of data/scenes/verification/ramp.json: a cylinder whose axis is tilted 20 degrees from
// x; above its end face the normal is the axis, beside its side the radial direction.
BOOST_AUTO_TEST_CASE(a_tilted_cylinder_gives_its_end_face_and_its_side) {
  const double a = 20.0 * std::numbers::pi / 180.0;
  const Vec3 e(std::cos(a), std::sin(a), 0.0), side(-std::sin(a), std::cos(a), 0.0);
  const Vec3 bottom(0, 0, 0), top = 2.0 * e;
  const Geometry cylinder{Cylinder{bottom, top, 1.0}};
  SurfaceDistance s = surface_distance(cylinder, top + 0.3 * side + 0.1 * e);
  BOOST_TEST(s.distance == 0.1, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, e));
  s = surface_distance(cylinder, top + 0.3 * side - 0.05 * e);  // just inside the end face
  BOOST_TEST(s.distance == -0.05, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, e));
  s = surface_distance(cylinder, 1.0 * e + 1.2 * side);
  BOOST_TEST(s.distance == 0.2, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, side));
  check_projection(cylinder, "tilted cylinder");
  // Along z as a plane-strain prism: a disk, whatever z.
  const Geometry rod{Cylinder{Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0}};
  s = surface_distance(rod, Vec3(0.5, 0, 0.99), true);
  BOOST_TEST(s.distance == -0.5, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, Vec3(1, 0, 0)));
}

// A tube of outer radius 1, wall 0.25, capped 0.5 thick at its bottom: in the bore the nearest
// surface is the inner wall or the cap's inner face; in the wall the nearer of the two walls.
BOOST_AUTO_TEST_CASE(a_hollow_cylinder_gives_its_walls_and_its_cap) {
  const Geometry tube{HollowCylinder{Vec3(0, 0, 0), Vec3(4, 0, 0), 1.0, 0.25, 0.5}};
  SurfaceDistance s = surface_distance(tube, Vec3(2, 0.6, 0));  // in the bore
  BOOST_TEST(s.distance == 0.15, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, Vec3(0, -1, 0)));
  s = surface_distance(tube, Vec3(0.6, 0.1, 0));  // in the bore, above the cap
  BOOST_TEST(s.distance == 0.1, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, Vec3(1, 0, 0)));
  s = surface_distance(tube, Vec3(2, 0, 0.8));  // in the wall, nearer the inner face
  BOOST_TEST(s.distance == -0.05, tt::tolerance(1e-12));
  BOOST_TEST(near(s.outward, Vec3(0, 0, -1)));
  check_projection(tube, "hollow cylinder", true);
}

// Outside a union the nearest part's surface; the ramp scene's base box and tilted cylinder.
BOOST_AUTO_TEST_CASE(a_union_gives_its_nearest_part) {
  const Geometry ramp{
      Union{{Geometry{Box{Vec3(0.0, 0.0005, 0.0), Vec3(0.002, 0.0115, 0.006)}},
             Geometry{Cylinder{Vec3(0.00121107582724932, 0.00480292949836016, 0.003),
                               Vec3(0.0045, 0.006, 0.003), 0.003}}}}};
  const double a = 20.0 * std::numbers::pi / 180.0;
  const Vec3 e(std::cos(a), std::sin(a), 0.0);
  const SurfaceDistance s = surface_distance(ramp, Vec3(0.0045, 0.006, 0.003) + 1e-4 * e);
  BOOST_TEST(s.distance == 1e-4, tt::tolerance(1e-9));
  BOOST_TEST(near(s.outward, e));
  check_projection(ramp, "the ramp's union", true);
  // A corner of two rigid boxes (a floor and a wall): on its bisector both faces are as near,
  // and the normal is their mean, as at a box's edge.
  const Geometry corner{Union{
      {Geometry{Box{Vec3(0, 0, 0), Vec3(4, 1, 4)}}, Geometry{Box{Vec3(0, 0, 0), Vec3(1, 4, 4)}}}}};
  const SurfaceDistance c = surface_distance(corner, Vec3(1.5, 1.5, 2));
  BOOST_TEST(c.distance == 0.5, tt::tolerance(1e-12));
  BOOST_TEST(near(c.outward, Vec3(1, 1, 0) / std::sqrt(2.0)));
  BOOST_TEST(near(surface_distance(corner, Vec3(1.5, 1.2, 2)).outward, Vec3(0, 1, 0)));
  // Two boxes that touch along x = 1: their shared face is no surface. Above the joint the
  // surface is the top; inside, a face another part buries does not serve (beside the joint no
  // face is left: no direction), and where the overlap of the corner buries the floor's top,
  // the wall's face does (taking the deepest part instead, the joint read as a surface at any
  // depth and pushed a block resting over it sideways).
  const Geometry pair{Union{
      {Geometry{Box{Vec3(0, 0, 0), Vec3(1, 1, 4)}}, Geometry{Box{Vec3(1, 0, 0), Vec3(2, 1, 4)}}}}};
  BOOST_TEST(near(surface_distance(pair, Vec3(1, 1, 2)).outward, Vec3(0, 1, 0)));
  BOOST_TEST(near(surface_distance(pair, Vec3(1, 1.2, 2)).outward, Vec3(0, 1, 0)));
  BOOST_TEST(near(surface_distance(pair, Vec3(0.9, 0.75, 2)).outward, Vec3::Zero()));
  BOOST_TEST(near(surface_distance(pair, Vec3(1.5, 0.95, 2)).outward, Vec3(0, 1, 0)));
  const SurfaceDistance in_corner = surface_distance(corner, Vec3(0.3, 0.9, 2));
  BOOST_TEST(in_corner.distance == -0.3, tt::tolerance(1e-12));
  BOOST_TEST(near(in_corner.outward, Vec3(-1, 0, 0)));
}

BOOST_AUTO_TEST_SUITE_END()
