#include "pointdriver/fit/least_squares.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_vector.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace impact::pointdriver::fit {

namespace {

double to_physical(const Parameter& p, double u) {
  return p.lower + (p.upper - p.lower) / (1.0 + std::exp(-u));
}
double to_unbounded(const Parameter& p, double v) {
  return std::log((v - p.lower) / (p.upper - v));
}
/// dp/du at u.
double slope(const Parameter& p, double u) {
  const double s = 1.0 / (1.0 + std::exp(-u));
  return (p.upper - p.lower) * s * (1.0 - s);
}

struct Problem {
  const std::vector<Parameter>* parameters;
  std::vector<int> free;  // indices of the free parameters
  const BatchResidual* residual;
  double fd_step;
  std::size_t n = 0;
  int evaluations = 0;
  int calls = 0;
  // The last f evaluation, reused by df at the same point.
  std::vector<double> last_u;
  Eigen::VectorXd last_f;

  std::vector<double> full(const gsl_vector* u) const {
    std::vector<double> v;
    for (const auto& p : *parameters) v.push_back(p.value);
    for (std::size_t k = 0; k < free.size(); ++k)
      v[static_cast<std::size_t>(free[k])] =
          to_physical((*parameters)[static_cast<std::size_t>(free[k])], gsl_vector_get(u, k));
    return v;
  }
  std::vector<Eigen::VectorXd> eval(const std::vector<std::vector<double>>& sets) {
    evaluations += static_cast<int>(sets.size());
    ++calls;
    auto r = (*residual)(sets);
    for (const auto& v : r)
      if (static_cast<std::size_t>(v.size()) != n)
        throw std::runtime_error("least_squares: the residual changed size");
    return r;
  }
};

int f_callback(const gsl_vector* u, void* data, gsl_vector* f) {
  auto* pr = static_cast<Problem*>(data);
  const auto r = pr->eval({pr->full(u)});
  for (std::size_t i = 0; i < pr->n; ++i) gsl_vector_set(f, i, r[0](static_cast<long>(i)));
  pr->last_u.assign(u->data, u->data + u->size);
  pr->last_f = r[0];
  for (std::size_t i = 0; i < pr->n; ++i)
    if (!std::isfinite(r[0](static_cast<long>(i)))) return GSL_EDOM;
  return GSL_SUCCESS;
}

int df_callback(const gsl_vector* u, void* data, gsl_matrix* J) {
  auto* pr = static_cast<Problem*>(data);
  const std::size_t m = pr->free.size();
  bool cached = pr->last_u.size() == u->size;
  for (std::size_t k = 0; cached && k < u->size; ++k) cached = pr->last_u[k] == u->data[k];
  std::vector<std::vector<double>> sets;
  std::vector<double> h(m);
  gsl_vector* up = gsl_vector_alloc(u->size);
  for (std::size_t k = 0; k < m; ++k) {
    gsl_vector_memcpy(up, u);
    h[k] = pr->fd_step * std::max(1.0, std::abs(gsl_vector_get(u, k)));
    gsl_vector_set(up, k, gsl_vector_get(u, k) + h[k]);
    sets.push_back(pr->full(up));
  }
  if (!cached) sets.push_back(pr->full(u));
  gsl_vector_free(up);
  const auto r = pr->eval(sets);
  const Eigen::VectorXd f0 = cached ? pr->last_f : r.back();
  for (std::size_t k = 0; k < m; ++k) {
    const Eigen::VectorXd d = (r[k] - f0) / h[k];
    for (std::size_t i = 0; i < pr->n; ++i) gsl_matrix_set(J, i, k, d(static_cast<long>(i)));
  }
  return GSL_SUCCESS;
}

}  // namespace

