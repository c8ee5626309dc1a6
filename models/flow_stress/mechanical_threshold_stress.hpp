// Mechanical Threshold Stress (MTS) flow stress: Follansbee & Kocks (1988), Acta Metall.
// 36(1):81-93, in the form of Banerjee (2007), Int. J. Solids Struct. 44:834-859, eqs. (4)-(12):
//   sigma_y = sigma_a + (S_i sigma_i + S_e sigma_e) mu(T) / mu_0                        (eq. 4)
//   S_k = [1 - (k_B T / (g_0k b^3 mu(T)) ln(eps0_k / rate))^(1/q_k)]^(1/p_k), k = i, e   (eq. 5-6)
//   mu(T) = mu_0 - D / (exp(T_0 / T) - 1)                           (Varshni 1970, eq. 10)
// sigma_a: athermal stress; sigma_i: the intrinsic (Peierls) barrier, thermally activated by S_i;
// sigma_e: the structure-evolution stress, the law's internal variable, thermally activated by S_e
// and grown by Voce-tanh hardening (Follansbee & Kocks eq. 12; Banerjee eq. 8-9):
//   d sigma_e / d ep = theta_0 [1 - tanh(alpha X) / tanh(alpha)],  X = sigma_e / sigma_es,
//   theta_0 = a_0 + a_1 ln(rate) + a_2 sqrt(rate) - a_3 T,
//   sigma_es = sigma_es0 (rate / eps0_es)^(k_B T / (g_0es b^3 mu(T))).
// The internal variable is carried by the point (PointState::flow_internal, starting at 0: an
// annealed state) and integrated consistently with the return: over a step from ep_n with
// sigma_e,n, sigma_e(ep) = sigma_e,n + theta(sigma_e,n, rate, T_n) (ep - ep_n), the same expression
// in the flow stress the radial return solves and in the state it writes (internal_after), so the
// next step starts on the surface the return ended on. Rates below minimum_strain_rate are taken
// at it (the logarithms diverge); an activation term beyond its barrier gives S = 0. T in K; the
// law has its own shear modulus mu(T) (the elasticity's model is not read).
#pragma once

#include "models/core/input.hpp"
#include "models/flow_stress/flow_stress.hpp"

namespace impact {

struct MechanicalThresholdStressParams {
  double sigma_a = 0.0;               ///< athermal stress [Pa]
  double sigma_i = 0.0;               ///< intrinsic barrier stress [Pa] (0 for fcc metals)
  double g0_i = 1.0;                  ///< its normalised activation energy [-]
  double eps0_i = 1e13;               ///< its reference rate [1/s]
  double p_i = 0.5;                   ///< barrier-profile exponents [-]
  double q_i = 1.5;                   ///< [-]
  double g0_e = 1.6;                  ///< structure-evolution normalised activation energy [-]
  double eps0_e = 1e7;                ///< its reference rate [1/s]
  double p_e = 2.0 / 3.0;             ///< [-]
  double q_e = 1.0;                   ///< [-]
  double a0 = 0.0;                    ///< theta_0 = a0 + a1 ln(rate) + a2 sqrt(rate) - a3 T [Pa]
  double a1 = 0.0;                    ///< [Pa]
  double a2 = 0.0;                    ///< [Pa s^(1/2)]
  double a3 = 0.0;                    ///< [Pa/K]
  double alpha = 2.0;                 ///< shape of the tanh hardening [-]
  double sigma_es0 = 0.0;             ///< saturation stress at 0 K [Pa]
  double g0_es = 1.0;                 ///< its normalised activation energy [-]
  double eps0_es = 1e7;               ///< its reference rate [1/s]
  double burgers = 2.5e-10;           ///< Burgers vector b [m]
  double mu0 = 0.0;                   ///< shear modulus at 0 K [Pa]
  double D = 0.0;                     ///< Varshni's D [Pa]
  double T0 = 0.0;                    ///< Varshni's T_0 [K]
  double minimum_strain_rate = 1e-6;  ///< [1/s]

  static constexpr std::string_view kType = "mechanical_threshold_stress";
  static constexpr LawParameter<MechanicalThresholdStressParams> kParameters[] = {
      {"sigma_a", "Pa", &MechanicalThresholdStressParams::sigma_a, {0.0, 2e9}},
      {"sigma_i", "Pa", &MechanicalThresholdStressParams::sigma_i, {0.0, 1e10}},
      {"g0_i", "-", &MechanicalThresholdStressParams::g0_i, {1e-3, 10.0}},
      {"eps0_i", "1/s", &MechanicalThresholdStressParams::eps0_i},
      {"p_i", "-", &MechanicalThresholdStressParams::p_i},
      {"q_i", "-", &MechanicalThresholdStressParams::q_i},
      {"g0_e", "-", &MechanicalThresholdStressParams::g0_e, {1e-3, 10.0}},
      {"eps0_e", "1/s", &MechanicalThresholdStressParams::eps0_e},
      {"p_e", "-", &MechanicalThresholdStressParams::p_e},
      {"q_e", "-", &MechanicalThresholdStressParams::q_e},
      {"a0", "Pa", &MechanicalThresholdStressParams::a0, {0.0, 1e11}},
      {"a1", "Pa", &MechanicalThresholdStressParams::a1},
      {"a2", "Pa s^0.5", &MechanicalThresholdStressParams::a2},
      {"a3", "Pa/K", &MechanicalThresholdStressParams::a3},
      {"alpha", "-", &MechanicalThresholdStressParams::alpha, {1e-3, 10.0}},
      {"sigma_es0", "Pa", &MechanicalThresholdStressParams::sigma_es0, {1e6, 1e10}},
      {"g0_es", "-", &MechanicalThresholdStressParams::g0_es, {1e-3, 10.0}},
      {"eps0_es", "1/s", &MechanicalThresholdStressParams::eps0_es},
      {"burgers", "m", &MechanicalThresholdStressParams::burgers},
      {"mu0", "Pa", &MechanicalThresholdStressParams::mu0},
      {"D", "Pa", &MechanicalThresholdStressParams::D},
      {"T0", "K", &MechanicalThresholdStressParams::T0},
      {"minimum_strain_rate", "1/s", &MechanicalThresholdStressParams::minimum_strain_rate}};
};

/// sigma_y(ep, rate, T) and its derivatives, with sigma_e advanced from the step's start
/// (c.start_plastic_strain, c.internal) to ep; ep >= start, rate >= 0 [1/s].
FlowStress flow_stress(const MechanicalThresholdStressParams& p, double plastic_strain,
                       double plastic_strain_rate, const FlowConditions& c);

/// sigma_e after a plastic increment d_ep at `rate` from sigma_e = `internal` (the expression the
/// flow stress uses) [Pa].
double internal_after(const MechanicalThresholdStressParams& p, double internal, double d_ep,
                      double plastic_strain_rate, const FlowConditions& c);

/// The pieces of the law at one rate and temperature (for the tests and the documentation).
struct MtsFactors {
  double mu = 0.0;        ///< mu(T) [Pa]
  double S_i = 0.0;       ///< [-]
  double S_e = 0.0;       ///< [-]
  double theta0 = 0.0;    ///< [Pa]
  double sigma_es = 0.0;  ///< [Pa]
};
MtsFactors mts_factors(const MechanicalThresholdStressParams& p, double rate, double T);

/// Reads every parameter above ("minimum_strain_rate" optional, default 1e-6 /s).
MechanicalThresholdStressParams read_law(JsonReader& r, const MechanicalThresholdStressParams*,
                                         double room_temperature, double melt_temperature);
Json to_json(const MechanicalThresholdStressParams& p);

}  // namespace impact
