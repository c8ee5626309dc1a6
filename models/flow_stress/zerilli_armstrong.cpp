#include "models/flow_stress/zerilli_armstrong.hpp"

#include <cmath>
#include <limits>

namespace impact {

FlowStress flow_stress(const ZerilliArmstrongParams& p, double ep, double rate,
                       const FlowConditions& c) {
  const double T = c.temperature;
  const bool slow = rate < p.minimum_strain_rate;
  const double rate_star = (slow ? p.minimum_strain_rate : rate) / p.reference_strain_rate;
  // exp(-C3 T + C4 T ln rate*): the thermally activated part, and what multiplies it.
  const double activation = std::exp(-p.C3 * T + p.C4 * T * std::log(rate_star));
  const double root = std::sqrt(ep);
  const double thermal = p.C1 + p.C2 * root;
  const double ep_n = p.C5 > 0.0 ? std::pow(ep, p.n) : 0.0;
  constexpr double inf = std::numeric_limits<double>::infinity();
  FlowStress f;
  f.value = p.C0 + thermal * activation + p.C5 * ep_n;
  // d/d ep: C2 exp(...) / (2 sqrt ep) + C5 n ep^(n-1), unbounded at ep = 0 (n < 1).
  double slope = 0.0;
  if (p.C2 > 0.0 && activation > 0.0) slope += ep > 0.0 ? 0.5 * p.C2 * activation / root : inf;
  if (p.C5 > 0.0) {
    slope += ep > 0.0 ? p.C5 * p.n * ep_n / ep : (p.n < 1.0 ? inf : (p.n == 1.0 ? p.C5 : 0.0));
  }
  f.d_plastic_strain = slope;
  f.d_rate = slow ? 0.0 : thermal * activation * p.C4 * T / rate;
  f.d_temperature = thermal * activation * (-p.C3 + p.C4 * std::log(rate_star));
  return f;
}

ZerilliArmstrongParams read_law(JsonReader& r, const ZerilliArmstrongParams*, double, double) {
  ZerilliArmstrongParams p;
  r.ignore("type");
  const std::string form =
      r.choice("form", {"fcc", "bcc"}, "Zerilli-Armstrong form (crystal structure)");
  p.form = form == "bcc" ? ZerilliArmstrongForm::bcc : ZerilliArmstrongForm::fcc;
  p.C0 = r.quantity("C0", Quantity::stress, Range::non_negative(),
                    "Zerilli-Armstrong athermal and grain-size stress C0 [Pa]");
  if (p.form == ZerilliArmstrongForm::fcc) {
    p.C2 = r.quantity("C2", Quantity::stress, Range::positive(),
                      "Zerilli-Armstrong fcc hardening coefficient C2 [Pa]");
  } else {
    p.C1 = r.quantity("C1", Quantity::stress, Range::non_negative(),
                      "Zerilli-Armstrong bcc thermal stress C1 [Pa]");
    p.C5 = r.quantity("C5", Quantity::stress, Range::non_negative(),
                      "Zerilli-Armstrong bcc hardening coefficient C5 [Pa]");
    p.n = r.number("n", Range::open_closed(0.0, 1.5), "Zerilli-Armstrong bcc exponent n [-]");
  }
  p.C3 = r.number("C3", Range::closed(0.0, 1.0), "Zerilli-Armstrong thermal softening C3 [1/K]");
  p.C4 = r.number("C4", Range::closed(0.0, 1.0), "Zerilli-Armstrong rate sensitivity C4 [1/K]");
  p.reference_strain_rate = r.number_or("reference_strain_rate", 1.0, Range::positive(),
                                        "the rate the law's ln(rate) is taken against [1/s]");
  p.minimum_strain_rate = r.number_or("minimum_strain_rate", 1e-6, Range::positive(),
                                      "slowest rate the law is evaluated at [1/s]");
  r.reject_unknown_keys();
  return p;
}

Json to_json(const ZerilliArmstrongParams& p) {
  Json j = {{"type", ZerilliArmstrongParams::kType},
            {"form", p.form == ZerilliArmstrongForm::bcc ? "bcc" : "fcc"},
            {"C0", p.C0}};
  if (p.form == ZerilliArmstrongForm::fcc) {
    j["C2"] = p.C2;
  } else {
    j["C1"] = p.C1;
    j["C5"] = p.C5;
    j["n"] = p.n;
  }
  j["C3"] = p.C3;
  j["C4"] = p.C4;
  j["reference_strain_rate"] = p.reference_strain_rate;
  j["minimum_strain_rate"] = p.minimum_strain_rate;
  return j;
}

}  // namespace impact
