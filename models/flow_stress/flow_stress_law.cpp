#include "models/flow_stress/flow_stress_law.hpp"

#include <stdexcept>

namespace impact {

namespace {

// f(law tag) for every alternative of the catalogue, in order.
template <class F, std::size_t... I>
void for_each_law(F&& f, std::index_sequence<I...>) {
  (f(static_cast<const std::variant_alternative_t<I, FlowStressLaw>*>(nullptr)), ...);
}
template <class F>
void for_each_law(F&& f) {
  for_each_law(f, std::make_index_sequence<std::variant_size_v<FlowStressLaw>>{});
}

// The member `name` of a law, or null.
template <class Law>
double Law::*member(std::string_view name) {
  for (const auto& parameter : Law::kParameters)
    if (parameter.name == name) return parameter.member;
  return nullptr;
}

[[noreturn]] void no_such_parameter(const FlowStressLaw& law, std::string_view name) {
  std::string known;
  for (const std::string& n : parameter_names(law)) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument(std::string(law_type(law)) + " has no parameter " +
                              std::string(name) + " (it has " + known + ")");
}

}  // namespace

std::string_view law_type(const FlowStressLaw& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::kType; }, law);
}

std::vector<std::string_view> law_types() {
  std::vector<std::string_view> types;
  for_each_law([&](const auto* tag) { types.push_back(std::decay_t<decltype(*tag)>::kType); });
  return types;
}

FlowStressLaw read_flow_stress(JsonReader& r, double room_temperature, double melt_temperature) {
  const std::string type = r.choice("type", law_types(), "flow stress model");
  FlowStressLaw law;  // an unknown type (a problem recorded): the default
  for_each_law([&](const auto* tag) {
    using Law = std::decay_t<decltype(*tag)>;
    if (Law::kType == type) law = read_law(r, tag, room_temperature, melt_temperature);
  });
  return law;
}

Json to_json(const FlowStressLaw& law) {
  return std::visit([](const auto& l) { return to_json(l); }, law);
}

std::vector<std::string> parameter_names(const FlowStressLaw& law) {
  return std::visit(
      [](const auto& l) {
        std::vector<std::string> names;
        for (const auto& p : std::decay_t<decltype(l)>::kParameters) names.emplace_back(p.name);
        return names;
      },
      law);
}

std::string_view parameter_unit(const FlowStressLaw& law, std::string_view name) {
  return std::visit(
      [&](const auto& l) -> std::string_view {
        for (const auto& p : std::decay_t<decltype(l)>::kParameters)
          if (p.name == name) return p.unit;
        no_such_parameter(law, name);
      },
      law);
}

FitBounds fit_bounds(const FlowStressLaw& law, std::string_view name) {
  return std::visit(
      [&](const auto& l) -> FitBounds {
        for (const auto& p : std::decay_t<decltype(l)>::kParameters)
          if (p.name == name) return p.fit;
        no_such_parameter(law, name);
      },
      law);
}

bool has_parameter(const FlowStressLaw& law, std::string_view name) {
  return std::visit(
      [&](const auto& l) { return member<std::decay_t<decltype(l)>>(name) != nullptr; }, law);
}

double parameter(const FlowStressLaw& law, std::string_view name) {
  return std::visit(
      [&](const auto& l) {
        const auto m = member<std::decay_t<decltype(l)>>(name);
        if (!m) no_such_parameter(law, name);
        return l.*m;
      },
      law);
}

void set_parameter(FlowStressLaw& law, std::string_view name, double value) {
  std::visit(
      [&](auto& l) {
        const auto m = member<std::decay_t<decltype(l)>>(name);
        if (!m) no_such_parameter(law, name);
        l.*m = value;
      },
      law);
}

}  // namespace impact
