// The catalogue of equations of state: a material names one in
// constitutive_model.equation_of_state {"type": ..., "<type>": {its parameters}, ...}. Every EOS's
// block may be present whatever the type (switching EOS is a one-key overlay) and each present
// block is validated. Each EOS lives in its own files with
//   - its parameters struct, with kType (the JSON "type" and block key), kMeaning (the block's
//     description in messages) and kParameters (name, unit, member; models/core/catalogue.hpp),
//   - read_model(JsonReader&, const Params*) and to_json(params) for its block,
//   - eos_step and eos_bulk_modulus (models/eos/eos_step.hpp), which the elastic-plastic step
//     (models/material/elastic_plastic.cpp) calls by visiting the variant,
// and one line in EquationOfState below. docs/extending.md walks through adding one.
#pragma once

#include <variant>

#include "models/core/catalogue.hpp"
#include "models/eos/default_hypo.hpp"
#include "models/eos/mie_gruneisen.hpp"

namespace impact {

/// Every equation of state, one line each (the first is the default when the block has no type).
using EquationOfState = std::variant<DefaultHypoParams, MieGruneisenParams>;

/// Step 4 of the elastic-plastic update with whichever EOS.
inline EosStep eos_step(const EquationOfState& eos, const EosMaterial& m, const EosStepInput& in) {
  return std::visit([&](const auto& e) { return eos_step(e, m, in); }, eos);
}
/// The bulk modulus of the wave speed (the stable time step) at (density, internal_energy).
inline double eos_bulk_modulus(const EquationOfState& eos, const EosMaterial& m, double density,
                               double internal_energy) {
  return std::visit([&](const auto& e) { return eos_bulk_modulus(e, m, density, internal_energy); },
                    eos);
}

/// Reads constitutive_model.equation_of_state at `cm` (a problem names the known types).
EquationOfState read_equation_of_state(JsonReader& cm);
/// {"type": kType, kType: the EOS's block}: what read_equation_of_state reads back.
Json to_json(const EquationOfState& eos);

}  // namespace impact
