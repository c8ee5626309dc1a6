// Adiabatic heating by plastic dissipation: Taylor & Quinney (1934), Proc. R. Soc. Lond. A
// 143:307-326 (and Farren & Taylor 1925); report eq. (8):
//   Delta T = chi sigma:D^p dt / (rho c_p) = chi sigma_y Delta eps_p / (rho c_p),
// chi the Taylor-Quinney coefficient (fraction of plastic work turned into heat). The second form
// holds for associated J2 flow: D^p = eps_dot_p (3/2) s / sigma_eq, so sigma:D^p = sigma_eq
// eps_dot_p, and sigma_eq = sigma_y on the yield surface. Adiabatic within a step (no conduction).
// Difference from the report: its eq. (8) prints sigma:D with the TOTAL rate of deformation and the
// 2004 code used the total stress power chi sigma:D / (rho c_p) (clipped at >= 0), which heats
// under purely elastic loading and under hydrostatic compression too. Only plastic dissipation
// heats here; elastic work is stored, and is returned on unloading.
#pragma once

#include "models/core/input.hpp"

namespace impact {

struct AdiabaticHeatingParams {
  bool enabled = true;          ///< heat by plastic work
  double taylor_quinney = 0.9;  ///< chi [-]
};

/// Delta T [K] = chi sigma_y d_ep / (rho c_p); flow stress [Pa], density [kg/m^3], c_p [J/(kg K)].
inline double adiabatic_temperature_rise(double taylor_quinney, double flow_stress,
                                         double delta_plastic_strain, double density,
                                         double specific_heat) {
  return taylor_quinney * flow_stress * delta_plastic_strain / (density * specific_heat);
}

/// Reads {"enabled", "taylor_quinney"}; both optional.
AdiabaticHeatingParams read_adiabatic_heating(JsonReader& r);

}  // namespace impact
