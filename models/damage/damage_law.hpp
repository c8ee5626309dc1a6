// The catalogue of damage models: a material names one in constitutive_model.damage
// {"type": ...}; without the block, no damage evolves. Each model lives in its own files with
//   - its parameters struct, with kType (the JSON "type") and kParameters (name, unit, member;
//     models/core/catalogue.hpp),
//   - read_model(JsonReader&, const Params*, room_temperature, melt_temperature) and to_json,
//   - damage_increment(params, d_ep, stress, rate, temperature): what a plastic increment adds,
// and one line in DamageLaw below. The elastic-plastic step calls damage_increment by visiting the
// variant (accumulate_damage); "none" has no increment.
#pragma once

#include <string_view>
#include <variant>

#include "models/core/catalogue.hpp"
#include "models/core/tensor.hpp"
#include "models/damage/johnson_cook_damage.hpp"

namespace impact {

/// No damage evolution. "type": "none" switches damage off by overlay while another model's
/// constants stay in the block for later: its reader accepts every catalogued model's parameters.
struct NoDamage {
  static constexpr std::string_view kType = "none";
  static constexpr NoParameters<NoDamage> kParameters{};
};

/// Every damage model, one line each (the first is the default of a material without the block;
/// a block without "type" is johnson_cook, as it was before the catalogue).
using DamageLaw = std::variant<NoDamage, JohnsonCookDamageParams>;

/// Reads the damage block at `r` by its "type" (default johnson_cook; a problem names the known
/// types); the temperatures are the material's.
DamageLaw read_damage(JsonReader& r, double room_temperature, double melt_temperature);
Json to_json(const NoDamage&);
/// The object read_damage reads back, "type" first.
Json to_json(const DamageLaw& law);

/// damage += the increment of a plastic increment d_ep > 0 taken at `stress`, rate [1/s] and
/// temperature [K], whichever model (a model without damage_increment adds nothing).
inline void accumulate_damage(const DamageLaw& law, double& damage, double delta_plastic_strain,
                              const Mat3& stress, double plastic_strain_rate, double temperature) {
  std::visit(
      [&](const auto& l) {
        if constexpr (requires {
                        damage_increment(l, delta_plastic_strain, stress, plastic_strain_rate,
                                         temperature);
                      })
          damage +=
              damage_increment(l, delta_plastic_strain, stress, plastic_strain_rate, temperature);
      },
      law);
}

}  // namespace impact
