// Melting (report sec. 3, option do_melting; docs/report_code.md sec. 10): at or above the
// melting temperature a point keeps no deviatoric stress; the equation of state still gives the
// pressure, so sigma -> (tr sigma / 3) I.
// "Melted" is T >= T_m: the Johnson-Cook thermal factor 1 - T*^m is zero from there on, so the
// point has no strength either way. The 2004 code used T > T_m or sigma_y <= 0, which is the same
// set of states for Johnson-Cook; its heating cap kept T <= T_m, so heating alone could never melt
// a point (strict >); with >= a point heated exactly to T_m counts as melted.
//
// The melting temperature: the material's melt_temperature T_m0 (curve "constant", the default),
// or the Steinberg-Cochran-Guinan curve (Steinberg, Cochran & Guinan 1980, J. Appl. Phys.
// 51:1498, eq. (5)), Lindemann's law with a Gruneisen parameter Gamma = Gamma0 - a (1 - 1/eta):
//   T_m(eta) = T_m0 exp(2 a (1 - 1/eta)) eta^(2 (Gamma0 - a - 1/3)),   eta = rho / rho0,
// so compression raises the melting point. It is evaluated at the start-of-step density, with the
// start-of-step temperature.
#pragma once

#include <cmath>

#include "models/core/input.hpp"
#include "models/core/tensor.hpp"

namespace impact {

enum class MeltingCurve { constant, steinberg_cochran_guinan };

struct MeltingParams {
  bool do_melting = true;  ///< remove the deviator of melted points
  MeltingCurve curve = MeltingCurve::constant;
  double gamma0 = 0.0;  ///< SCG curve: Gruneisen parameter at rho0 [-]
  double a = 0.0;       ///< SCG curve: first-order volume correction to Gamma [-]
};

/// T_m [K] at compression eta = rho / rho0 [-]; `reference` is the material's T_m0 [K].
inline double melting_temperature(const MeltingParams& p, double reference, double compression) {
  if (p.curve == MeltingCurve::constant) return reference;
  return reference * std::exp(2.0 * p.a * (1.0 - 1.0 / compression)) *
         std::pow(compression, 2.0 * (p.gamma0 - p.a - 1.0 / 3.0));
}

/// T >= T_m (both [K]).
inline bool is_melted(double temperature, double melt_temperature) {
  return temperature >= melt_temperature;
}

/// The stress of a melted point: deviator removed, mean stress kept.
inline Mat3 melt_stress(const Mat3& stress) {
  return mean(stress) * Mat3::Identity();
}

/// Reads {"do_melting", "curve": "constant" | "steinberg_cochran_guinan", "gamma0", "a"} (all
/// optional; gamma0 and a required by the SCG curve).
MeltingParams read_melting(JsonReader& r);

}  // namespace impact
