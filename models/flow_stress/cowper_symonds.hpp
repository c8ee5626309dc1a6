// Swift hardening with Cowper-Symonds rate scaling, the strength of the crash and structural-
// impact codes (LS-DYNA's power-law and piecewise plasticity with its rate parameters C = D,
// P = q):
//   sigma_y = K (eps0 + ep)^n [1 + (rate / D)^(1/q)],
// the hardening of Swift (1952), J. Mech. Phys. Solids 1:1-18, eq. (1), times the dynamic
// over static yield ratio of Cowper & Symonds (1957), Brown University Tech. Rep. 28, as Jones
// (1989), Structural Impact, eq. (8.4), writes it; their mild steel: D = 40.4 /s, q = 5
// (Bodner & Symonds' aluminium alloy: D = 6500 /s, q = 4). n = 0 gives a rate-dependent
// perfectly plastic law with sigma_0 = K. The law has no temperature dependence (the material's
// melting still applies). The ratio's slope is unbounded as the rate goes to zero (1/q < 1), so
// steps slower than minimum_strain_rate use that rate (default 1e-6 /s), with no rate slope.
#pragma once

#include "models/core/input.hpp"
#include "models/flow_stress/flow_stress.hpp"

namespace impact {

struct CowperSymondsParams {
  double K = 0.0;                     ///< strength coefficient [Pa]
  double eps0 = 0.0;                  ///< Swift's pre-strain [-] (> 0 when n > 0)
  double n = 0.0;                     ///< hardening exponent [-]
  double D = 0.0;                     ///< Cowper-Symonds rate constant [1/s]
  double q = 1.0;                     ///< Cowper-Symonds exponent [-]
  double minimum_strain_rate = 1e-6;  ///< [1/s]

  static constexpr std::string_view kType = "cowper_symonds";
  static constexpr LawParameter<CowperSymondsParams> kParameters[] = {
      {"K", "Pa", &CowperSymondsParams::K, {1e6, 1e10}},
      {"eps0", "-", &CowperSymondsParams::eps0, {1e-6, 0.5}},
      {"n", "-", &CowperSymondsParams::n, {0.0, 1.0}},
      {"D", "1/s", &CowperSymondsParams::D, {1e-2, 1e8}},
      {"q", "-", &CowperSymondsParams::q, {1.0, 20.0}},
      {"minimum_strain_rate", "1/s", &CowperSymondsParams::minimum_strain_rate}};
};

/// sigma_y(ep, rate) and its derivatives; ep >= 0, rate >= 0 [1/s].
FlowStress flow_stress(const CowperSymondsParams& p, double plastic_strain,
                       double plastic_strain_rate, const FlowConditions& c);

/// Reads {"K", "eps0", "n", "D", "q", "minimum_strain_rate"}.
CowperSymondsParams read_law(JsonReader& r, const CowperSymondsParams*, double room_temperature,
                             double melt_temperature);
Json to_json(const CowperSymondsParams& p);

}  // namespace impact
