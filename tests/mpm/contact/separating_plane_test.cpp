// The separating plane of `contact.normal = "logistic_regression"` (mpm/contact/separating_plane
// .cpp: penalised logistic regression, Nairn, Hammerquist & Smith 2020) against independently
// derived values:
//   two points   xi = -+a e_x, weight 1 each, labels 0 and 1: by symmetry c = 0 and w = w e_x,
//                and dL/dw = 0 reads lambda w = 2 a sigma(-a w), lambda = kPlanePenalty * 2. Its
//                root by bisection (a = 0.5: w = 8.19...) matches to 1e-9 relative.
//   mirror       a cloud and its mirror image about the plane x = 0.2 with the labels swapped:
//                the plane is x = 0.2 exactly, w along x (|w_y|, |w_z| < 1e-12 |w|) and
//                c / w_x = -0.2 to 1e-9.
//   inclined     particles 2, 4, 8 per cell along each axis in the 3 x 3 x 3 cells around a
//                node, labelled by the side of a plane through the node at 30 degrees to x in the
//                (x, y) plane, weighted by a uGIMP-like tent (1 - |xi|/1.5 per axis): the lattice
//                steps the interface, so no plane is exact, but the fitted normal is closer to the
//                plane's than the sum of the same cloud's mass gradients at every density, and its
//                error falls with the density to below 1 degree at 8 per cell.
//   2D           dims = 2: w_z = 0 exactly whatever the points' z.
//   one body     every label alike, or no weight: w = 0 (the caller falls back).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "mpm/contact/separating_plane.hpp"

using namespace impact;
using namespace impact::mpm;

BOOST_AUTO_TEST_SUITE(mpm_separating_plane)

BOOST_AUTO_TEST_CASE(two_points_give_the_root_of_the_stationarity_condition) {
  const double a = 0.5;
  const std::vector<PlanePoint> points = {{Vec3(-a, 0, 0), 1.0, false}, {Vec3(a, 0, 0), 1.0, true}};
  const Vec3 w = separating_plane(points, 3);
  const double lambda = kPlanePenalty * 2.0;
  // Bisection on f(w) = lambda w - 2 a / (1 + exp(a w)), increasing in w.
  double lo = 0.0, hi = 1e3;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lambda * mid - 2.0 * a / (1.0 + std::exp(a * mid)) > 0.0 ? hi : lo) = mid;
  }
  BOOST_TEST_MESSAGE("w = " << w.transpose() << ", root " << lo);
  BOOST_TEST(std::abs(w(0) / lo - 1.0) < 1e-9);
  BOOST_TEST(std::abs(w(1)) < 1e-12 * lo);
  BOOST_TEST(std::abs(w(2)) < 1e-12 * lo);
}

BOOST_AUTO_TEST_CASE(a_mirrored_cloud_is_split_by_its_mirror_plane) {
  std::vector<PlanePoint> points;
  const double x0 = 0.2;
  for (const double x : {0.35, 0.6, 1.1})
    for (const double y : {-1.0, -0.3, 0.4, 1.2})
      for (const double z : {-0.7, 0.5}) {
        const double weight = 1.0 / (1.0 + x + 0.3 * y * y + 0.1 * z);
        points.push_back({Vec3(x, y, z), weight, true});
        points.push_back({Vec3(2.0 * x0 - x, y, z), weight, false});
      }
  const Vec3 w = separating_plane(points, 3);
  BOOST_TEST_MESSAGE("w = " << w.transpose());
  BOOST_TEST(w(0) > 0.0);
  BOOST_TEST(std::abs(w(1)) < 1e-12 * w.norm());
  BOOST_TEST(std::abs(w(2)) < 1e-12 * w.norm());
}

// The fitted and the mass-gradient normals' angles to the plane through the node at 30 degrees
// to x, particles `per_cell` per cell along each axis [degrees].
std::pair<double, double> inclined_interface_errors(int per_cell) {
  const double angle = 30.0 * std::numbers::pi / 180.0;
  const Vec3 n(std::cos(angle), std::sin(angle), 0.0);
  std::vector<PlanePoint> points;
  Vec3 grad_first = Vec3::Zero(), grad_second = Vec3::Zero();
  const double pitch = 1.0 / per_cell;
  for (int i = -3 * per_cell / 2; i < 3 * per_cell / 2; ++i)
    for (int j = -3 * per_cell / 2; j < 3 * per_cell / 2; ++j)
      for (int k = -3 * per_cell / 2; k < 3 * per_cell / 2; ++k) {
        const Vec3 xi = (Vec3(i, j, k) + Vec3::Constant(0.5)) * pitch;
        double weight = 1.0;
        for (int d = 0; d < 3; ++d) weight *= std::max(0.0, 1.0 - std::abs(xi(d)) / 1.5);
        if (!(weight > 0.0)) continue;
        const bool second = xi.dot(n) > 0.0;
        points.push_back({xi, weight, second});
        // -d S / d xi of the tent at the node: how the nodal mass gradient weighs a particle.
        Vec3 g;
        for (int d = 0; d < 3; ++d) {
          double s = xi(d) > 0.0 ? 1.0 / 1.5 : -1.0 / 1.5;
          for (int e = 0; e < 3; ++e)
            if (e != d) s *= std::max(0.0, 1.0 - std::abs(xi(e)) / 1.5);
          g(d) = s;
        }
        (second ? grad_second : grad_first) += g;
      }
  const auto degrees = [&](const Vec3& v) {
    return std::acos(std::min(1.0, v.normalized().dot(n))) * 180.0 / std::numbers::pi;
  };
  // unit(grad m_second - grad m_first) points into the second body (contact.hpp).
  return {degrees(separating_plane(points, 3)), degrees(grad_second - grad_first)};
}

