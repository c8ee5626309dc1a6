// The catalogue of flow-stress laws: a material names one in constitutive_model.flow_stress
// {"type": ...}. Each law lives in its own files with
//   - its parameters struct, with kType (the JSON "type") and kParameters (name, unit, member),
//   - flow_stress(law, ep, rate, FlowConditions) -> FlowStress (value and derivatives),
//   - read_law(JsonReader&, const Law*, room_temperature, melt_temperature) and to_json(law),
// and one line in FlowStressLaw below (the machinery is every catalogue's:
// models/core/catalogue.hpp). Everything else (the material reader and writer, the radial return,
// the point driver's fitter and checker, the MPM solver) reaches a law through the functions here,
// by type name and parameter name. docs/extending.md walks through adding one.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "models/flow_stress/cowper_symonds.hpp"
#include "models/flow_stress/flow_stress.hpp"
#include "models/flow_stress/johnson_cook.hpp"
#include "models/flow_stress/mechanical_threshold_stress.hpp"
#include "models/flow_stress/preston_tonks_wallace.hpp"
#include "models/flow_stress/steinberg_cochran_guinan.hpp"
#include "models/flow_stress/zerilli_armstrong.hpp"

namespace impact {

/// Every flow-stress law, one line each (the first is the default of an empty material).
using FlowStressLaw =
    std::variant<JohnsonCookParams, ZerilliArmstrongParams, SteinbergCochranGuinanParams,
                 PrestonTonksWallaceParams, MechanicalThresholdStressParams, CowperSymondsParams>;

/// sigma_y(ep, rate, conditions) and its derivatives, whichever law.
inline FlowStress flow_stress(const FlowStressLaw& law, double plastic_strain,
                              double plastic_strain_rate, const FlowConditions& c) {
  return std::visit(
      [&](const auto& l) { return flow_stress(l, plastic_strain, plastic_strain_rate, c); }, law);
}

/// The law's internal variable (PointState::flow_internal) after a plastic increment d_ep at
/// `rate` from `internal`: a law with one defines internal_after(law, internal, d_ep, rate, c)
/// beside its flow_stress, the same expression its flow stress uses; the others keep it.
inline double flow_internal_after(const FlowStressLaw& law, double internal, double d_ep,
                                  double plastic_strain_rate, const FlowConditions& c) {
  return std::visit(
      [&](const auto& l) {
        if constexpr (requires { internal_after(l, internal, d_ep, plastic_strain_rate, c); })
          return internal_after(l, internal, d_ep, plastic_strain_rate, c);
        else
          return internal;
      },
      law);
}

/// The law's JSON "type".
inline std::string_view law_type(const FlowStressLaw& law) {
  return model_type(law);
}
/// Every law's "type", catalogue order.
inline std::vector<std::string_view> law_types() {
  return model_types<FlowStressLaw>();
}
/// Reads the object at `r` by its "type" (a problem names the known types);
/// the temperatures are the material's.
FlowStressLaw read_flow_stress(JsonReader& r, double room_temperature, double melt_temperature);
/// The object read_flow_stress reads back, "type" first.
inline Json to_json(const FlowStressLaw& law) {
  return model_to_json(law);
}

// The law's parameters by name (parameter_names, parameter_unit, has_parameter, fit_bounds,
// parameter, set_parameter) are the catalogue's: models/core/catalogue.hpp.

}  // namespace impact
