// What every flow-stress law shares: the result (the flow stress and its partial derivatives, as
// the radial return and the stability tangent need them), the conditions a law may read besides
// the plastic strain and its rate, and the description of a law's parameters by name (what the
// fitter and the checker reach them by; models/flow_stress/flow_stress_law.hpp).
#pragma once

#include <string>
#include <string_view>

#include "models/core/input.hpp"

namespace impact {

/// Flow stress with its partial derivatives, for one point (FlowStress) or a vector of points
/// (BasicFlowStress<lane::Vec>, the batched Johnson-Cook return).
template <class V>
struct BasicFlowStress {
  V value{};             ///< sigma_y [Pa]
  V d_plastic_strain{};  ///< d sigma_y / d ep [Pa]; +inf at ep = 0 when the hardening's slope is
  V d_rate{};            ///< d sigma_y / d rate [Pa s]
  V d_temperature{};     ///< d sigma_y / d T [Pa/K]
};
using FlowStress = BasicFlowStress<double>;

/// What a law may read besides the plastic strain and its rate, fixed over one step's return:
/// the start-of-step temperature and pressure, and the compression rho / rho0 at the end of the
/// step (Steinberg-Cochran-Guinan's pressure-dependent modulus, Preston-Tonks-Wallace's density).
struct FlowConditions {
  double temperature = 294.0;  ///< T [K]
  double pressure = 0.0;       ///< p [Pa], positive in compression
  double compression = 1.0;    ///< rho / rho0 [-]
  double density = 0.0;        ///< rho [kg/m^3]
  /// For a law with an internal variable (PointState::flow_internal): the plastic strain and the
  /// variable at the start of the step, from which the law advances it to the ep it is asked at.
  double start_plastic_strain = 0.0;  ///< [-]
  double internal = 0.0;              ///< the law's own unit (MTS: sigma_e [Pa])
  /// T_m [K] of the material's melting curve (models/thermal/melting.hpp) at the start-of-step
  /// density, the one the melting check uses: Preston-Tonks-Wallace's T^ = T / T_m. 0 (a caller
  /// outside a material): the law's own melt_temperature.
  double melt_temperature = 0.0;
};

/// The range a fitter searches for a parameter by default [SI]. Empty (lower == upper, the
/// default): not a strength parameter to fit (a reference rate, a molar mass, a modulus the law
/// shares with elasticity); a fit configuration may still free it with bounds of its own.
struct FitBounds {
  double lower = 0.0;
  double upper = 0.0;
  bool empty() const { return !(upper > lower); }
};

/// One named parameter of a law: the JSON key, its unit (SI), the member it lives in and the
/// fitter's default bounds. A law lists them in `kParameters`; `pointdriver fit` varies them by
/// name.
template <class Law>
struct LawParameter {
  std::string_view name;
  std::string_view unit;
  double Law::*member;
  FitBounds fit{};
};

/// {"type": kType, every kParameters entry by name}: the writer of a law whose keys are exactly
/// its parameters (its reader then reads them back).
template <class Law>
Json parameters_to_json(const Law& law) {
  Json j = {{"type", Law::kType}};
  for (const auto& q : Law::kParameters) j[std::string(q.name)] = law.*q.member;
  return j;
}

}  // namespace impact
