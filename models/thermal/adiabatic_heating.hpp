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
//
// Internal energy and temperature (docs/theory.md sec. 5): e is the specific internal energy above
// the point's initial state, T its temperature. Heat that a point retains raises both, e by h and
// T by h / c_p, so that e - e_v = c_p (T - T_0) at every step, e_v = -int p dv the work of the
// pressure. Heating on (`enabled`) means adiabatic: the point retains the heat of its dissipation
// (the Taylor-Quinney share of the plastic work, and in the MPM solver the artificial viscosity's
// work and the friction heat of contact); off means isothermal: that heat leaves the point and
// neither e nor T changes by it.
#pragma once

#include "models/core/input.hpp"
#include "models/core/point_state.hpp"

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

/// Retains heat [J/kg] at a point by the rule above: e += h and T += h / c_p when `retained`
/// (heating on), nothing otherwise.
inline void retain_heat(PointState& s, double heat_per_mass, bool retained, double specific_heat) {
  if (!retained) return;
  s.internal_energy += heat_per_mass;
  s.temperature += heat_per_mass / specific_heat;
}

/// Reads {"enabled", "taylor_quinney"}; both optional.
AdiabaticHeatingParams read_adiabatic_heating(JsonReader& r);

}  // namespace impact
