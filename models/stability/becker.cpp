#include "models/stability/becker.hpp"

#include <gsl/gsl_min.h>
#include <gsl/gsl_multimin.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

namespace impact {

Mat3 acoustic_tensor(const Tensor4& C, const Vec3& n) {
  Mat3 a = Mat3::Zero();
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < 3; ++l) {
      const double w = n(i) * n(l);
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) a(j, k) += w * C(3 * i + j, 3 * k + l);
    }
  return a;
}

namespace {

constexpr double kPi = std::numbers::pi;

// The search problem: tangents and the principal frame Q = [e_min, e_mid, e_max] (ascending).
struct Search {
  const Tensor4* tangent;
  const Tensor4* elastic;
  Mat3 Q;

  // det A^ep / det A^e at a lab-frame normal; non-finite values (a degenerate elastic reference)
  // become DBL_MAX so that GSL never meets them (its default error handler aborts).
  double ratio(const Vec3& n) const {
    const double r =
        acoustic_tensor(*tangent, n).determinant() / acoustic_tensor(*elastic, n).determinant();
    return std::isfinite(r) ? r : std::numeric_limits<double>::max();
  }
  // Becker's plane: n(t) = cos t e_max + sin t e_min.
  Vec3 plane_normal(double t) const { return std::cos(t) * Q.col(2) + std::sin(t) * Q.col(0); }
  // Sphere in the principal frame, polar axis e_max, phi = 0 and pi on Becker's plane.
  Vec3 sphere_normal(double theta, double phi) const {
    return Q *
           Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  }
};

double plane_objective(double t, void* params) {
  const auto* s = static_cast<const Search*>(params);
  return s->ratio(s->plane_normal(t));
}

double sphere_objective(const gsl_vector* x, void* params) {
  const auto* s = static_cast<const Search*>(params);
  return s->ratio(s->sphere_normal(gsl_vector_get(x, 0), gsl_vector_get(x, 1)));
}

BeckerResult search_principal_plane(const Search& s) {
  // Coarse sweep: 5-degree steps over [0, pi) (n and -n are the same band).
  constexpr int kSamples = 36;
  constexpr double dt = kPi / kSamples;
  double f[kSamples];
  int best = 0;
  for (int k = 0; k < kSamples; ++k) {
    f[k] = s.ratio(s.plane_normal(k * dt));
    if (f[k] < f[best]) best = k;
  }
  double t_best = best * dt;
  double f_best = f[best];
  // Brent refinement on [t_best - dt, t_best + dt]; the objective has period pi, so the neighbours
  // wrap around. GSL requires the guess to be strictly below both ends; a flat neighbourhood (an
  // elastic tangent) has nothing to refine.
  const double f_lo = f[(best + kSamples - 1) % kSamples];
  const double f_hi = f[(best + 1) % kSamples];
  if (f_best < f_lo && f_best < f_hi) {
    std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> m(
        gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent), &gsl_min_fminimizer_free);
    gsl_function fn{&plane_objective, const_cast<Search*>(&s)};
    gsl_min_fminimizer_set_with_values(m.get(), &fn, t_best, f_best, t_best - dt, f_lo, t_best + dt,
                                       f_hi);
    for (int it = 0; it < 100; ++it) {
      if (gsl_min_fminimizer_iterate(m.get()) != GSL_SUCCESS) break;
      // 1e-9 rad: the indicator error is then ~ f'' 1e-18, far below round-off.
      if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m.get()),
                                gsl_min_fminimizer_x_upper(m.get()), 1e-9, 0.0) == GSL_SUCCESS)
        break;
    }
    const double t = gsl_min_fminimizer_x_minimum(m.get());
    const double v = s.ratio(s.plane_normal(t));
    if (v < f_best) {
      t_best = t;
      f_best = v;
    }
  }
  BeckerResult r;
  r.normal = s.plane_normal(t_best);
  r.indicator = f_best;
  return r;
}

