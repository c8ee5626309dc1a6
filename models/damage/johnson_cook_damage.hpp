// Johnson-Cook damage: Johnson & Cook (1985), Eng. Fract. Mech. 21:31-48; report eq. (7):
//   dD = d_ep / eps_f,
//   eps_f = [D1 + D2 exp(D3 sigma*)] [1 + D4 ln(max(rate / rate0, 1))] [1 + D5 T*],
//   sigma* = sigma_m / sigma_eq (stress triaxiality), T* = clamp((T - T_room)/(T_melt - T_room), 0,
//   1).
// The report prints exp(D3/3 sigma*) with sigma* = tr(sigma)/sigma_eq: D3 (tr sigma / 3)/sigma_eq
// is the same thing; here sigma* is the usual triaxiality (uniaxial tension 1/3). Differences from
// the 2004 code (docs/report_code.md sec. 5), all deliberate:
//  - rate is normalised by reference_strain_rate (2004: the raw rate in 1/s) and floored at the
//    reference rate like the flow stress, so the factor is continuous and never below 1 + 0;
//  - T* is clamped to [0, 1] (2004: unclamped; its adiabatic-heating bug started the model's
//    temperature at 0 K, T* = -294/631 = -0.47, so 1 + D5 T* = 0.25 cut eps_f to 25 %);
//  - eps_f is floored at min_fracture_strain (2004: eps_f <= 0 returned the old damage, so with the
//    6061-T6 constants damage STOPPED growing for sigma* > ln(-D1/D2)/D3 = 1.347, i.e. in strong
//    hydrostatic tension -- physically backwards; with the floor it grows fastest there);
//  - sigma* is not clamped to [-1.5, 1.5] and there is no "spall" shortcut D = 1 at sigma* > 8:
//    the floor already makes damage grow fastest at high triaxiality, and compression only raises
//    eps_f (D3 < 0), which is the model's intent.
// Optional cut-off (not in the report): Bao & Wierzbicki (2005), "On the cut-off value of negative
// triaxiality for fracture", Eng. Fract. Mech. 72:1049-1069, found no fracture at or below
// sigma* = -1/3 in their upsetting tests; with `cutoff_triaxiality` a plastic increment at or below
// it adds no damage, so a compressed core (a Taylor rod's) does not fail on strain alone. The
// cut-off is inclusive to round-off (cutoff_tolerance): -1/3 is uniaxial compression itself, whose
// computed sigma* lands a few ulp on either side of -1/3 depending on the frame.
// T_room and T_melt are the material's (one source of truth with the flow stress).
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "models/core/catalogue.hpp"
#include "models/core/input.hpp"
#include "models/core/tensor.hpp"

namespace impact {

struct JohnsonCookDamageParams {
  double D1 = 0.0;                     ///< [-]
  double D2 = 0.0;                     ///< [-]
  double D3 = 0.0;                     ///< triaxiality exponent [-]
  double D4 = 0.0;                     ///< strain-rate coefficient [-]
  double D5 = 0.0;                     ///< temperature coefficient [-]
  double reference_strain_rate = 1.0;  ///< rate0 [1/s]
  double min_fracture_strain = 1e-3;   ///< floor on eps_f [-]
  /// At and below this triaxiality (to cutoff_tolerance) no damage accumulates (Bao & Wierzbicki
  /// 2005 place the cut-off at -1/3); absent: damage grows at every triaxiality (the report's
  /// eq. 7).
  std::optional<double> cutoff_triaxiality;
  double room_temperature = 294.0;  ///< [K]
  double melt_temperature = 925.0;  ///< [K]

  static constexpr std::string_view kType = "johnson_cook";
  static constexpr LawParameter<JohnsonCookDamageParams> kParameters[] = {
      {"D1", "-", &JohnsonCookDamageParams::D1},
      {"D2", "-", &JohnsonCookDamageParams::D2},
      {"D3", "-", &JohnsonCookDamageParams::D3},
      {"D4", "-", &JohnsonCookDamageParams::D4},
      {"D5", "-", &JohnsonCookDamageParams::D5},
      {"reference_strain_rate", "1/s", &JohnsonCookDamageParams::reference_strain_rate},
      {"min_fracture_strain", "-", &JohnsonCookDamageParams::min_fracture_strain}};
};

/// The round-off band above the cut-off that still counts as at it: 8 eps (1 + |cutoff|), eps =
/// 2^-52. sigma_m and sigma_eq carry errors of a few eps of the stress scale max(|sigma_m|,
/// sigma_eq), so sigma* = sigma_m / sigma_eq is off by a few eps (1 + |sigma*|): randomly rotated
/// uniaxial compressions give -1/3 to within 0.75 eps (1e6 frames). 2.4e-15 at -1/3.
inline double cutoff_tolerance(double cutoff) {
  return 8.0 * std::numeric_limits<double>::epsilon() * (1.0 + std::abs(cutoff));
}

/// Fracture strain eps_f(sigma*, rate, T) >= min_fracture_strain; rate [1/s], T [K].
double jc_fracture_strain(const JohnsonCookDamageParams& p, double triaxiality,
                          double plastic_strain_rate, double temperature);

/// Stress triaxiality sigma_m / sigma_eq (tension positive). Returns 0 when sigma_eq == 0: a purely
/// hydrostatic state cannot be plastic, so no damage increment uses this value (it only labels the
/// state); returning 0 instead of +-inf keeps outputs finite.
double triaxiality(const Mat3& stress);

/// Damage increment d_ep / eps_f for a plastic-strain increment d_ep >= 0 taken at the given
/// triaxiality, plastic strain rate [1/s] and temperature [K]; 0 at or below cutoff_triaxiality
/// (+ cutoff_tolerance).
double jc_damage_increment(const JohnsonCookDamageParams& p, double delta_plastic_strain,
                           double triaxiality, double plastic_strain_rate, double temperature);

/// Reads {"D1".."D5", "reference_strain_rate", "min_fracture_strain", "cutoff_triaxiality"}
/// ("type" is the caller's);
/// temperatures are the material's.
JohnsonCookDamageParams read_johnson_cook_damage(JsonReader& r, double room_temperature,
                                                 double melt_temperature);
/// The catalogue's reader (models/damage/damage_law.hpp): read_johnson_cook_damage.
inline JohnsonCookDamageParams read_model(JsonReader& r, const JohnsonCookDamageParams*,
                                          double room_temperature, double melt_temperature) {
  return read_johnson_cook_damage(r, room_temperature, melt_temperature);
}
/// {"type", the parameters, "cutoff_triaxiality" when set}: what the reader reads back.
Json to_json(const JohnsonCookDamageParams& p);

/// The damage a plastic increment d_ep adds at this stress (the catalogue's hook,
/// models/damage/damage_law.hpp): jc_damage_increment at the stress's triaxiality.
inline double damage_increment(const JohnsonCookDamageParams& p, double delta_plastic_strain,
                               const Mat3& stress, double plastic_strain_rate, double temperature) {
  return jc_damage_increment(p, delta_plastic_strain, triaxiality(stress), plastic_strain_rate,
                             temperature);
}

}  // namespace impact
