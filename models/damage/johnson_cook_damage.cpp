#include "models/damage/johnson_cook_damage.hpp"

#include <algorithm>
#include <cmath>

namespace impact {

double jc_fracture_strain(const JohnsonCookDamageParams& p, double triaxiality,
                          double plastic_strain_rate, double temperature) {
  const double stress_factor = p.D1 + p.D2 * std::exp(p.D3 * triaxiality);
  // Rates below the reference give the reference value (as for the flow stress).
  const double rate_star = plastic_strain_rate / p.reference_strain_rate;
  const double rate_factor = 1.0 + p.D4 * std::log(std::max(rate_star, 1.0));
  // No extrapolation outside the calibrated range [T_room, T_melt].
  const double t_star = std::clamp(
      (temperature - p.room_temperature) / (p.melt_temperature - p.room_temperature), 0.0, 1.0);
  const double thermal_factor = 1.0 + p.D5 * t_star;
  const double eps_f = stress_factor * rate_factor * thermal_factor;
  // The floor replaces eps_f <= 0 (high triaxiality): damage then grows fastest there instead of
  // stopping.
  return eps_f < p.min_fracture_strain ? p.min_fracture_strain : eps_f;
}

double triaxiality(const Mat3& stress) {
  const double sigma_eq = von_mises(stress);
  return sigma_eq == 0.0 ? 0.0 : mean(stress) / sigma_eq;
}

double jc_damage_increment(const JohnsonCookDamageParams& p, double delta_plastic_strain,
                           double triaxiality, double plastic_strain_rate, double temperature) {
  if (p.cutoff_triaxiality &&
      triaxiality <= *p.cutoff_triaxiality + cutoff_tolerance(*p.cutoff_triaxiality))
    return 0.0;
  return delta_plastic_strain /
         jc_fracture_strain(p, triaxiality, plastic_strain_rate, temperature);
}

JohnsonCookDamageParams read_johnson_cook_damage(JsonReader& r, double room_temperature,
                                                 double melt_temperature) {
  JohnsonCookDamageParams p;
  r.ignore("type");
  p.D1 = r.number("D1", Range::any(), "Johnson-Cook damage constant D1 [-]");
  p.D2 = r.number("D2", Range::any(), "Johnson-Cook damage constant D2 [-]");
  p.D3 = r.number("D3", Range::any(), "Johnson-Cook damage triaxiality exponent D3 [-]");
  p.D4 = r.number("D4", Range::any(), "Johnson-Cook damage strain-rate coefficient D4 [-]");
  p.D5 = r.number("D5", Range::any(), "Johnson-Cook damage temperature coefficient D5 [-]");
  p.reference_strain_rate = r.number_or("reference_strain_rate", 1.0, Range::positive(),
                                        "reference plastic strain rate of D4 [1/s]");
  p.min_fracture_strain = r.number_or("min_fracture_strain", 1e-3, Range::positive(),
                                      "floor on the fracture strain eps_f [-]");
  if (r.has("cutoff_triaxiality")) {
    p.cutoff_triaxiality =
        r.number("cutoff_triaxiality", Range::closed(-10.0, 0.0),
                 "triaxiality at and below which no damage accumulates [-] (Bao & "
                 "Wierzbicki 2005: -1/3)");
    // Optional, with no value when absent (damage at every triaxiality, the report's eq. 7).
    r.amend_description("cutoff_triaxiality", [](KeyDescription& d) { d.default_value = ""; });
  }
  // eps_f at zero triaxiality, reference rate and room temperature is D1 + D2; a non-positive value
  // would put every point on the floor even in pure shear: surely a typo (e.g. a sign of D2).
  if (std::isfinite(p.D1) && std::isfinite(p.D2) && !(p.D1 + p.D2 > 0.0)) {
    r.problems().add(r.key_path("D2"),
                     "expected D1 + D2 > 0 (the fracture strain in pure shear at the reference "
                     "rate and room temperature)");
  }
  p.room_temperature = room_temperature;
  p.melt_temperature = melt_temperature;
  r.reject_unknown_keys();
  return p;
}

Json to_json(const JohnsonCookDamageParams& p) {
  Json j = parameters_to_json(p);
  if (p.cutoff_triaxiality) j["cutoff_triaxiality"] = *p.cutoff_triaxiality;
  return j;
}

}  // namespace impact
