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

ThermalStress steinberg_lund_thermal_stress(const SteinbergCochranGuinanParams& p, double rate,
                                            double temperature) {
  constexpr double k_B = 1.380649e-23;  // [J/K]
  ThermalStress y;
  if (rate <= 0.0) {  // at rest: Y_T -> C2 rate, no thermal stress
    y.d_rate = p.C2;
    return y;
  }
  const double K = 2.0 * p.U_k / (k_B * temperature);
  // h(Y) = 1/rate - (1/C1) exp(K (1 - Y/Y_P)^2) - C2/Y rises with Y on (0, Y_P].
  const auto waiting = [&](double Y) {  // (1/C1) exp(K x^2), x = 1 - Y/Y_P (inf beyond range)
    const double x = 1.0 - Y / p.Y_P;
    return std::exp(std::min(K * x * x, 700.0)) / p.C1;
  };
  const auto h = [&](double Y) { return 1.0 / rate - waiting(Y) - p.C2 / Y; };
  if (h(p.Y_P) <= 0.0) {  // even the Peierls stress flows no faster than the rate: capped
    y.value = p.Y_P;
    return y;
  }
  double lo = 0.0, hi = p.Y_P;  // h(lo+) < 0 < h(hi)
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (h(mid) < 0.0 ? lo : hi) = mid;
  }
  const double Y = 0.5 * (lo + hi);
  const double x = 1.0 - Y / p.Y_P;
  const double w = waiting(Y);
  const double h_Y = w * 2.0 * K * x / p.Y_P + p.C2 / (Y * Y);
  y.value = Y;
  y.d_rate = 1.0 / (rate * rate) / h_Y;                    // h_rate = -1/rate^2
  y.d_temperature = -(w * x * x * K / temperature) / h_Y;  // h_T = (1/C1) e^(K x^2) x^2 K / T
  return y;
}

FlowStress flow_stress(const SteinbergCochranGuinanParams& p, double ep, double rate,
                       const FlowConditions& c) {
  const double base = 1.0 + p.beta * (ep + p.initial_plastic_strain);
  const double hardened = p.Y0 * std::pow(base, p.n);
  const bool capped = hardened >= p.Y_max;
  const double athermal = std::min(hardened, p.Y_max);
  const ThermalStress thermal = p.rate_form == SteinbergRateForm::steinberg_lund
                                    ? steinberg_lund_thermal_stress(p, rate, c.temperature)
                                    : ThermalStress{};
  const double ratio = modulus_ratio(p, c);
  FlowStress f;
  f.value = (thermal.value + athermal) * ratio;
  f.d_plastic_strain = capped ? 0.0 : p.n * p.beta * hardened / base * ratio;
  f.d_rate = thermal.d_rate * ratio;
  f.d_temperature = thermal.d_temperature * ratio +
                    (ratio > 0.0 ? (thermal.value + athermal) * p.dG_dT / p.G0 : 0.0);
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
  const std::string form = r.choice("rate_form", {"rate_independent", "steinberg_lund"},
                                    "SCG rate form", "rate_independent");
  if (form == "steinberg_lund") {
    p.rate_form = SteinbergRateForm::steinberg_lund;
    p.C1 = r.number("C1", Range::positive(), "Steinberg-Lund rate constant C1 [1/s]");
    p.U_k = r.number("U_k", Range::open(0.0, 1e-17),
                     "Steinberg-Lund kink-pair energy U_k [J] (1 eV = 1.602176634e-19 J)");
    p.Y_P = r.quantity("Y_P", Quantity::stress, Range::positive(),
                       "Steinberg-Lund Peierls stress Y_P [Pa]");
    p.C2 = r.number("C2", Range::non_negative(), "Steinberg-Lund drag coefficient C2 [Pa s]");
  }
  r.reject_unknown_keys();
  if (p.Y_max < p.Y0) {
    r.problems().add(r.key_path("Y_max"), "expected a stress >= Y0 = " + std::to_string(p.Y0) +
                                              " Pa (the cap of the hardening), got " +
                                              std::to_string(p.Y_max));
  }
  return p;
}

Json to_json(const SteinbergCochranGuinanParams& p) {
  Json j = {{"type", SteinbergCochranGuinanParams::kType},
            {"Y0", p.Y0},
            {"Y_max", p.Y_max},
            {"beta", p.beta},
            {"n", p.n},
            {"initial_plastic_strain", p.initial_plastic_strain},
            {"G0", p.G0},
            {"dG_dp", p.dG_dp},
            {"dG_dT", p.dG_dT}};
  if (p.rate_form == SteinbergRateForm::steinberg_lund) {
    j["rate_form"] = "steinberg_lund";
    j["C1"] = p.C1;
    j["U_k"] = p.U_k;
    j["Y_P"] = p.Y_P;
    j["C2"] = p.C2;
  }
  return j;
}

}  // namespace impact
