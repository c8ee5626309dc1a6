#include "mpm/contact/separating_plane.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "models/core/lane_math.hpp"

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

// The loss, its gradient and Hessian at one theta (evaluate_blocks).
struct Fit {
  double L = 0.0;
  Vec4 gradient = Vec4::Zero();
  Mat4 hessian = Mat4::Zero();
};

// The cloud on lanes, kLaneWidth points per block (lane_math.hpp's exp and log1p, branch-free,
// where the C library's were 75 % of a step with this normal on a graded grid): features xi (xi_z
// = 0 on a 2D grid), the balanced weight (0 in the last block's padding lanes) and the side,
// +1 for the second body and -1 for the first.
struct alignas(lane::kLaneBytes) PointBlock {
  lane::Vec x, y, z, weight, side;
};

// The sums of one evaluation, each lane's own over the blocks, then the lanes in order: the same
// bits on every instruction set (the lanes round alike) and for every thread or rank.
struct FitSums {
  double L = 0.0;
  double gradient[4] = {0.0, 0.0, 0.0, 0.0};
  // The lower triangle, column by column: (0,0) (1,0) (2,0) (3,0) (1,1) (2,1) ... (3,3).
  double hessian[10] = {};
};

// L(theta) with its gradient and Hessian, in one pass over the points: one exponential and one
// logarithm per point. The loss of a point is -ln sigma(s) = softplus(-s), softplus(x) = max(x, 0)
// + ln(1 + exp(-|x|)), written with s = +-z of the point's own side (positive where the plane
// puts it on its own body's side) so that neither 1 - sigma nor softplus(z) - z loses digits
// where sigma saturates. The line search evaluates its trial points with this too: an accepted
// trial's derivatives are the next Newton step's, and only a rejected one (rare) spends its
// derivatives.
IMPACT_LANE_CLONES void evaluate_blocks(const PointBlock* blocks, std::size_t count,
                                        const double* theta, FitSums& out) {
  using lane::Vec;
  const Vec zero = lane::splat<Vec>(0.0), one = lane::splat<Vec>(1.0);
  Vec L = zero, g[4] = {zero, zero, zero, zero}, h[10];
  for (Vec& v : h) v = zero;
  for (std::size_t b = 0; b < count; ++b) {
    const PointBlock& p = blocks[b];
    const Vec f[4] = {p.x, p.y, p.z, one};
    const Vec z = theta[0] * p.x + theta[1] * p.y + theta[2] * p.z + theta[3];
    const Vec s = p.side * z;
    // sigma(|s|) and sigma(-|s|) from one exponential, without overflow; -ln sigma(s) and the
    // probability of the other body, sigma(-s).
    const Vec e = lane::exp(-lane::abs(s));
    const Vec up = 1.0 / (1.0 + e), down = e / (1.0 + e);
    L += p.weight * (lane::select<Vec>(s < 0.0, -s, zero) + lane::log1p(e));
    // dL/dz = -sigma(-s) ds/dz, d2L/dz2 = sigma(z) sigma(-z).
    const Vec wrong = p.weight * lane::select<Vec>(s >= 0.0, down, up) * p.side;
    const Vec curvature = p.weight * up * down;
    int k = 0;
    for (int j = 0; j < 4; ++j) {
      g[j] -= wrong * f[j];
      const Vec cf = curvature * f[j];
      for (int i = j; i < 4; ++i) h[k++] += cf * f[i];
    }
  }
  for (int lane_k = 0; lane_k < lane::kLaneWidth; ++lane_k) {
    out.L += L[lane_k];
    for (int j = 0; j < 4; ++j) out.gradient[j] += g[j][lane_k];
    for (int k = 0; k < 10; ++k) out.hessian[k] += h[k][lane_k];
  }
}

Fit evaluate(const std::vector<PointBlock>& blocks, int dims, const Vec4& theta, double lambda) {
  FitSums sums;
  const double t[4] = {theta(0), theta(1), theta(2), theta(3)};
  evaluate_blocks(blocks.data(), blocks.size(), t, sums);
  Fit fit;
  fit.L = 0.5 * lambda * theta.head<3>().squaredNorm() + sums.L;
  int k = 0;
  for (int j = 0; j < 4; ++j) {
    fit.gradient(j) = sums.gradient[j];
    for (int i = j; i < 4; ++i) fit.hessian(i, j) = sums.hessian[k++];  // the LDLT reads no other
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

// The points in blocks of kLaneWidth, their weights scaled per body (scale[second]).
std::vector<PointBlock> blocks_of(std::span<const PlanePoint> points, int dims,
                                  const double scale[2]) {
  // Value-initialised: the padding lanes hold zeros (weight 0: they add nothing).
  std::vector<PointBlock> blocks((points.size() + lane::kLaneWidth - 1) / lane::kLaneWidth);
  for (std::size_t q = 0; q < points.size(); ++q) {
    PointBlock& b = blocks[q / lane::kLaneWidth];
    const int k = static_cast<int>(q % lane::kLaneWidth);
    const PlanePoint& p = points[q];
    b.x[k] = p.xi(0);
    b.y[k] = p.xi(1);
    b.z[k] = dims == 3 ? p.xi(2) : 0.0;
    b.weight[k] = p.weight * scale[p.second ? 1 : 0];
    b.side[k] = p.second ? 1.0 : -1.0;
  }
  return blocks;
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
  const std::vector<PointBlock> blocks = blocks_of(points, dims, scale);
  const double lambda = kPlanePenalty;
  Vec4 theta = Vec4::Zero();
  Fit fit = evaluate(blocks, dims, theta, lambda);
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
      Fit at_trial = evaluate(blocks, dims, trial, lambda);
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

double deformed_radius(const Mat3& F, const Vec3& l, const Vec3& n, int dims) {
  double r;
  if (dims == 2) {
    const Eigen::Matrix2d A = F.topLeftCorner<2, 2>() * l.head<2>().asDiagonal();
    r = 1.0 / (A.inverse() * n.head<2>()).norm();
  } else {
    r = 1.0 / ((F * l.asDiagonal()).inverse() * n).norm();
  }
  return std::isfinite(r) ? r : 0.0;
}

double deformed_reach(const Mat3& F, const Vec3& l, const Vec3& n, int dims) {
  const Vec3 Fn = F.transpose() * n;
  double r = 0.0;
  for (int d = 0; d < dims; ++d) r += l(d) * std::abs(Fn(d));
  return r;
}

}  // namespace impact::mpm
