#include "models/thermal/melting.hpp"

namespace impact {

MeltingParams read_melting(JsonReader& r) {
  MeltingParams p;
  p.do_melting = r.boolean_or("do_melting", p.do_melting,
                              "remove the deviatoric stress of points at or above T_melt");
  r.reject_unknown_keys();
  return p;
}

}  // namespace impact
