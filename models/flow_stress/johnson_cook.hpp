// Johnson-Cook flow stress: Johnson & Cook (1983), Proc. 7th Int. Symp. Ballistics, 541-547;
// report eq. (5):
//   sigma_y = [A + B ep^n] [rate factor] [1 - T*^m],   T* = (T - T_room)/(T_melt - T_room).
// Rate factor (rate* = rate / reference_strain_rate):
//   clamped (default):  1 + C ln(max(rate*, 1))   -- rates below the reference give no softening,
//                       continuous at rate* = 1 (as MFront's and LS-DYNA's JC do);
//   report_2004:        (1 + rate*)^C for rate* < 1, 1 + C ln rate* otherwise (the report's code;
//                       it jumps by 2^C - 1 = +0.14 % at rate* = 1 for C = 0.002).
// Temperature factor: 1 for T* <= 0 (no hardening below room temperature: JC was fitted above it),
// 0 for T* >= 1 (molten: no deviatoric strength; melting is flagged by thermal/melting).
// T_room and T_melt come from the material (one source of truth), not from this block.
#pragma once

#include "models/core/input.hpp"

namespace impact {

enum class JohnsonCookRateForm { clamped, report_2004 };

struct JohnsonCookParams {
  double A = 0.0;                      ///< yield stress [Pa]
  double B = 0.0;                      ///< hardening modulus [Pa]
  double n = 1.0;                      ///< hardening exponent [-]
  double C = 0.0;                      ///< strain-rate coefficient [-]
  double m = 1.0;                      ///< thermal-softening exponent [-]
  double reference_strain_rate = 1.0;  ///< [1/s]
  double room_temperature = 294.0;     ///< [K]
  double melt_temperature = 925.0;     ///< [K]
  JohnsonCookRateForm rate_form = JohnsonCookRateForm::clamped;
};

/// Flow stress with its partial derivatives, as the return mapping and the stability tangent need.
struct FlowStress {
  double value = 0.0;             ///< sigma_y [Pa]
  double d_plastic_strain = 0.0;  ///< d sigma_y / d ep [Pa]; +inf at ep = 0 when n < 1
  double d_rate = 0.0;            ///< d sigma_y / d rate [Pa s]
  double d_temperature = 0.0;     ///< d sigma_y / d T [Pa/K]
};

/// The temperature factor 1 - T*^m and its slope d/dT [1/K]. A return mapping at fixed
/// temperature evaluates it once instead of once per Newton step (it holds a pow).
struct JohnsonCookThermal {
  double factor = 1.0;
  double d_factor = 0.0;
};
JohnsonCookThermal johnson_cook_thermal(const JohnsonCookParams& p, double temperature);

/// sigma_y(ep, rate, T) and its derivatives; ep >= 0, rate >= 0 [1/s], T [K].
FlowStress johnson_cook(const JohnsonCookParams& p, double plastic_strain,
                        double plastic_strain_rate, double temperature);

/// The same with the temperature factor evaluated beforehand (johnson_cook_thermal).
FlowStress johnson_cook(const JohnsonCookParams& p, double plastic_strain,
                        double plastic_strain_rate, const JohnsonCookThermal& thermal);

/// An upper bound of the radial return's plastic-strain increment d (models/plasticity/
/// radial_return.hpp) for a trial stress `overshoot` [Pa] above sigma_y(ep, 0, T): the smaller of
/// the increment the strain hardening alone and the one the rate factor alone would need to raise
/// the flow stress by the overshoot. Both are bounds because every factor of the law is >= its
/// static value: sigma_y(ep + d, d/dt) - sigma_y(ep, 0) >= B ((ep + d)^n - ep^n) theta and
/// >= (A + B ep^n) (rate factor - 1) theta. +inf when neither applies (B = 0 and C = 0, or molten);
/// 0 when the hardening bound is below the smallest double.
double johnson_cook_increment_bound(const JohnsonCookParams& p, const JohnsonCookThermal& thermal,
                                    double plastic_strain, double overshoot, double dt);

/// The law at one temperature, as the radial return calls it: flow(ep, rate) and the increment's
/// upper bound (models/plasticity/radial_return.hpp, BoundedFlow).
struct JohnsonCookAtTemperature {
  const JohnsonCookParams& params;
  JohnsonCookThermal thermal;
  FlowStress operator()(double plastic_strain, double plastic_strain_rate) const {
    return johnson_cook(params, plastic_strain, plastic_strain_rate, thermal);
  }
  double increment_bound(double plastic_strain, double overshoot, double dt) const {
    return johnson_cook_increment_bound(params, thermal, plastic_strain, overshoot, dt);
  }
};

/// Homologous temperature T* = (T - T_room)/(T_melt - T_room), unclamped.
inline double homologous_temperature(double temperature, double room, double melt) {
  return (temperature - room) / (melt - room);
}

/// Reads {"A", "B", "n", "C", "m", "reference_strain_rate", "rate_form"}; temperatures are the
/// material's.
JohnsonCookParams read_johnson_cook(JsonReader& r, double room_temperature,
                                    double melt_temperature);

}  // namespace impact
