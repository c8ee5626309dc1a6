#include "models/flow_stress/johnson_cook.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact {

JohnsonCookThermal johnson_cook_thermal(const JohnsonCookParams& p, double temperature) {
  const double t_star = homologous_temperature(temperature, p.room_temperature, p.melt_temperature);
  JohnsonCookThermal th;
  if (t_star >= 1.0) {
    th.factor = 0.0;
  } else if (t_star > 0.0) {
    const double t_m = std::pow(t_star, p.m);
    th.factor = 1.0 - t_m;
    th.d_factor = -p.m * t_m / t_star / (p.melt_temperature - p.room_temperature);
  }
  return th;
}

FlowStress johnson_cook(const JohnsonCookParams& p, double plastic_strain,
                        double plastic_strain_rate, double temperature) {
  return johnson_cook(p, plastic_strain, plastic_strain_rate, johnson_cook_thermal(p, temperature));
}

JohnsonCookParams read_johnson_cook(JsonReader& r, double room_temperature,
                                    double melt_temperature) {
  JohnsonCookParams p;
  r.ignore("type");
  p.A = r.quantity("A", Quantity::stress, Range::positive(), "Johnson-Cook yield stress A [Pa]");
  p.B = r.quantity("B", Quantity::stress, Range::non_negative(),
                   "Johnson-Cook hardening modulus B [Pa]");
  p.n = r.number("n", Range::open_closed(0.0, 1.5), "Johnson-Cook hardening exponent n [-]");
  p.C = r.number("C", Range::closed(0.0, 1.0), "Johnson-Cook strain-rate coefficient C [-]");
  p.m = r.number("m", Range::open(0.0, 10.0), "Johnson-Cook thermal-softening exponent m [-]");
  p.reference_strain_rate = r.number_or("reference_strain_rate", 1.0, Range::positive(),
                                        "reference plastic strain rate [1/s]");
  const std::string form = r.choice("rate_form", {"clamped", "report_2004"},
                                    "rate factor below the reference rate", "clamped");
  p.rate_form =
      form == "report_2004" ? JohnsonCookRateForm::report_2004 : JohnsonCookRateForm::clamped;
  p.room_temperature = room_temperature;
  p.melt_temperature = melt_temperature;
  r.reject_unknown_keys();
  return p;
}

Json to_json(const JohnsonCookParams& f) {
  return {{"type", JohnsonCookParams::kType},
          {"A", f.A},
          {"B", f.B},
          {"n", f.n},
          {"C", f.C},
          {"m", f.m},
          {"reference_strain_rate", f.reference_strain_rate},
          {"rate_form", f.rate_form == JohnsonCookRateForm::clamped ? "clamped" : "report_2004"}};
}

}  // namespace impact