BOOST_AUTO_TEST_CASE(an_inclined_interface_is_found_closer_than_by_the_mass_gradients) {
  double last = 90.0;
  for (const int per_cell : {2, 4, 8}) {
    const auto [fitted, gradients] = inclined_interface_errors(per_cell);
    BOOST_TEST_MESSAGE(per_cell << " particles per cell: fitted normal " << fitted
                                << " degrees off, mass-gradient sum " << gradients);
    BOOST_TEST(fitted < gradients);
    BOOST_TEST(fitted < last);
    last = fitted;
  }
  BOOST_TEST(last < 1.0);
}

BOOST_AUTO_TEST_CASE(a_2d_fit_has_no_z_component_and_one_body_gives_none) {
  std::vector<PlanePoint> points;
  for (int i = 0; i < 8; ++i) {
    const double x = -0.9 + 0.25 * i;
    points.push_back({Vec3(x, 0.3 * x, 0.4 * i - 1.0), 1.0 + 0.1 * i, x > 0.1});
  }
  const Vec3 w = separating_plane(points, 2);
  BOOST_TEST(w(0) > 0.0);
  BOOST_TEST(w(2) == 0.0);
  for (PlanePoint& p : points) p.second = true;
  BOOST_TEST(separating_plane(points, 3).norm() == 0.0);
  for (PlanePoint& p : points) p.second = false;
  BOOST_TEST(separating_plane(points, 3).norm() == 0.0);
  BOOST_TEST(separating_plane({}, 3).norm() == 0.0);
}

// The particle's radius along n for the bodies' gap (`contact.detection = "separation"`): the
// inscribed ellipse of its box of half-widths l carried by F, by hand. An axis-aligned ellipse of
// semi-axes a, b, along (cos t, sin t): 1 / sqrt(cos^2 t / a^2 + sin^2 t / b^2).
BOOST_AUTO_TEST_CASE(a_particles_deformed_radius_is_its_ellipse_along_the_normal) {
  const double pi = std::acos(-1.0), c = std::cos(pi / 6.0), s = std::sin(pi / 6.0);
  const Vec3 x(1.0, 0.0, 0.0), tilted(c, s, 0.0);
  const Vec3 l(1e-3, 2e-3, 3e-3), unit(1e-3, 1e-3, 1e-3);
  const auto tol = boost::test_tools::tolerance(1e-12);
  const Mat3 I = Mat3::Identity();
  BOOST_TEST(deformed_radius(I, l, x, 3) == 1e-3, tol);
  BOOST_TEST(deformed_radius(I, l, tilted, 3) == 1e-3 / std::sqrt(c * c + s * s / 4.0), tol);
  // Rotated 30 degrees about z: along x the ellipse's axes lie at 30 degrees to it, as the tilted
  // normal lies to the unrotated ellipse's.
  Mat3 R;
  R << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  BOOST_TEST(deformed_radius(R, l, x, 3) == 1e-3 / std::sqrt(c * c + s * s / 4.0), tol);
  BOOST_TEST(deformed_radius(R, unit, x, 3) == 1e-3, tol);  // a rotated circle: its radius
  // Compressed to half along x: 0.5 mm along x, 1 / sqrt(4 c^2 + s^2) mm at 30 degrees.
  const Mat3 squeezed = Vec3(0.5, 1.0, 1.0).asDiagonal();
  BOOST_TEST(deformed_radius(squeezed, unit, x, 3) == 0.5e-3, tol);
  BOOST_TEST(deformed_radius(squeezed, unit, tilted, 3) == 1e-3 / std::sqrt(4.0 * c * c + s * s),
             tol);
  // A 2D grid: the out-of-plane (hoop) stretch does not widen it.
  const Mat3 hoop = Vec3(1.0, 1.0, 7.0).asDiagonal();
  BOOST_TEST(deformed_radius(hoop, l, tilted, 2) == 1e-3 / std::sqrt(c * c + s * s / 4.0), tol);
  BOOST_TEST(deformed_radius(Mat3::Zero(), l, x, 3) == 0.0);  // degenerate: no reach
}

// The deformed box's reach along n, sum_d l_d abs((F^T n)_d), by hand: the box's corner.
BOOST_AUTO_TEST_CASE(a_particles_deformed_box_reaches_its_corner_along_the_normal) {
  const double pi = std::acos(-1.0), c = std::cos(pi / 6.0), s = std::sin(pi / 6.0);
  const Vec3 x(1.0, 0.0, 0.0), tilted(c, s, 0.0), l(1e-3, 2e-3, 3e-3);
  const auto tol = boost::test_tools::tolerance(1e-12);
  BOOST_TEST(deformed_reach(Mat3::Identity(), l, x, 3) == 1e-3, tol);
  BOOST_TEST(deformed_reach(Mat3::Identity(), l, tilted, 3) == 1e-3 * c + 2e-3 * s, tol);
  BOOST_TEST(deformed_reach(Mat3::Identity(), l, tilted, 3) >
             deformed_radius(Mat3::Identity(), l, tilted, 3));  // the ellipse lies inside
  Mat3 R;  // rotated 30 degrees about z: along x, the rotated half-edges' x components
  R << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  BOOST_TEST(deformed_reach(R, l, x, 3) == 1e-3 * c + 2e-3 * s, tol);
  const Mat3 hoop = Vec3(1.0, 1.0, 7.0).asDiagonal();  // 2D: no extent along z
  BOOST_TEST(deformed_reach(hoop, l, Vec3(0.0, 0.0, 1.0), 2) == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
