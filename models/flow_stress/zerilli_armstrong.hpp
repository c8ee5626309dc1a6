// Zerilli-Armstrong flow stress: Zerilli & Armstrong (1987), J. Appl. Phys. 61(5):1816-1825,
// eq. (14) for fcc and eq. (17) for bcc metals, written as one law:
//   sigma_y = C0 + (C1 + C2 ep^(1/2)) exp(-C3 T + C4 T ln rate*) + C5 ep^n,
//   rate* = max(rate, minimum_strain_rate) / reference_strain_rate.
// fcc (copper, aluminium, nickel): dislocation interactions make the thermal activation depend on
// strain, C1 = C5 = 0. bcc (iron, tantalum): the Peierls barrier is strain independent, C2 = 0.
// C0 = Delta sigma_G' + k l^(-1/2): the athermal stress and the Hall-Petch grain-size term.
// The paper's rate is in 1/s (reference_strain_rate = 1 /s). The law has no rate-independent
// limit: its thermal term vanishes as the rate goes to zero, so the static yield check and steps
// slower than minimum_strain_rate use that rate (default 1e-6 /s; below it the law was never
// fitted). T [K] is absolute; the law has no melting of its own (the material's melting applies).
#pragma once

#include "models/core/input.hpp"
#include "models/flow_stress/flow_stress.hpp"

namespace impact {

enum class ZerilliArmstrongForm { fcc, bcc };

struct ZerilliArmstrongParams {
  ZerilliArmstrongForm form = ZerilliArmstrongForm::fcc;
  double C0 = 0.0;                     ///< athermal + grain-size stress [Pa]
  double C1 = 0.0;                     ///< bcc: thermal (Peierls) stress [Pa]
  double C2 = 0.0;                     ///< fcc: thermal hardening coefficient [Pa]
  double C3 = 0.0;                     ///< [1/K]
  double C4 = 0.0;                     ///< [1/K]
  double C5 = 0.0;                     ///< bcc: athermal hardening coefficient [Pa]
  double n = 0.0;                      ///< bcc: hardening exponent [-] (fcc: unused, 0)
  double reference_strain_rate = 1.0;  ///< [1/s]
  double minimum_strain_rate = 1e-6;   ///< [1/s]

  static constexpr std::string_view kType = "zerilli_armstrong";
  static constexpr LawParameter<ZerilliArmstrongParams> kParameters[] = {
      {"C0", "Pa", &ZerilliArmstrongParams::C0, {0.0, 5e9}},
      {"C1", "Pa", &ZerilliArmstrongParams::C1, {0.0, 2e10}},
      {"C2", "Pa", &ZerilliArmstrongParams::C2, {0.0, 2e10}},
      {"C3", "1/K", &ZerilliArmstrongParams::C3, {0.0, 0.05}},
      {"C4", "1/K", &ZerilliArmstrongParams::C4, {0.0, 0.01}},
      {"C5", "Pa", &ZerilliArmstrongParams::C5, {0.0, 5e9}},
      {"n", "-", &ZerilliArmstrongParams::n, {0.01, 2.0}},
      {"reference_strain_rate", "1/s", &ZerilliArmstrongParams::reference_strain_rate},
      {"minimum_strain_rate", "1/s", &ZerilliArmstrongParams::minimum_strain_rate}};
};

/// sigma_y(ep, rate, T) and its derivatives; ep >= 0, rate >= 0 [1/s].
FlowStress flow_stress(const ZerilliArmstrongParams& p, double plastic_strain,
                       double plastic_strain_rate, const FlowConditions& c);

/// Reads {"form": "fcc" | "bcc", "C0", "C2" (fcc) or "C1", "C5", "n" (bcc), "C3", "C4",
/// "reference_strain_rate", "minimum_strain_rate"}.
ZerilliArmstrongParams read_law(JsonReader& r, const ZerilliArmstrongParams*,
                                double room_temperature, double melt_temperature);
Json to_json(const ZerilliArmstrongParams& p);

}  // namespace impact
