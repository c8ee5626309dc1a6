// What every flow-stress law shares: the result (the flow stress and its partial derivatives, as
// the radial return and the stability tangent need them) and the conditions a law may read besides
// the plastic strain and its rate. A law's parameters by name (FitBounds, LawParameter) are every
// catalogue's (models/core/catalogue.hpp).
#pragma once

#include <string>
#include <string_view>

#include "models/core/catalogue.hpp"
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

}  // namespace impact
