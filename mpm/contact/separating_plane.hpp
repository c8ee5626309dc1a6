// The plane that separates two bodies' particles near a node, by logistic regression (Nairn,
// Hammerquist & Smith 2020, CMAME 362:112859, sec. 3): the contact normal of
// `contact.normal = "logistic_regression"` (contact/contact.hpp). Each particle p that weighs on
// the node (shape weight S_p > 0) is a labelled point: y_p = 1 for one body, 0 for the other, at
// xi_p = (x_p - x_I) / h (cells from the node). The fit finds w, c of the probability that a point
// belongs to the second body, sigma(w . xi + c), sigma(z) = 1 / (1 + exp(-z)), by minimising
//   L(w, c) = sum_p S_p [ln(1 + exp(z_p)) - y_p z_p] + (lambda / 2) |w|^2,   z_p = w . xi_p + c,
// and w (pointing into the second body) is the plane's normal in cell units. Two bodies'
// particles are separable, so without the penalty |w| would grow without bound; lambda =
// kPlanePenalty sum_p S_p bounds it (the fit is then unique: L is strictly convex) and leaves the
// direction that of the points near the plane. Newton's method with a backtracking line search
// converges from w = 0, c = 0 (where the first step is the least-squares plane) in a few steps.
// Where both bodies occupy the node's support alike (no plane separates them), w is small or zero
// and the caller falls back to the mass gradients.
#pragma once

#include <span>

#include "mpm/grid/grid.hpp"

namespace impact::mpm {

/// One particle in the fit: its offset from the node in cells, its shape weight and its body.
struct PlanePoint {
  Vec3 xi;
  double weight = 0.0;
  bool second = false;  ///< y_p = 1 (the second body), else y_p = 0
};

/// lambda / sum_p S_p: the penalty on |w|^2 relative to the points' total weight.
inline constexpr double kPlanePenalty = 1e-3;

/// The fitted w (cells^-1; zero when no plane is found: one body only, or no weight). `dims` = 2
/// fits in the (x, y) plane only (a 2D grid: xi_z is ignored and w_z = 0).
Vec3 separating_plane(std::span<const PlanePoint> points, int dims);

}  // namespace impact::mpm
