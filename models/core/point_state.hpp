// The history one material point carries from step to step: a plain struct, copied by value, so the
// update reads the start-of-step state s0 and writes the end-of-step state s1 (MFront's split).
#pragma once

#include <cstdint>

#include "models/core/tensor.hpp"

namespace impact {

/// Which criterion failed a point (report sec. 3), kept with the point so that a run can say, per
/// particle, why it failed (docs/models.md#failure-causes-and-failure-in-compression).
enum class FailureCause : std::uint8_t { none, melting, tepla, drucker, becker };

/// Bits of PointState::instability: a stability check fired at a plastic step but, with
/// stability_check.outcome = "report", did not fail the point.
inline constexpr std::uint8_t kDruckerFired = 1;
inline constexpr std::uint8_t kBeckerFired = 2;

struct PointState {
  Mat3 stress = Mat3::Zero();   ///< Cauchy stress in the lab frame [Pa], tension positive
  Mat3 F = Mat3::Identity();    ///< deformation gradient [-]
  Mat3 R = Mat3::Identity();    ///< rotation of F = R U, kept so a step needs one decomposition
  double plastic_strain = 0.0;  ///< equivalent plastic strain [-]
  double plastic_strain_rate = 0.0;  ///< equivalent plastic strain rate of the last step [1/s]
  double temperature = 294.0;        ///< [K]
  double internal_energy = 0.0;      ///< specific internal energy above the reference state [J/kg]
  double damage = 0.0;               ///< Johnson-Cook damage D [-]
  double porosity = 0.0;             ///< void volume fraction f [-]
  /// The flow-stress law's internal variable, for a law that has one (Mechanical Threshold
  /// Stress: the structure-evolution stress sigma_e [Pa]); 0 at the start, unused otherwise.
  double flow_internal = 0.0;
  bool melted = false;  ///< T reached the melting temperature this step
  bool failed = false;  ///< localized by TEPLA, melting or a stability check (sticky)
  FailureCause failure_cause = FailureCause::none;  ///< what failed it (sticky with `failed`)
  std::uint8_t instability = 0;  ///< kDruckerFired | kBeckerFired, reported only (sticky)
  /// The mean stress was tensile at the step that failed the point (before erosion): a spall-like
  /// failure, as opposed to one under pressure (sticky with `failed`).
  bool failed_in_tension = false;
};

}  // namespace impact
