#include "models/eos/equation_of_state.hpp"

#include <string>

namespace impact {

EquationOfState read_equation_of_state(JsonReader& cm) {
  JsonReader eos = cm.child("equation_of_state", "pressure model");
  const std::string type = eos.choice("type", model_types<EquationOfState>(), "equation of state",
                                      model_type(EquationOfState{}));
  // Parameter blocks of every EOS may be present, so that switching EOS is a one-key overlay;
  // each present block is validated whether chosen or not.
  EquationOfState chosen;
  bool chosen_read = false;
  for_each_model<EquationOfState>([&](const auto* tag) {
    using Eos = std::decay_t<decltype(*tag)>;
    if (auto block = eos.optional_child(Eos::kType, Eos::kMeaning)) {
      const Eos read = read_model(*block, tag);
      if (Eos::kType == type) chosen = read, chosen_read = true;
    }
  });
  eos.reject_unknown_keys();
  // An EOS with parameters needs its block; one without (default_hypo) has defaults for all.
  for_each_model<EquationOfState>([&](const auto* tag) {
    using Eos = std::decay_t<decltype(*tag)>;
    if (Eos::kType != type || chosen_read || std::size(Eos::kParameters) == 0) return;
    std::string names;
    for (const auto& p : Eos::kParameters)
      names += (names.empty() ? "" : ", ") + std::string(p.name);
    eos.problems().add(eos.key_path(Eos::kType),
                       "missing object with " + names + " (required when type is " + type + ")");
  });
  return chosen;
}

Json to_json(const EquationOfState& eos) {
  const std::string type(model_type(eos));
  return {{"type", type}, {type, std::visit([](const auto& e) { return to_json(e); }, eos)}};
}

}  // namespace impact
