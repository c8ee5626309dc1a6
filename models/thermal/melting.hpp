// Melting (report sec. 3, option do_melting; docs/report_code.md sec. 10): at or above the
// melting temperature a point keeps no deviatoric stress; the equation of state still gives the
// pressure, so sigma -> (tr sigma / 3) I.
// "Melted" is T >= T_m: the Johnson-Cook thermal factor 1 - T*^m is zero from there on, so the
// point has no strength either way. The 2004 code used T > T_m or sigma_y <= 0, which is the same
// set of states for Johnson-Cook; its heating cap kept T <= T_m, so heating alone could never melt
// a point (strict >); with >= a point heated exactly to T_m counts as melted.
#pragma once

#include "models/core/input.hpp"
#include "models/core/tensor.hpp"

namespace impact {

struct MeltingParams {
  bool do_melting = true;  ///< remove the deviator of melted points
};

/// T >= T_m (both [K]).
inline bool is_melted(double temperature, double melt_temperature) {
  return temperature >= melt_temperature;
}

/// The stress of a melted point: deviator removed, mean stress kept.
inline Mat3 melt_stress(const Mat3& stress) {
  return mean(stress) * Mat3::Identity();
}

/// Reads {"do_melting"} (optional).
MeltingParams read_melting(JsonReader& r);

}  // namespace impact
