#include "mpm/contact/separating_plane.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace impact::mpm {

namespace {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;

// ln(1 + exp(z)) without overflow.
double softplus(double z) {
  return z > 0.0 ? z + std::log1p(std::exp(-z)) : std::log1p(std::exp(z));
}

// theta = (w_x, w_y, w_z, c); a 2D fit keeps w_z = 0 (its row and column are the identity).
Vec4 features(const PlanePoint& p, int dims) {
  return {p.xi(0), p.xi(1), dims == 3 ? p.xi(2) : 0.0, 1.0};
}

// The loss of one point at z = w . xi + c: -ln sigma(z) for the second body, -ln(1 - sigma(z)) =
// -ln sigma(-z) for the first; written with z of the point's own side, s = +-z, so that neither
// 1 - sigma nor softplus(z) - z loses digits where sigma saturates.
double side(const PlanePoint& p, double z) {
  return p.second ? z : -z;
}

template <class Weight>
double objective(std::span<const PlanePoint> points, int dims, const Vec4& theta, double lambda,
                 const Weight& weight) {
  double L = 0.5 * lambda * theta.head<3>().squaredNorm();
  for (const PlanePoint& p : points)
    L += weight(p) * softplus(-side(p, theta.dot(features(p, dims))));
  return L;
}

}  // namespace

Vec3 separating_plane(std::span<const PlanePoint> points, int dims) {
  double total = 0.0, second = 0.0;
  for (const PlanePoint& p : points) {
    total += p.weight;
    if (p.second) second += p.weight;
  }
  // One body only, or one whose stencil tails barely reach the node (separating_plane.hpp).
  if (!(total > 0.0) || !(std::min(second, total - second) > kPlaneLeastShare * total))
    return Vec3::Zero();
  // Each body weighs half (separating_plane.hpp): its points' weights scaled by 1 / (2 W_body).
  const double scale[2] = {0.5 / (total - second), 0.5 / second};
  const auto weight = [&](const PlanePoint& p) { return p.weight * scale[p.second ? 1 : 0]; };
  const double lambda = kPlanePenalty;
  Vec4 theta = Vec4::Zero();
  double L = objective(points, dims, theta, lambda, weight);
  constexpr int kMaxNewtonSteps = 50;
  for (int iteration = 0; iteration < kMaxNewtonSteps; ++iteration) {
    Vec4 gradient = Vec4::Zero();
    Mat4 hessian = Mat4::Zero();
    for (const PlanePoint& p : points) {
      const Vec4 f = features(p, dims);
      const double z = theta.dot(f);
      // sigma(z) = 1 / (1 + exp(-z)) and sigma(-z) from one exponential, without overflow.
      const double e = std::exp(-std::abs(z));
      const double s_up = 1.0 / (1.0 + e), s_down = e / (1.0 + e);  // sigma(|z|), sigma(-|z|)
      const double s_plus = z >= 0.0 ? s_up : s_down, s_minus = z >= 0.0 ? s_down : s_up;
      // dL/dz = -sigma(-s) ds/dz, d2L/dz2 = sigma(z) sigma(-z), s = +-z the point's own side.
      const double wrong = p.second ? s_minus : s_plus;  // the probability of the other body
      gradient -= weight(p) * wrong * (p.second ? 1.0 : -1.0) * f;
      hessian += weight(p) * s_plus * s_minus * f * f.transpose();
    }
    for (int d = 0; d < 3; ++d) {
      gradient(d) += lambda * theta(d);
      hessian(d, d) += lambda;
    }
    if (dims == 2) {  // w_z stays 0
      gradient(2) = 0.0;
      hessian.row(2).setZero();
      hessian.col(2).setZero();
      hessian(2, 2) = 1.0;
    }
    const Vec4 step = -hessian.ldlt().solve(gradient);
    // Newton decrement: -gradient . step estimates twice the decrease left to make. Converged
    // when that is at round-off of L (the weights sum to 1, so L is O(1) until it is small).
    const double decrement = -gradient.dot(step);
    if (!(decrement > 1e-28 * std::max(1.0, L))) break;  // the gradient's round-off floor
    // Within round-off of the minimum L no longer decreases measurably: the Newton step is
    // taken whole (quadratic convergence) and the fit ends.
    if (decrement < 1e-12 * std::max(1.0, L)) {
      theta += step;
      break;
    }
    // Backtracking (Armijo): L is convex but the full step can overshoot where sigma saturates.
    bool moved = false;
    double t = 1.0;
    for (int halving = 0; halving < 40 && !moved; ++halving, t *= 0.5) {
      const Vec4 trial = theta + t * step;
      const double L_trial = objective(points, dims, trial, lambda, weight);
      if (L_trial < L && L_trial <= L - 0.25 * t * decrement) {
        theta = trial;
        L = L_trial;
        moved = true;
      }
    }
    if (!moved) break;  // no decrease within round-off: at the minimum
  }
  // Bodies that no plane separates (their particles mixed at the node): more than
  // kPlaneMixedShare of the balanced weight on the wrong side. The gradients decide there.
  double wrong = 0.0;
  for (const PlanePoint& p : points)
    if (side(p, theta.dot(features(p, dims))) < 0.0) wrong += weight(p);
  if (wrong > kPlaneMixedShare) return Vec3::Zero();
  return theta.head<3>();
}

}  // namespace impact::mpm