LeastSquaresResult least_squares(const std::vector<Parameter>& parameters,
                                 const BatchResidual& residual,
                                 const LeastSquaresOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  Problem pr;
  pr.parameters = &parameters;
  pr.residual = &residual;
  pr.fd_step = options.fd_step;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const Parameter& p = parameters[i];
    if (!p.free) continue;
    if (!(p.lower < p.value && p.value < p.upper))
      throw std::invalid_argument("parameter " + p.name + ": start value " +
                                  std::to_string(p.value) + " is not inside its bounds (" +
                                  std::to_string(p.lower) + ", " + std::to_string(p.upper) + ")");
    pr.free.push_back(static_cast<int>(i));
  }
  std::vector<double> start;
  for (const auto& p : parameters) start.push_back(p.value);
  const Eigen::VectorXd r0 = residual({start})[0];
  pr.n = static_cast<std::size_t>(r0.size());
  const std::size_t m = pr.free.size();

  LeastSquaresResult out;
  out.values = start;
  out.std_errors.assign(parameters.size(), 0.0);
  const long np = static_cast<long>(parameters.size());
  out.covariance = Eigen::MatrixXd::Zero(np, np);
  out.correlation = Eigen::MatrixXd::Identity(np, np);
  if (m == 0) {
    out.residual = r0;
    out.chi2 = r0.squaredNorm();
    out.stop_reason = "no free parameters";
    return out;
  }
  if (pr.n < m)
    throw std::invalid_argument("least_squares: " + std::to_string(pr.n) + " residuals for " +
                                std::to_string(m) + " free parameters");

  gsl_set_error_handler_off();
  gsl_multifit_nlinear_parameters fdf_params = gsl_multifit_nlinear_default_parameters();
  fdf_params.trs = gsl_multifit_nlinear_trs_lmaccel;
  fdf_params.scale = gsl_multifit_nlinear_scale_more;
  fdf_params.solver = gsl_multifit_nlinear_solver_qr;
  gsl_multifit_nlinear_fdf fdf;
  fdf.f = f_callback;
  fdf.df = df_callback;
  fdf.fvv = nullptr;  // second directional derivative by finite differences (GSL)
  fdf.n = pr.n;
  fdf.p = m;
  fdf.params = &pr;
  gsl_multifit_nlinear_workspace* w =
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fdf_params, pr.n, m);
  gsl_vector* u0 = gsl_vector_alloc(m);
  for (std::size_t k = 0; k < m; ++k)
    gsl_vector_set(u0, k,
                   to_unbounded(parameters[static_cast<std::size_t>(pr.free[k])],
                                parameters[static_cast<std::size_t>(pr.free[k])].value));
  int info = 0;
  int status = gsl_multifit_nlinear_init(u0, &fdf, w);
  if (status == GSL_SUCCESS)
    status =
        gsl_multifit_nlinear_driver(static_cast<std::size_t>(options.max_iterations), options.xtol,
                                    options.gtol, options.ftol, nullptr, nullptr, &info, w);
  out.status = status;
  out.iterations = static_cast<int>(gsl_multifit_nlinear_niter(w));
  if (status == GSL_SUCCESS)
    out.stop_reason = info == 1   ? "small step (xtol)"
                      : info == 2 ? "small gradient (gtol)"
                                  : "converged";
  else if (status == GSL_EMAXITER)
    out.stop_reason = "iteration limit reached";
  else
    out.stop_reason = std::string("stopped: ") + gsl_strerror(status);

  const gsl_vector* u = gsl_multifit_nlinear_position(w);
  const gsl_vector* f = gsl_multifit_nlinear_residual(w);
  gsl_matrix* J = gsl_multifit_nlinear_jac(w);
  out.values = pr.full(u);
  out.residual.resize(static_cast<long>(pr.n));
  for (std::size_t i = 0; i < pr.n; ++i) out.residual(static_cast<long>(i)) = gsl_vector_get(f, i);
  out.chi2 = out.residual.squaredNorm();
  const double dof = static_cast<double>(pr.n) - static_cast<double>(m);
  out.variance = dof > 0 ? out.chi2 / dof : 0.0;

  gsl_matrix* cu = gsl_matrix_alloc(m, m);
  gsl_multifit_nlinear_covar(J, 0.0, cu);
  // Upper triangle, mirrored: (v da) db and (v db) da round differently, and the covariance and
  // correlation must be exactly symmetric.
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = a; b < m; ++b) {
      const auto ia = static_cast<long>(pr.free[a]);
      const auto ib = static_cast<long>(pr.free[b]);
      const double da = slope(parameters[static_cast<std::size_t>(ia)], gsl_vector_get(u, a));
      const double db = slope(parameters[static_cast<std::size_t>(ib)], gsl_vector_get(u, b));
      out.covariance(ia, ib) = out.variance * da * db * gsl_matrix_get(cu, a, b);
      out.covariance(ib, ia) = out.covariance(ia, ib);
    }
  }
  for (long i = 0; i < np; ++i)
    out.std_errors[static_cast<std::size_t>(i)] = std::sqrt(std::max(0.0, out.covariance(i, i)));
  for (long i = 0; i < np; ++i)
    for (long j = 0; j < np; ++j) {
      const double d =
          out.std_errors[static_cast<std::size_t>(i)] * out.std_errors[static_cast<std::size_t>(j)];
      if (i < j) out.correlation(i, j) = d > 0 ? out.covariance(i, j) / d : 0.0;
      if (i > j) out.correlation(i, j) = out.correlation(j, i);
    }
  gsl_matrix_free(cu);
  gsl_vector_free(u0);
  gsl_multifit_nlinear_free(w);
  out.residual_evaluations = pr.evaluations + 1;
  out.batch_calls = pr.calls + 1;
  out.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace impact::pointdriver::fit
