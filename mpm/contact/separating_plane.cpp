#include "mpm/contact/separating_plane.hpp"

#include <Eigen/Cholesky>
#include <cmath>

namespace impact::mpm {

namespace {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;

// ln(1 + exp(z)) without overflow, and sigma(z).
double softplus(double z) {
  return z > 0.0 ? z + std::log1p(std::exp(-z)) : std::log1p(std::exp(z));
}
double sigmoid(double z) {
  if (z >= 0.0) return 1.0 / (1.0 + std::exp(-z));
  const double e = std::exp(z);
  return e / (1.0 + e);
}

// theta = (w_x, w_y, w_z, c); a 2D fit keeps w_z = 0 (its row and column are the identity).
Vec4 features(const PlanePoint& p, int dims) {
  return {p.xi(0), p.xi(1), dims == 3 ? p.xi(2) : 0.0, 1.0};
}

template <class Weight>
double objective(std::span<const PlanePoint> points, int dims, const Vec4& theta, double lambda,
                 const Weight& weight) {
  double L = 0.5 * lambda * theta.head<3>().squaredNorm();
  for (const PlanePoint& p : points) {
    const double z = theta.dot(features(p, dims));
    L += weight(p) * (softplus(z) - (p.second ? z : 0.0));
  }
  return L;
}

}  // namespace

Vec3 separating_plane(std::span<const PlanePoint> points, int dims) {
  double total = 0.0, second = 0.0;
  for (const PlanePoint& p : points) {
    total += p.weight;
    if (p.second) second += p.weight;
  }
  if (!(total > 0.0) || !(second > 0.0) || !(second < total)) return Vec3::Zero();  // one body
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
      const double s = sigmoid(theta.dot(f));
      gradient += weight(p) * (s - (p.second ? 1.0 : 0.0)) * f;
      hessian += weight(p) * s * (1.0 - s) * f * f.transpose();
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
    // Newton decrement: -gradient . step estimates twice the remaining decrease of L.
    const double decrement = -gradient.dot(step);
    if (!(decrement > 0.0)) break;
    if (step.norm() <= 1e-9 * (1.0 + theta.norm())) {  // quadratic convergence: done
      theta += step;
      break;
    }
    // Backtracking (Armijo): L is convex but the full step can overshoot where sigma saturates.
    double t = 1.0;
    for (int halving = 0; halving < 40; ++halving, t *= 0.5) {
      const Vec4 trial = theta + t * step;
      const double L_trial = objective(points, dims, trial, lambda, weight);
      if (L_trial <= L - 0.25 * t * decrement) {
        theta = trial;
        L = L_trial;
        break;
      }
    }
    if (t < 1e-12) break;  // no decrease within round-off: at the minimum
  }
  return theta.head<3>();
}

}  // namespace impact::mpm