BeckerResult search_full_sphere(const Search& s) {
  // Coarse sweep of the upper hemisphere: theta in 5-degree steps from the pole e_max, phi in
  // 10-degree steps (one sample at the pole).
  constexpr int kTheta = 18, kPhi = 36;
  constexpr double d_theta = 0.5 * kPi / kTheta, d_phi = 2.0 * kPi / kPhi;
  double theta_best = 0.0, phi_best = 0.0;
  double f_best = s.ratio(s.sphere_normal(0.0, 0.0));
  for (int i = 1; i <= kTheta; ++i)
    for (int j = 0; j < kPhi; ++j) {
      const double v = s.ratio(s.sphere_normal(i * d_theta, j * d_phi));
      if (v < f_best) {
        f_best = v;
        theta_best = i * d_theta;
        phi_best = j * d_phi;
      }
    }
  // Nelder-Mead refinement in (theta, phi), started at the best sample with the grid steps.
  std::unique_ptr<gsl_multimin_fminimizer, decltype(&gsl_multimin_fminimizer_free)> m(
      gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 2),
      &gsl_multimin_fminimizer_free);
  double x0[2] = {theta_best, phi_best};
  double step[2] = {0.5 * d_theta, 0.5 * d_phi};
  gsl_vector_view x = gsl_vector_view_array(x0, 2);
  gsl_vector_view st = gsl_vector_view_array(step, 2);
  gsl_multimin_function fn{&sphere_objective, 2, const_cast<Search*>(&s)};
  if (gsl_multimin_fminimizer_set(m.get(), &fn, &x.vector, &st.vector) == GSL_SUCCESS) {
    for (int it = 0; it < 400; ++it) {
      if (gsl_multimin_fminimizer_iterate(m.get()) != GSL_SUCCESS) break;
      // Simplex size 1e-9 rad: far below what changes the indicator.
      if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(m.get()), 1e-9) == GSL_SUCCESS) break;
    }
    const gsl_vector* xm = gsl_multimin_fminimizer_x(m.get());
    const double theta = gsl_vector_get(xm, 0), phi = gsl_vector_get(xm, 1);
    const double v = s.ratio(s.sphere_normal(theta, phi));
    if (v < f_best) {
      f_best = v;
      theta_best = theta;
      phi_best = phi;
    }
  }
  BeckerResult r;
  r.normal = s.sphere_normal(theta_best, phi_best);
  r.indicator = f_best;
  return r;
}

}  // namespace

BeckerResult becker_check(const Tensor4& tangent, const Tensor4& elastic, const Mat3& stress,
                          NormalSearch search) {
  if (!tangent.allFinite() || !elastic.allFinite() || !stress.allFinite()) {
    return BeckerResult{std::numeric_limits<double>::quiet_NaN(), Vec3::Zero(), false};
  }
  // Principal frame of the (symmetric part of the) stress; eigenvalues ascending.
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(sym(stress));
  const Search s{&tangent, &elastic, eig.eigenvectors()};
  BeckerResult r =
      search == NormalSearch::principal_plane ? search_principal_plane(s) : search_full_sphere(s);
  // The normals are unit to round-off already; normalizing and re-evaluating makes the reported
  // indicator exactly the ratio at the reported normal (the ratio is homogeneous of degree 0 in n).
  r.normal.normalize();
  r.indicator = s.ratio(r.normal);
  r.unstable = r.indicator <= 0.0;
  return r;
}

BeckerResult becker_check_j2(double bulk_modulus, double shear_modulus, const Mat3& stress,
                             double H) {
  if (!stress.allFinite() || std::isnan(H)) {
    return BeckerResult{std::numeric_limits<double>::quiet_NaN(), Vec3::Zero(), false};
  }
  Eigen::SelfAdjointEigenSolver<Mat3> eig;
  eig.computeDirect(sym(stress));  // closed-form 3x3; eigenvalues ascending
  const Vec3 lambda = eig.eigenvalues();
  const Mat3& Q = eig.eigenvectors();
  const Vec3 dev = lambda - Vec3::Constant(lambda.mean());
  const double sigma_eq = std::sqrt(1.5 * dev.squaredNorm());
  BeckerResult r;
  r.normal = Q.col(2);
  if (sigma_eq == 0.0) return r;  // no deviator: the tangent is elastic, indicator 1
  const double mu = shear_modulus;
  const double a = std::isinf(H) ? 0.0 : 4.0 * mu * mu / (3.0 * mu + H);
  const double beta = (bulk_modulus + mu / 3.0) / (bulk_modulus + 4.0 * mu / 3.0);
  const double n_max = 1.5 * dev(2) / sigma_eq, n_min = 1.5 * dev(0) / sigma_eq;
  const double dn = n_max - n_min;
  const auto ratio = [&](double x) {
    const double nv = n_min + dn * x;
    const double f = n_min * n_min + (n_max * n_max - n_min * n_min) * x - beta * nv * nv;
    return 1.0 - a / mu * f;
  };
  double x_best = 1.0;
  r.indicator = ratio(1.0);
  const auto consider = [&](double x) {
    const double v = ratio(x);
    if (v < r.indicator) {
      r.indicator = v;
      x_best = x;
    }
  };
  consider(0.0);
  if (dn > 0.0) {
    const double x_star = ((n_max + n_min) - 2.0 * beta * n_min) / (2.0 * beta * dn);
    if (x_star > 0.0 && x_star < 1.0) consider(x_star);
  }
  r.normal = (std::sqrt(x_best) * Q.col(2) + std::sqrt(1.0 - x_best) * Q.col(0)).normalized();
  r.unstable = r.indicator <= 0.0;
  return r;
}

}  // namespace impact
