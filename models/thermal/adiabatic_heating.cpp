#include "models/thermal/adiabatic_heating.hpp"

namespace impact {

AdiabaticHeatingParams read_adiabatic_heating(JsonReader& r) {
  AdiabaticHeatingParams p;
  p.enabled =
      r.boolean_or("enabled", p.enabled, "heat by the Taylor-Quinney share of plastic work");
  p.taylor_quinney = r.number_or("taylor_quinney", p.taylor_quinney, Range::closed(0.0, 1.0),
                                 "Taylor-Quinney coefficient chi [-]");
  r.reject_unknown_keys();
  return p;
}

}  // namespace impact
