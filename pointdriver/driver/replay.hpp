// A replay file: when a step cannot be solved even after the cut-backs, the driver writes the
// state at the start of that step and the step's controls as a path file; running it reproduces
// the failure in one step (MFront's GenerateMTestFileOnFailure, MGIS integrate_debug).
#pragma once

#include "pointdriver/driver/mixed_control.hpp"
#include "pointdriver/path/path.hpp"

namespace impact::pointdriver {

/// The failed step of `leg` (leg time t_leg, length dt) from state `s0` (lab frame) and
/// superposed rotation `Q`, as a one-leg path document.
Json replay_path(const Path& path, const Leg& leg, const ControlPlan& plan, const PointState& s0,
                 const Mat3& Q, double t_leg, double dt, double end_temperature,
                 double rotation_rate);

/// A 3x3 tensor as {"xx": .., "xy": .., ...} (row-major names of path.hpp).
Json tensor_json(const Mat3& a);

/// The six symmetric components {"xx", "yy", "zz", "xy", "yz", "zx"}.
Json stress_json(const Mat3& a);

}  // namespace impact::pointdriver
