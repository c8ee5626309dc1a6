// The plane that separates two bodies' particles near a node, by logistic regression (Nairn,
// Hammerquist & Smith 2020, CMAME 362:112859, sec. 3): the contact normal of
// `contact.normal = "logistic_regression"` (contact/contact.hpp). Each particle p of the node's
// cloud (step/contact_planes.cpp: within about two cells, tent weight > 0) is a labelled point:
// y_p = 1 for one body, 0 for the other, at xi_p = (x_p - x_I) / h (cells from the node). The fit
// finds w, c of the probability that a point belongs to the second body, sigma(w . xi + c),
// sigma(z) = 1 / (1 + exp(-z)), by minimising
//   L(w, c) = sum_p w_p [ln(1 + exp(z_p)) - y_p z_p] + (lambda / 2) |w|^2,   z_p = w . xi_p + c,
// and w (pointing into the second body) is the plane's normal in cell units. Two bodies'
// particles are separable, so without the penalty |w| would grow without bound; lambda =
// kPlanePenalty bounds it (the fit is then unique: L is strictly convex) and leaves the direction
// that of the points near the plane. w_p are the cloud's tent weights scaled per body (below).
// Newton's method with a backtracking line search converges from w = 0, c = 0 (where the first step
// is the least-squares plane) in a few steps. Each body's weights are scaled so that it weighs 1/2
// in all (class balance): a body that reaches the node only with its stencils' tails would
// otherwise leave the fit to the penalty and the normal would point at its centroid. No plane is
// returned (w = 0: the caller falls back to the mass gradients) where one body holds less than
// kPlaneLeastShare of the points' weight (a tail of 1e-10 tilted the normal by 23 degrees),
// or where the fit leaves more than kPlaneMixedShare of the balanced weight on the wrong side (the
// bodies' particles mixed). Departures from Nairn et al. (the paper and the NairnMPM code that
// implements it): they fit 2 sigma - 1 to labels
// +-1 by least squares with every particle weighted 1 and a penalty of 1e-7 cell^2, start from a
// linear regression and stop after 15 iterations; here the cross-entropy (the logistic
// likelihood) with tent weights over a wider cloud, class balance and lambda = 1e-3, Newton from
// zero (its first step is the least-squares plane) to convergence. Their fit also gives the bodies'
// separation along n for a displacement contact check: `contact.detection = "separation"`
// (step/contact_planes.cpp measures it on the node's own particles; contact/contact.hpp).
#pragma once

#include <span>

#include "mpm/grid/grid.hpp"

namespace impact::mpm {

/// One particle in the fit: its offset from the node in cells, its weight and its body.
struct PlanePoint {
  Vec3 xi;
  double weight = 0.0;
  bool second = false;  ///< y_p = 1 (the second body), else y_p = 0
};

/// lambda: the penalty on |w|^2 (the balanced weights sum to 1).
inline constexpr double kPlanePenalty = 1e-3;
/// A body with less than this share of the points' shape weight gets no plane fitted.
inline constexpr double kPlaneLeastShare = 1e-5;
/// A fit with more than this share of the balanced weight on the wrong side is no plane.
inline constexpr double kPlaneMixedShare = 0.1;

/// The fitted w (cells^-1; zero when no plane is found: one body only, or no weight). `dims` = 2
/// fits in the (x, y) plane only (a 2D grid: xi_z is ignored and w_z = 0).
Vec3 separating_plane(std::span<const PlanePoint> points, int dims);

/// A particle's radius along the unit vector n [m], for the bodies' gap of `contact.detection =
/// "separation"`: the distance from x_p along n to the edge of the ellipse (ellipsoid) inscribed in
/// its box domain of half-widths l [m] carried by its deformation gradient F, 1 / |(F L)^{-1} n|
/// with L = diag(l) (Nairn, Hammerquist & Smith 2020 measure the separation with the particles'
/// deformed radii; NairnMPM's default is this ellipse). `dims` = 2: in the (x, y) plane (n_z = 0;
/// a 2D grid's hoop or out-of-plane stretch does not widen it). The box's own reach along n,
/// sum_d l_d abs((F^T n)_d), exceeds it by up to 41 % off the box's axes, and a plane tilted 3.8
/// degrees at a rod's edge started that rod's contact 0.22 us early against 0.09 us
/// (tests/mpm/verification/contact_detection_test.cpp). Zero for a degenerate F.
double deformed_radius(const Mat3& F, const Vec3& l, const Vec3& n, int dims);

/// The reach along the unit vector n of the same particle's deformed box [m], sum_d l_d
/// abs((F^T n)_d) (its support: no point of the box lies further along n), at least
/// deformed_radius. The gap at a node of three or more bodies (step/contact_planes.cpp) takes it,
/// so that a positive gap along any direction means the domains are apart.
double deformed_reach(const Mat3& F, const Vec3& l, const Vec3& n, int dims);

}  // namespace impact::mpm
