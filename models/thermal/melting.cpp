#include "models/thermal/melting.hpp"

namespace impact {

MeltingParams read_melting(JsonReader& r) {
  MeltingParams p;
  p.do_melting = r.boolean_or("do_melting", p.do_melting,
                              "remove the deviatoric stress of points at or above T_melt");
  const std::string curve =
      r.choice("curve", {"constant", "steinberg_cochran_guinan"},
               "melting temperature: constant or SCG's Lindemann curve", "constant");
  if (curve == "steinberg_cochran_guinan") {
    p.curve = MeltingCurve::steinberg_cochran_guinan;
    p.gamma0 = r.number("gamma0", Range::open(0.0, 10.0), "SCG melting: Gruneisen Gamma0 [-]");
    p.a = r.number("a", Range::closed(0.0, 10.0), "SCG melting: volume correction a [-]");
  }
  r.reject_unknown_keys();
  return p;
}

}  // namespace impact
