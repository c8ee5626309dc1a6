// Steinberg-Cochran-Guinan flow stress: Steinberg, Cochran & Guinan (1980), J. Appl. Phys.
// 51(3):1498-1504, eq. (2)-(3), the rate-independent form for high strain rates (above ~1e5 /s,
// where the paper's data lie):
//   sigma_y = min(Y0 [1 + beta (ep + ep_i)]^n, Y_max) G(p, T) / G0,
//   G(p, T) / G0 = 1 + (G'_p / G0) p / eta^(1/3) + (G'_T / G0)(T - 300 K),   eta = rho / rho0,
// with p the pressure (compression positive) and T in K; the strength scales with the shear
// modulus, which rises with pressure and falls with temperature (the paper's 300 K reference).
// The modulus ratio is floored at 0 (no strength, like a molten point). The material's melting
// (models/thermal/melting.hpp) applies on top; the law is rate independent (d_rate = 0).
#pragma once

#include "models/core/input.hpp"
#include "models/flow_stress/flow_stress.hpp"

namespace impact {

struct SteinbergCochranGuinanParams {
  double Y0 = 0.0;                       ///< yield stress at p = 0, T = 300 K [Pa]
  double Y_max = 0.0;                    ///< work-hardening cap [Pa]
  double beta = 0.0;                     ///< hardening coefficient [-]
  double n = 0.1;                        ///< hardening exponent [-]
  double initial_plastic_strain = 0.0;   ///< ep_i [-]
  double G0 = 0.0;                       ///< shear modulus at p = 0, T = 300 K [Pa]
  double dG_dp = 0.0;                    ///< G'_p = dG/dp [-]
  double dG_dT = 0.0;                    ///< G'_T = dG/dT [Pa/K] (negative)
  double reference_temperature = 300.0;  ///< the paper's reference [K]

  static constexpr std::string_view kType = "steinberg_cochran_guinan";
  static constexpr LawParameter<SteinbergCochranGuinanParams> kParameters[] = {
      {"Y0", "Pa", &SteinbergCochranGuinanParams::Y0},
      {"Y_max", "Pa", &SteinbergCochranGuinanParams::Y_max},
      {"beta", "-", &SteinbergCochranGuinanParams::beta},
      {"n", "-", &SteinbergCochranGuinanParams::n},
      {"initial_plastic_strain", "-", &SteinbergCochranGuinanParams::initial_plastic_strain},
      {"G0", "Pa", &SteinbergCochranGuinanParams::G0},
      {"dG_dp", "-", &SteinbergCochranGuinanParams::dG_dp},
      {"dG_dT", "Pa/K", &SteinbergCochranGuinanParams::dG_dT}};
};

/// G(p, T) / G0 of the law, floored at 0; `conditions`: p, T and eta.
double modulus_ratio(const SteinbergCochranGuinanParams& p, const FlowConditions& c);

FlowStress flow_stress(const SteinbergCochranGuinanParams& p, double plastic_strain,
                       double plastic_strain_rate, const FlowConditions& c);

/// Reads {"Y0", "Y_max", "beta", "n", "initial_plastic_strain", "G0", "dG_dp", "dG_dT"}.
SteinbergCochranGuinanParams read_law(JsonReader& r, const SteinbergCochranGuinanParams*,
                                      double room_temperature, double melt_temperature);
Json to_json(const SteinbergCochranGuinanParams& p);

}  // namespace impact
