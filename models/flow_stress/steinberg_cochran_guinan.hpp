// Steinberg-Cochran-Guinan flow stress: Steinberg, Cochran & Guinan (1980), J. Appl. Phys.
// 51(3):1498-1504, eq. (2)-(3), the rate-independent form for high strain rates (above ~1e5 /s,
// where the paper's data lie):
//   sigma_y = min(Y0 [1 + beta (ep + ep_i)]^n, Y_max) G(p, T) / G0,
//   G(p, T) / G0 = 1 + (G'_p / G0) p / eta^(1/3) + (G'_T / G0)(T - 300 K),   eta = rho / rho0,
// with p the pressure (compression positive) and T in K; the strength scales with the shear
// modulus, which rises with pressure and falls with temperature (the paper's 300 K reference).
// The modulus ratio is floored at 0 (no strength, like a molten point). The material's melting
// (models/thermal/melting.hpp) applies on top.
// rate_form "steinberg_lund" (Steinberg & Lund 1989, J. Appl. Phys. 65:1528, eq. (1)-(4)) adds
// the thermally activated (Peierls) stress Y_T for rates below ~1e5 /s:
//   sigma_y = [Y_T(rate, T) + min(Y0 [1 + beta (ep + ep_i)]^n, Y_max)] G(p, T) / G0,
//   rate = [ (1/C1) exp((2 U_k / (k_B T)) (1 - Y_T / Y_P)^2) + C2 / Y_T ]^(-1),   Y_T <= Y_P,
// with Y0 then the athermal stress Y_A; Y_T is the root of that equation (unique: its right side
// rises monotonically with Y_T), Y_P when even Y_P flows slower than the rate, 0 at rest. Its
// slopes in rate and T come from differentiating the equation implicitly.
#pragma once

#include "models/core/input.hpp"
#include "models/flow_stress/flow_stress.hpp"

namespace impact {

enum class SteinbergRateForm { rate_independent, steinberg_lund };

struct SteinbergCochranGuinanParams {
  SteinbergRateForm rate_form = SteinbergRateForm::rate_independent;
  double Y0 = 0.0;                       ///< yield stress at p = 0, T = 300 K [Pa]
  double Y_max = 0.0;                    ///< work-hardening cap [Pa]
  double beta = 0.0;                     ///< hardening coefficient [-]
  double n = 0.1;                        ///< hardening exponent [-]
  double initial_plastic_strain = 0.0;   ///< ep_i [-]
  double G0 = 0.0;                       ///< shear modulus at p = 0, T = 300 K [Pa]
  double dG_dp = 0.0;                    ///< G'_p = dG/dp [-]
  double dG_dT = 0.0;                    ///< G'_T = dG/dT [Pa/K] (negative)
  double reference_temperature = 300.0;  ///< the paper's reference [K]
  // Steinberg-Lund only:
  double C1 = 0.0;   ///< [1/s]
  double U_k = 0.0;  ///< kink-pair energy [J] (the paper gives eV)
  double Y_P = 0.0;  ///< Peierls stress [Pa]
  double C2 = 0.0;   ///< drag coefficient [Pa s]

  static constexpr std::string_view kType = "steinberg_cochran_guinan";
  static constexpr LawParameter<SteinbergCochranGuinanParams> kParameters[] = {
      {"Y0", "Pa", &SteinbergCochranGuinanParams::Y0, {1e6, 5e9}},
      {"Y_max", "Pa", &SteinbergCochranGuinanParams::Y_max, {1e6, 2e10}},
      {"beta", "-", &SteinbergCochranGuinanParams::beta, {0.0, 1e4}},
      {"n", "-", &SteinbergCochranGuinanParams::n, {0.01, 2.0}},
      {"initial_plastic_strain", "-", &SteinbergCochranGuinanParams::initial_plastic_strain},
      {"G0", "Pa", &SteinbergCochranGuinanParams::G0},
      {"dG_dp", "-", &SteinbergCochranGuinanParams::dG_dp},
      {"dG_dT", "Pa/K", &SteinbergCochranGuinanParams::dG_dT},
      {"C1", "1/s", &SteinbergCochranGuinanParams::C1},
      {"U_k", "J", &SteinbergCochranGuinanParams::U_k},
      {"Y_P", "Pa", &SteinbergCochranGuinanParams::Y_P},
      {"C2", "Pa s", &SteinbergCochranGuinanParams::C2}};
};

/// Steinberg-Lund's thermal stress Y_T [Pa] at the rate [1/s] and T [K], with its slopes.
struct ThermalStress {
  double value = 0.0, d_rate = 0.0, d_temperature = 0.0;
};
ThermalStress steinberg_lund_thermal_stress(const SteinbergCochranGuinanParams& p, double rate,
                                            double temperature);

/// G(p, T) / G0 of the law, floored at 0; `conditions`: p, T and eta.
double modulus_ratio(const SteinbergCochranGuinanParams& p, const FlowConditions& c);

FlowStress flow_stress(const SteinbergCochranGuinanParams& p, double plastic_strain,
                       double plastic_strain_rate, const FlowConditions& c);

/// Reads {"Y0", "Y_max", "beta", "n", "initial_plastic_strain", "G0", "dG_dp", "dG_dT",
/// "rate_form": "rate_independent" | "steinberg_lund" with "C1", "U_k", "Y_P", "C2"}.
SteinbergCochranGuinanParams read_law(JsonReader& r, const SteinbergCochranGuinanParams*,
                                      double room_temperature, double melt_temperature);
Json to_json(const SteinbergCochranGuinanParams& p);

}  // namespace impact
