// Mechanical Threshold Stress (MTS) flow stress: Follansbee & Kocks (1988), Acta Metall.
// 36(1):81-93, in the form of Banerjee (2007), Int. J. Solids Struct. 44:834-859, eqs. (4)-(12):
//   sigma_y = sigma_a + (S_i sigma_i + S_e sigma_e) mu / mu_0                            (eq. 4)
//   S_k = [1 - (k_B T / (g_0k b^3 mu) ln(eps0_k / rate))^(1/q_k)]^(1/p_k), k = i, e      (eq. 5-6)
// sigma_a: athermal stress; sigma_i: the intrinsic (Peierls) barrier, thermally activated by S_i;
// sigma_e: the structure-evolution stress, the law's internal variable, thermally activated by S_e
// and grown by tanh hardening with a stage IV (Follansbee & Kocks eq. 12; Banerjee eq. 8-9; Goto
// et al. 2000, Metall. Mater. Trans. A 31:1985, for HY-100):
//   d sigma_e / d ep = theta_0 (1 - F(X)) + theta_IV F(X),  F = tanh(alpha X) / tanh(alpha),
//   X = sigma_e / sigma_es,
//   theta_0  = max(a_0 + a_1 ln(rate) + a_2 sqrt(rate) - a_3 T, 0),
//   theta_IV = max(aIV_0 + aIV_1 ln(rate) + aIV_2 sqrt(rate) - aIV_3 T, 0)   (aIV_k default 0:
//              no stage IV, Follansbee & Kocks' copper),
//   sigma_es = sigma_es0 (rate / eps0_es)^(k_B T / (g_0es b^3 mu)).
// Why the clamps: theta_0 and theta_IV are polynomial fits to hardening rates measured over a
// range of rates and temperatures (Banerjee's 4340 tempers) and go negative outside it (Rc 49:
// theta_0 < 0 at 1e4 /s, 294 K). A hardening rate is the slope of a dislocation density that
// storage raises (Kocks-Mecking); a negative one would make the structure stress fall with strain
// without bound, through 0. So each is held at 0 where its fit is negative (its derivatives 0
// there), and sigma_e, a stress the dislocation density carries, is held >= 0. Where sigma_e
// exceeds a falling sigma_es (X > 1, F > 1) theta may still be negative: recovery towards the
// saturation, which the clamp on sigma_e bounds.
// The shear modulus mu scales the law; mu_0 is its value at 0 K and p = 0 (the reference of
// mu / mu_0):
//   - by default Varshni's mu(T) = mu_0 - D / (exp(T_0 / T) - 1) (Varshni 1970, Banerjee eq. 10)
//     from the law's own keys mu0, D, T0 (Follansbee & Kocks' copper, Goto et al.'s HY-100);
//   - with a nested block "shear_modulus" (the format the elasticity's constitutive_model
//     .shear_modulus reads: models/elasticity/shear_modulus.hpp), that catalogue's form, e.g.
//     Nadal & Le Poac (2003) mu(p, T), which Banerjee (2007) uses for 4340 steel,
//     evaluated at the conditions' temperature, pressure, compression, density and T_m (the
//     material's melt temperature when the conditions carry none). The formula lives there once
//     (shear_modulus_with_slope gives d mu / d T for the derivatives); D and T0 are then not
//     given (they stay in kParameters, unused, so that the fitter and the catalogue address the
//     law's numbers by name as before; the block's own numbers are the modulus', not strength
//     parameters to fit). Where mu = 0 (a form above its range: as molten) only sigma_a remains.
// The internal variable is carried by the point (PointState::flow_internal, starting at 0: an
// annealed state) and integrated consistently with the return: over a step from ep_n with
// sigma_e,n, sigma_e(ep) = max(sigma_e,n + theta(sigma_e,n, rate, T_n) (ep - ep_n), 0), the same
// expression in the flow stress the radial return solves and in the state it writes
// (internal_after), so the next step starts on the surface the return ended on. Rates below
// minimum_strain_rate are taken at it (the logarithms diverge); an activation term beyond its
// barrier gives S = 0. T in K.
#pragma once

#include <optional>

#include "models/core/input.hpp"
#include "models/elasticity/shear_modulus.hpp"
#include "models/flow_stress/flow_stress.hpp"

