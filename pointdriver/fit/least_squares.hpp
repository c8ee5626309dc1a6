// Bounded nonlinear least squares with GSL's multifit_nlinear: trust region, Levenberg-Marquardt
// with geodesic acceleration (gsl_multifit_nlinear_trs_lmaccel), More's diagonal scaling, QR.
//
// Parameters: each free parameter p in [lower, upper] is mapped to an unbounded, scaled variable u
// with p = lower + (upper - lower) / (1 + exp(-u)) (a logistic transform: bounds hold at every
// evaluation, and near the lower bound dp/du ~ p - lower, i.e. a relative scaling); fixed
// parameters keep their values. The Jacobian is by forward differences in u, all perturbed
// parameter sets evaluated in one batch call (the residual function takes a list of sets).
//
// At the optimum: covariance of the free parameters C = s^2 (J_p^T J_p)^-1 with J_p the Jacobian
// with respect to the physical parameters (chain rule through the transform) and
// s^2 = sum r^2 / (N - P) the residual variance; standard errors sqrt(C_ii); correlations
// C_ij / sqrt(C_ii C_jj).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace impact::pointdriver::fit {

struct Parameter {
  std::string name;
  double value = 0.0;  ///< start value (physical units)
  bool free = true;
  double lower = 0.0;
  double upper = 1.0;
};

struct LeastSquaresOptions {
  int max_iterations = 200;
  double xtol = 1e-10;  ///< GSL's step test
  double gtol = 1e-12;  ///< GSL's gradient test
  double ftol = 1e-14;
  double fd_step = 1e-6;  ///< forward-difference step in u (times max(1, |u|))
};

/// Residual vectors for several full parameter vectors at once (every entry of every set,
/// fixed ones included): one call is one batch of driver runs.
using BatchResidual =
    std::function<std::vector<Eigen::VectorXd>(const std::vector<std::vector<double>>& sets)>;

struct LeastSquaresResult {
  std::vector<double> values;      ///< all parameters at the optimum
  std::vector<double> std_errors;  ///< 0 for fixed parameters
  Eigen::MatrixXd correlation;     ///< all parameters (fixed rows and columns 0, diagonal 1)
  Eigen::MatrixXd covariance;      ///< all parameters (fixed rows and columns 0)
  Eigen::VectorXd residual;        ///< at the optimum
  int iterations = 0;
  int residual_evaluations = 0;  ///< parameter sets evaluated (f, Jacobian and fvv together)
  int batch_calls = 0;
  double chi2 = 0.0;       ///< sum of squared residuals
  double variance = 0.0;   ///< chi2 / (N - P)
  double wall_time = 0.0;  ///< [s]
  int status = 0;          ///< GSL status of the driver
  std::string stop_reason;
};

/// Minimises sum r(p)^2 over the free parameters. Throws std::invalid_argument when a start value
/// lies outside its bounds or there are fewer residuals than free parameters.
LeastSquaresResult least_squares(const std::vector<Parameter>& parameters,
                                 const BatchResidual& residual,
                                 const LeastSquaresOptions& options = {});

}  // namespace impact::pointdriver::fit
