#include "models/damage/damage_law.hpp"

#include <string>

namespace impact {

namespace {

NoDamage read_model(JsonReader& r, const NoDamage*, double, double) {
  for_each_model<DamageLaw>([&](const auto* tag) {
    for (const auto& p : std::decay_t<decltype(*tag)>::kParameters) r.ignore(p.name);
  });
  r.reject_unknown_keys();
  return {};
}

}  // namespace

DamageLaw read_damage(JsonReader& r, double room_temperature, double melt_temperature) {
  const std::string type =
      r.choice("type", model_types<DamageLaw>(), "damage model", JohnsonCookDamageParams::kType);
  const auto read = [&](const auto* tag) {
    return read_model(r, tag, room_temperature, melt_temperature);
  };
  if (auto law = read_by_type<DamageLaw>(type, read)) return *law;
  // An unknown type (a problem recorded) is read as "none" was: its keys checked the same way.
  return read(static_cast<const NoDamage*>(nullptr));
}

Json to_json(const NoDamage& none) {
  return parameters_to_json(none);
}

Json to_json(const DamageLaw& law) {
  return model_to_json(law);
}

}  // namespace impact