namespace impact {

/// Banerjee (2007, section 4.5) fits 4340 steel with one set of the temperature-sensitive
/// parameters below T_c = 1040 K (martensite, per temper) and another above it (austenite, every
/// temper): above T_c these replace the law's. The flow stress jumps at T_c, as in the paper.
struct MtsAboveCriticalTemperature {
  double T_c = 0.0;                                       ///< the switch temperature [K]
  double sigma_i = 0.0;                                   ///< [Pa]
  double g0_i = 1.0;                                      ///< [-]
  double sigma_es0 = 0.0;                                 ///< [Pa]
  double g0_es = 1.0;                                     ///< [-]
  double a0 = 0.0, a1 = 0.0, a2 = 0.0, a3 = 0.0;          ///< theta_0's, as the law's [Pa ...]
  double aIV0 = 0.0, aIV1 = 0.0, aIV2 = 0.0, aIV3 = 0.0;  ///< theta_IV's [Pa ...]
};

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
  double aIV0 = 0.0;                  ///< theta_IV, the same form (stage IV; 0: none) [Pa]
  double aIV1 = 0.0;                  ///< [Pa]
  double aIV2 = 0.0;                  ///< [Pa s^(1/2)]
  double aIV3 = 0.0;                  ///< [Pa/K]
  double alpha = 2.0;                 ///< shape of the tanh hardening [-]
  double sigma_es0 = 0.0;             ///< saturation stress at 0 K [Pa]
  double g0_es = 1.0;                 ///< its normalised activation energy [-]
  double eps0_es = 1e7;               ///< its reference rate [1/s]
  double burgers = 2.5e-10;           ///< Burgers vector b [m]
  double mu0 = 0.0;                   ///< shear modulus at 0 K [Pa]
  double D = 0.0;                     ///< Varshni's D [Pa]
  double T0 = 0.0;                    ///< Varshni's T_0 [K]
  double minimum_strain_rate = 1e-6;  ///< [1/s]
  /// The nested "shear_modulus" block's form (absent: Varshni from mu0, D, T0 above).
  std::optional<ShearModulusLaw> shear_modulus;
  double melt_temperature = 0.0;  ///< the material's T_m [K], for a form that reads T_m
  /// The nested "above_critical_temperature" block (absent: one set at every temperature).
  std::optional<MtsAboveCriticalTemperature> above_critical_temperature;

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
      {"a0", "Pa", &MechanicalThresholdStressParams::a0, {-1e11, 1e11}},
      {"a1", "Pa", &MechanicalThresholdStressParams::a1},
      {"a2", "Pa s^0.5", &MechanicalThresholdStressParams::a2},
      {"a3", "Pa/K", &MechanicalThresholdStressParams::a3},
      {"aIV0", "Pa", &MechanicalThresholdStressParams::aIV0, {-1e11, 1e11}},
      {"aIV1", "Pa", &MechanicalThresholdStressParams::aIV1},
      {"aIV2", "Pa s^0.5", &MechanicalThresholdStressParams::aIV2},
      {"aIV3", "Pa/K", &MechanicalThresholdStressParams::aIV3},
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
  double theta0 = 0.0;    ///< theta_0, clamped at 0 [Pa]
  double sigma_es = 0.0;  ///< [Pa]
  double theta_IV = 0.0;  ///< theta_IV, clamped at 0 [Pa]
};
/// At the conditions' temperature, pressure and density.
MtsFactors mts_factors(const MechanicalThresholdStressParams& p, double rate,
                       const FlowConditions& c);
/// At temperature T and no pressure (the Varshni modulus reads no more). With a nested modulus
/// that reads the density (Nadal-Le Poac's rho k_B T / (C m)), use the FlowConditions form: here
/// the density is 0 and that term is dropped.
MtsFactors mts_factors(const MechanicalThresholdStressParams& p, double rate, double T);

/// Reads every parameter above ("minimum_strain_rate" optional, default 1e-6 /s; aIV0..aIV3
/// optional, default 0; D and T0 required unless a "shear_modulus" block is given, and then
/// refused).
MechanicalThresholdStressParams read_law(JsonReader& r, const MechanicalThresholdStressParams*,
                                         double room_temperature, double melt_temperature);
Json to_json(const MechanicalThresholdStressParams& p);

}  // namespace impact
