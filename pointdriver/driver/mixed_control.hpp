// Mixed control of one step: find the unknown velocity-gradient components such that the
// stress-controlled components reach their targets and the F-controlled components their values.
//
// Unknowns u_m enter L = L_fixed + sum_m u_m G_m, with G_m a single component E_ij, or E_ij + E_ji
// for a stress-controlled shear pair given no spin. Residuals: sigma_c(L) - target_c [Pa] for
// stress components (sigma_c - r sigma_of for ratios), F_ij(L) - target_ij [-] for F components.
// Newton with a central-difference (or elastic) Jacobian and a backtracking line search on the
// scaled residual; convergence is tested per component against the stress tolerance [Pa] and the
// strain tolerance [-]. A step that does not converge is reported, never accepted (the caller cuts
// it back, and after the cut-back limit stops with a replay file).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "models/material/elastic_plastic.hpp"
#include "pointdriver/path/path.hpp"

namespace impact::pointdriver {

/// One equation of the mixed-control system.
struct ControlEquation {
  enum class Kind { stress, stress_ratio, deformation } kind = Kind::stress;
  int i = 0, j = 0;    ///< component
  int oi = 0, oj = 0;  ///< the component a ratio refers to
  double ratio = 0.0;
  double start = 0.0, end = 0.0;  ///< target at the leg's start and end (stress: ramped linearly)
  double target(double s) const;  ///< s in [0, 1]: fraction of the leg
};

/// The control of one leg, resolved against the state at the leg's start.
struct ControlPlan {
  Mat3 L_fixed = Mat3::Zero();   ///< prescribed velocity-gradient components [1/s]
  std::vector<Mat3> generators;  ///< unknown directions G_m
  std::vector<ControlEquation> equations;
  bool all_deformation = false;  ///< all nine F given: L is constant, no solve
};

/// Builds the plan of `leg` from the path-frame F and stress at its start.
ControlPlan make_plan(const Leg& leg, const Mat3& F_start, const Mat3& stress_start);

/// What the step solver needs besides the plan: the frame rotation and the material call.
struct StepContext {
  /// The model Newton iterates with. For a point that has not failed yet and a material whose
  /// erosion changes the stress (AllowNoTension, ZeroStress), it is the KeepStress twin of the
  /// material: failure detection is the same but the residual stays continuous, so the step on
  /// which the point fails still converges; the real model (`eroding_model`) is then applied
  /// once at the converged velocity gradient, and that failing step is accepted with the eroded
  /// stress even though it no longer meets the stress targets (the material can no longer carry
  /// them).
  const ElasticPlastic* model = nullptr;
  const ElasticPlastic* eroding_model = nullptr;
  const SolverSettings* settings = nullptr;
  Mat3 Q_mid = Mat3::Identity(), Q_new = Mat3::Identity();  ///< superposed rotation
  Mat3 spin = Mat3::Zero();  ///< Omega = Q_dot Q^T of the superposed rotation [1/s]
};

struct StepSolution {
  bool converged = false;
  int iterations = 0;
  int jacobian_evaluations = 0;      ///< fresh Newton matrices computed
  double max_stress_residual = 0.0;  ///< [Pa]
  double max_strain_residual = 0.0;  ///< [-]
  Mat3 L_path = Mat3::Zero();        ///< solved velocity gradient in the path frame
  Mat3 F_path = Mat3::Identity();    ///< F at the step's end in the path frame
  PointState state;                  ///< end-of-step state (lab frame)
  StepReport report;
  std::string message;  ///< why it did not converge
};

/// Solves one step of length dt from `s0` (lab frame) and path-frame F `F_path0`, with targets at
/// leg fraction `s_end`; `guess` is a velocity gradient to start Newton from. `jacobian`, when
/// given, is the previous step's Newton matrix: it is reused while Newton contracts by at least
/// a factor 10 per iteration and replaced by a fresh one otherwise (and on return holds the last).
StepSolution solve_step(const ControlPlan& plan, const StepContext& ctx, const PointState& s0,
                        const Mat3& F_path0, double dt, double s_end, const Mat3& guess,
                        Eigen::MatrixXd* jacobian = nullptr);

}  // namespace impact::pointdriver
