#include "models/flow_stress/steinberg_cochran_guinan.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace impact {

double modulus_ratio(const SteinbergCochranGuinanParams& p, const FlowConditions& c) {
  const double ratio = 1.0 + p.dG_dp / p.G0 * c.pressure / std::cbrt(c.compression) +
                       p.dG_dT / p.G0 * (c.temperature - p.reference_temperature);
  return std::max(ratio, 0.0);
}

FlowStress flow_stress(const SteinbergCochranGuinanParams& p, double ep, double,
                       const FlowConditions& c) {
  const double base = 1.0 + p.beta * (ep + p.initial_plastic_strain);
  const double hardened = p.Y0 * std::pow(base, p.n);
  const bool capped = hardened >= p.Y_max;
  const double ratio = modulus_ratio(p, c);
  FlowStress f;
  f.value = std::min(hardened, p.Y_max) * ratio;
  f.d_plastic_strain = capped ? 0.0 : p.n * p.beta * hardened / base * ratio;
  f.d_rate = 0.0;
  f.d_temperature = ratio > 0.0 ? std::min(hardened, p.Y_max) * p.dG_dT / p.G0 : 0.0;
  return f;
}

SteinbergCochranGuinanParams read_law(JsonReader& r, const SteinbergCochranGuinanParams*, double,
                                      double) {
  SteinbergCochranGuinanParams p;
  r.ignore("type");
  p.Y0 = r.quantity("Y0", Quantity::stress, Range::positive(), "SCG yield stress Y0 [Pa]");
  p.Y_max =
      r.quantity("Y_max", Quantity::stress, Range::positive(), "SCG work-hardening cap Y_max [Pa]");
  p.beta = r.number("beta", Range::non_negative(), "SCG hardening coefficient beta [-]");
  p.n = r.number("n", Range::closed(0.0, 1.5), "SCG hardening exponent n [-]");
  p.initial_plastic_strain = r.number_or("initial_plastic_strain", 0.0, Range::non_negative(),
                                         "SCG initial plastic strain ep_i [-]");
  p.G0 = r.quantity("G0", Quantity::elastic_modulus, Range::positive(),
                    "SCG shear modulus at p = 0, T = 300 K [Pa]");
  p.dG_dp = r.number("dG_dp", Range::closed(0.0, 10.0),
                     "SCG pressure derivative of the shear modulus G'_p [-]");
  p.dG_dT = r.number("dG_dT", Range::closed(-1e9, 0.0),
                     "SCG temperature derivative of the shear modulus G'_T [Pa/K]");
  r.reject_unknown_keys();
  if (p.Y_max < p.Y0) {
    r.problems().add(r.key_path("Y_max"), "expected a stress >= Y0 = " + std::to_string(p.Y0) +
                                              " Pa (the cap of the hardening), got " +
                                              std::to_string(p.Y_max));
  }
  return p;
}

Json to_json(const SteinbergCochranGuinanParams& p) {
  return {{"type", SteinbergCochranGuinanParams::kType},
          {"Y0", p.Y0},
          {"Y_max", p.Y_max},
          {"beta", p.beta},
          {"n", p.n},
          {"initial_plastic_strain", p.initial_plastic_strain},
          {"G0", p.G0},
          {"dG_dp", p.dG_dp},
          {"dG_dT", p.dG_dT}};
}

}  // namespace impact
