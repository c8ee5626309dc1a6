#include "mpm/contact/separating_plane.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace impact::mpm {

namespace {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;

// theta = (w_x, w_y, w_z, c); a 2D fit keeps w_z = 0 (its row and column are the identity).
Vec4 features(const PlanePoint& p, int dims) {
  return {p.xi(0), p.xi(1), dims == 3 ? p.xi(2) : 0.0, 1.0};
}

// z of the point's own side, s = +-z (positive where the plane puts it on its own body's side).
double side(const PlanePoint& p, double z) {
  return p.second ? z : -z;
}

// L(theta) with its gradient and Hessian, in one pass over the points: one exponential and one
// logarithm per point. The loss of a point is -ln sigma(s) = softplus(-s), softplus(x) = max(x, 0)
// + ln(1 + exp(-|x|)), written with s of the point's own side so that neither 1 - sigma nor
// softplus(z) - z loses digits where sigma saturates. The line search evaluates its trial points
// with this too: an accepted trial's derivatives are the next Newton step's, and only a rejected
// one (rare) spends its derivatives.
struct Fit {
  double L = 0.0;
  Vec4 gradient = Vec4::Zero();
  Mat4 hessian = Mat4::Zero();
};

template <class Weight>
Fit evaluate(std::span<const PlanePoint> points, int dims, const Vec4& theta, double lambda,
             const Weight& weight) {
  Fit fit;
  fit.L = 0.5 * lambda * theta.head<3>().squaredNorm();
  for (const PlanePoint& p : points) {
    const Vec4 f = features(p, dims);
    const double z = theta.dot(f);
    // sigma(z) = 1 / (1 + exp(-z)) and sigma(-z) from one exponential, without overflow.
    const double e = std::exp(-std::abs(z));
    const double s_up = 1.0 / (1.0 + e), s_down = e / (1.0 + e);  // sigma(|z|), sigma(-|z|)
    const double s_plus = z >= 0.0 ? s_up : s_down, s_minus = z >= 0.0 ? s_down : s_up;
    const double w = weight(p);
    fit.L += w * (std::max(-side(p, z), 0.0) + std::log1p(e));  // softplus(-s), |s| = |z|
    // dL/dz = -sigma(-s) ds/dz, d2L/dz2 = sigma(z) sigma(-z).
    const double wrong = p.second ? s_minus : s_plus;  // the probability of the other body
    fit.gradient -= w * wrong * (p.second ? 1.0 : -1.0) * f;
    // The lower triangle only: the LDLT factorisation reads no other.
    const Vec4 cf = (w * s_plus * s_minus) * f;
    for (int j = 0; j < 4; ++j)
      for (int i = j; i < 4; ++i) fit.hessian(i, j) += cf(i) * f(j);
  }
  for (int d = 0; d < 3; ++d) {
    fit.gradient(d) += lambda * theta(d);
    fit.hessian(d, d) += lambda;
  }
  if (dims == 2) {  // w_z stays 0
    fit.gradient(2) = 0.0;
    fit.hessian.row(2).setZero();
    fit.hessian.col(2).setZero();
    fit.hessian(2, 2) = 1.0;
  }
  return fit;
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
  Fit fit = evaluate(points, dims, theta, lambda, weight);
  constexpr int kMaxNewtonSteps = 50;
  for (int iteration = 0; iteration < kMaxNewtonSteps; ++iteration) {
    const Vec4 step = -fit.hessian.ldlt().solve(fit.gradient);
    // Newton decrement: -gradient . step estimates twice the decrease left to make. Converged
    // when that is at round-off of L (the weights sum to 1, so L is O(1) until it is small).
    const double decrement = -fit.gradient.dot(step);
    const double L = fit.L;
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
      Fit at_trial = evaluate(points, dims, trial, lambda, weight);
      if (at_trial.L < L && at_trial.L <= L - 0.25 * t * decrement) {
        theta = trial;
        fit = at_trial;
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
