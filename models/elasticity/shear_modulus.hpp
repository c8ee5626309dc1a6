// The shear modulus mu(T, p, rho) of the elastic response, chosen by a material's
// constitutive_model.shear_modulus {"type": ...}; the material's top-level shear_modulus is mu0.
// Evaluated once per step at the start-of-step temperature, pressure and density; the trial
// stress, the radial return, the wave speed (the time step) and the stability checks use it.
//   constant                 mu = mu0 (the default: the report's model).
//   varshni                  mu = mu0 - D / (exp(T0 / T) - 1): Varshni (1970), Phys. Rev. B
//                            2:3952, eq. (3), the form of the Mechanical Threshold Stress model
//                            (Chen & Gray 1996, Follansbee & Kocks 1988).
//   steinberg_cochran_guinan mu = mu0 [1 + (G'_p/mu0) p / eta^(1/3) + (G'_T/mu0)(T - 300 K)]:
//                            Steinberg, Cochran & Guinan (1980), J. Appl. Phys. 51:1498, eq. (2).
//   nadal_le_poac            mu = [(mu0 + G'_p p / eta^(1/3))(1 - T^) + rho k_B T / (C m)] / J(T^),
//                            J(T^) = 1 + exp(-(1 + 1/zeta) / (1 + zeta / (1 - T^))), T^ = T/T_m:
//                            Nadal & Le Poac (2003), J. Appl. Phys. 93:2472, eq. (9)-(10); m the
//                            mass of an atom.
// eta = rho / rho0, p positive in compression. Every form is floored at 0 (above a form's range of
// validity: no shear stiffness, as molten).
#pragma once

#include <string_view>
#include <variant>
#include <vector>

#include "models/core/catalogue.hpp"
#include "models/core/input.hpp"

namespace impact {

struct ModulusConditions {
  double temperature = 294.0;       ///< T [K]
  double pressure = 0.0;            ///< p [Pa]
  double compression = 1.0;         ///< eta = rho / rho0 [-]
  double density = 0.0;             ///< rho [kg/m^3]
  double melt_temperature = 925.0;  ///< T_m [K] (nadal_le_poac)
};

struct ConstantShearModulus {
  static constexpr std::string_view kType = "constant";
  static constexpr NoParameters<ConstantShearModulus> kParameters{};
};
struct VarshniShearModulus {
  static constexpr std::string_view kType = "varshni";
  double D = 0.0;   ///< [Pa]
  double T0 = 0.0;  ///< [K]
  static constexpr LawParameter<VarshniShearModulus> kParameters[] = {
      {"D", "Pa", &VarshniShearModulus::D}, {"T0", "K", &VarshniShearModulus::T0}};
};
struct SteinbergShearModulus {
  static constexpr std::string_view kType = "steinberg_cochran_guinan";
  double dG_dp = 0.0;  ///< G'_p [-]
  double dG_dT = 0.0;  ///< G'_T [Pa/K]
  static constexpr LawParameter<SteinbergShearModulus> kParameters[] = {
      {"dG_dp", "-", &SteinbergShearModulus::dG_dp},
      {"dG_dT", "Pa/K", &SteinbergShearModulus::dG_dT}};
};
struct NadalLePoacShearModulus {
  static constexpr std::string_view kType = "nadal_le_poac";
  double dG_dp = 0.0;       ///< [-]
  double zeta = 0.0;        ///< [-]
  double C = 0.0;           ///< [-]
  double molar_mass = 0.0;  ///< [kg/mol]
  static constexpr LawParameter<NadalLePoacShearModulus> kParameters[] = {
      {"dG_dp", "-", &NadalLePoacShearModulus::dG_dp},
      {"zeta", "-", &NadalLePoacShearModulus::zeta},
      {"C", "-", &NadalLePoacShearModulus::C},
      {"molar_mass", "kg/mol", &NadalLePoacShearModulus::molar_mass}};
};

/// The catalogue, one line per form (the first is the default); models/core/catalogue.hpp gives
/// the forms' parameters by name.
using ShearModulusLaw = std::variant<ConstantShearModulus, VarshniShearModulus,
                                     SteinbergShearModulus, NadalLePoacShearModulus>;

/// mu [Pa] of `law` with mu0 [Pa] under the conditions.
double shear_modulus(const ShearModulusLaw& law, double mu0, const ModulusConditions& c);

/// mu [Pa] (shear_modulus(), the same expression) and d mu / d T [Pa/K] at fixed pressure and
/// density, for a law that scales its stresses by mu (the Mechanical Threshold Stress law's
/// optional shear_modulus block): 0 where mu is floored.
struct ModulusWithSlope {
  double mu = 0.0;   ///< [Pa]
  double d_T = 0.0;  ///< [Pa/K]
};
ModulusWithSlope shear_modulus_with_slope(const ShearModulusLaw& law, double mu0,
                                          const ModulusConditions& c);
bool is_constant(const ShearModulusLaw& law);

/// Reads {"type", ...} (the block is optional: constant).
ShearModulusLaw read_shear_modulus(JsonReader& r);
/// {"type", every parameter}: what read_shear_modulus reads back.
Json to_json(const ShearModulusLaw& law);

}  // namespace impact
