#include "models/flow_stress/cowper_symonds.hpp"

#include <cmath>
#include <limits>

namespace impact {

FlowStress flow_stress(const CowperSymondsParams& p, double ep, double rate,
                       const FlowConditions&) {
  const bool slow = rate < p.minimum_strain_rate;
  const double r = slow ? p.minimum_strain_rate : rate;
  const double excess = std::pow(r / p.D, 1.0 / p.q);  // (rate / D)^(1/q)
  const double ratio = 1.0 + excess;                   // dynamic over static yield
  const double strain = p.eps0 + ep;
  const double hardening = p.K * std::pow(strain, p.n);  // Swift: K (eps0 + ep)^n
  FlowStress f;
  f.value = hardening * ratio;
  // d/d ep: K n (eps0 + ep)^(n-1), unbounded at eps0 + ep = 0 with n < 1.
  f.d_plastic_strain = p.n == 0.0   ? 0.0
                       : strain > 0 ? p.n * hardening / strain * ratio
                                    : std::numeric_limits<double>::infinity();
  f.d_rate = slow ? 0.0 : hardening * excess / (p.q * r);
  f.d_temperature = 0.0;
  return f;
}

CowperSymondsParams read_law(JsonReader& r, const CowperSymondsParams*, double, double) {
  CowperSymondsParams p;
  r.ignore("type");
  p.K = r.quantity("K", Quantity::stress, Range::positive(), "Swift strength coefficient K [Pa]");
  p.n = r.number("n", Range::closed(0.0, 1.0), "Swift hardening exponent n [-]");
  // With hardening, eps0 sets the first yield K eps0^n: zero would yield at zero stress.
  p.eps0 = p.n > 0.0 ? r.number("eps0", Range::open_closed(0.0, 1.0),
                                "Swift pre-strain eps0 [-] (> 0 when n > 0: yield is K eps0^n)")
                     : r.number_or("eps0", 0.0, Range::closed(0.0, 1.0), "Swift pre-strain [-]");
  p.D = r.number("D", Range::positive(), "Cowper-Symonds rate constant D [1/s]");
  p.q = r.number("q", Range::closed(1.0, 20.0), "Cowper-Symonds exponent q [-]");
  p.minimum_strain_rate = r.number_or("minimum_strain_rate", 1e-6, Range::positive(),
                                      "slowest rate the law is evaluated at [1/s]");
  r.reject_unknown_keys();
  return p;
}

Json to_json(const CowperSymondsParams& p) {
  return parameters_to_json(p);
}

}  // namespace impact
