// Runs a path: leg by leg, step by step, each step solved by mixed control (mixed_control.hpp),
// cut back on non-convergence, with temperature held, computed (report eq. 8) or prescribed, a
// superposed rigid rotation, the failure policy, and the energy bookkeeping. Rows go to a sink
// (CSV writer, verification case, fitting residual) as they are made.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "pointdriver/driver/mixed_control.hpp"
#include "pointdriver/path/path.hpp"

namespace impact::pointdriver {

/// The state after one step, with what the CSV reports about it.
struct Row {
  double time = 0.0;  ///< [s]
  int step = 0;
  int leg = 0;
  Mat3 F = Mat3::Identity();        ///< deformation gradient in the lab frame [-]
  Mat3 L = Mat3::Zero();            ///< velocity gradient of the step in the lab frame [1/s]
  Mat3 Q = Mat3::Identity();        ///< superposed rotation [-]
  PointState state;                 ///< stress (lab frame) and history
  Mat3 stress_path = Mat3::Zero();  ///< Q^T sigma Q: stress in the unrotated (path) frame [Pa]
  double tepla_indicator = 0.0;     ///< (f/f_c)^2 + D^2 [-]
  double melting_indicator = 0.0;   ///< T / T_m [-]
  double drucker_indicator = 0.0;   ///< sigma_dot : D^p [Pa/s^2] (0 when the check did not run)
  double becker_indicator = 1.0;    ///< det A_ep / det A_e [-] (1 when the check did not run)
  bool drucker_checked = false;
  FailureCause failure = FailureCause::none;  ///< the step on which the point failed
  double stress_work = 0.0;        ///< integral of J sigma : D dt, per reference volume [J/m^3]
  double dissipated_energy = 0.0;  ///< plastic work, per reference volume [J/m^3]
  int iterations = 0;              ///< Newton iterations of the step (summed over sub-steps)
  int jacobian_evaluations = 0;    ///< fresh Newton matrices computed in the step
  int substeps = 1;                ///< 1, or 2^k after k cut-backs
};

/// How a run ended.
struct RunResult {
  bool completed = false;  ///< reached the end of the last leg (or stopped by the policy)
  int steps = 0;
  double end_time = 0.0;                      ///< [s]
  FailureCause failure = FailureCause::none;  ///< the material's failure, if any
  double failure_time = -1.0;                 ///< [s]
  std::string error;           ///< why a step could not be solved (with completed == false)
  std::optional<Json> replay;  ///< a path reproducing the failed step
};

using RowSink = std::function<void(const Row&)>;

/// Runs `path` with its own material. The initial row (time 0) is sent first.
RunResult run_path(const Path& path, const RowSink& sink);

/// As above with another material (batch runs and fitting: N parameter sets x M paths).
RunResult run_path(const Path& path, const ElasticPlastic& model, const RowSink& sink);

}  // namespace impact::pointdriver
