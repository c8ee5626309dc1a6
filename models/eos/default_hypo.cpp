#include "models/eos/default_hypo.hpp"

#include <string>

namespace impact {

double default_hypo_pressure(double p_old, double trace_D, double dt, double bulk_modulus,
                             double shear_modulus, const DefaultHypoParams& p) {
  // Compression (tr D < 0) raises the compression-positive pressure.
  return p_old - default_hypo_effective_bulk_modulus(bulk_modulus, shear_modulus, p) * trace_D * dt;
}

DefaultHypoParams read_default_hypo(JsonReader& r) {
  DefaultHypoParams p;
  r.ignore("type");
  const std::string modulus = r.choice(
      "modulus", {"bulk", "report_eq2_lame"},
      "pressure-rate modulus: bulk K (correct) or the report's eq. (2) K - 2 mu/3", "bulk");
  p.modulus = modulus == "report_eq2_lame" ? HypoModulus::report_eq2_lame : HypoModulus::bulk;
  r.reject_unknown_keys();
  return p;
}

Json to_json(const DefaultHypoParams& p) {
  return {{"modulus", p.modulus == HypoModulus::bulk ? "bulk" : "report_eq2_lame"}};
}

}  // namespace impact
