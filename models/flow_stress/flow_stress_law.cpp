#include "models/flow_stress/flow_stress_law.hpp"

namespace impact {

FlowStressLaw read_flow_stress(JsonReader& r, double room_temperature, double melt_temperature) {
  const std::string type = r.choice("type", law_types(), "flow stress model");
  // An unknown type (a problem recorded): the default.
  return read_by_type<FlowStressLaw>(
             type,
             [&](const auto* tag) { return read_law(r, tag, room_temperature, melt_temperature); })
      .value_or(FlowStressLaw{});
}

}  // namespace impact
