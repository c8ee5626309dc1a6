// What every sub-model catalogue shares (flow stress, equation of state, shear modulus, damage):
// a slot is a std::variant with one alternative per model, and each model struct carries
//   - kType, the JSON name that selects it, and
//   - kParameters, its numeric parameters as {name, unit, member, fit bounds}.
// The functions below are driven by those two members alone, so a model is reached by type name
// and parameter name (the material reader and writer, the fitter, the checker, the catalogue test)
// without a chain of std::get_if per slot. The hot paths do not come through here: they visit the
// variant (or take a slot's own fast path) directly. docs/extending.md walks through adding a
// model.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "models/core/input.hpp"

namespace impact {

/// The range a fitter searches for a parameter by default [SI]. Empty (lower == upper, the
/// default): not a strength parameter to fit (a reference rate, a molar mass, a modulus the law
/// shares with elasticity); a fit configuration may still free it with bounds of its own.
struct FitBounds {
  double lower = 0.0;
  double upper = 0.0;
  bool empty() const { return !(upper > lower); }
};

/// One named parameter of a model: the JSON key, its unit (SI), the member it lives in and the
/// fitter's default bounds. A model lists them in `kParameters`; `pointdriver fit` varies them by
/// name.
template <class Model>
struct LawParameter {
  std::string_view name;
  std::string_view unit;
  double Model::*member;
  FitBounds fit{};
};

/// The kParameters of a model without numeric parameters (a C array cannot be empty).
template <class Model>
using NoParameters = std::array<LawParameter<Model>, 0>;

/// A model of a catalogue: its JSON type and its table of parameters.
template <class Model>
concept CataloguedModel = requires {
  { Model::kType } -> std::convertible_to<std::string_view>;
  { Model::kParameters[0].member } -> std::convertible_to<double Model::*>;
};

namespace detail {
template <class Variant>
struct IsCatalogue : std::false_type {};
template <CataloguedModel... Models>
struct IsCatalogue<std::variant<Models...>> : std::true_type {};
}  // namespace detail

/// A slot's catalogue: a std::variant whose every alternative is a CataloguedModel.
template <class Variant>
concept Catalogue = detail::IsCatalogue<Variant>::value;

/// f(static_cast<const Model*>(nullptr)) for every model of the catalogue, in order (the tag
/// selects a model's reader by overload).
template <Catalogue Variant, class F>
void for_each_model(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f(static_cast<const std::variant_alternative_t<I, Variant>*>(nullptr)), ...);
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>{});
}

/// Every model's "type", catalogue order (what a reader's choice lists).
template <Catalogue Variant>
std::vector<std::string_view> model_types() {
  std::vector<std::string_view> types;
  for_each_model<Variant>(
      [&](const auto* tag) { types.push_back(std::decay_t<decltype(*tag)>::kType); });
  return types;
}

/// The model's JSON "type".
template <Catalogue Variant>
std::string_view model_type(const Variant& model) {
  return std::visit([](const auto& m) { return std::decay_t<decltype(m)>::kType; }, model);
}

/// The model whose kType is `type`, made by read(tag) (a tag as for_each_model's); nothing for a
/// type the catalogue does not know (the reader's choice() has recorded that problem).
template <Catalogue Variant, class Read>
std::optional<Variant> read_by_type(std::string_view type, Read&& read) {
  std::optional<Variant> model;
  for_each_model<Variant>([&](const auto* tag) {
    if (std::decay_t<decltype(*tag)>::kType == type) model = Variant(read(tag));
  });
  return model;
}

/// The model as its reader takes it back: a model's own to_json(model).
template <Catalogue Variant>
Json model_to_json(const Variant& model) {
  return std::visit([](const auto& m) { return to_json(m); }, model);
}

/// {"type": kType, every kParameters entry by name}: the writer of a model whose keys are exactly
/// its parameters (its reader then reads them back).
template <CataloguedModel Model>
Json parameters_to_json(const Model& model) {
  Json j = {{"type", Model::kType}};
  for (const auto& q : Model::kParameters) j[std::string(q.name)] = model.*q.member;
  return j;
}

/// The parameter names of a model type (kParameters order).
template <CataloguedModel Model>
std::vector<std::string> parameter_names_of() {
  std::vector<std::string> names;
  for (const auto& p : Model::kParameters) names.emplace_back(p.name);
  return names;
}

/// std::invalid_argument "<type> has no parameter <name> (it has <known>)".
[[noreturn]] void throw_no_such_parameter(std::string_view type, std::string_view name,
                                          const std::vector<std::string>& known);

/// The entry of kParameters called `name`, or null.
template <CataloguedModel Model>
const LawParameter<Model>* find_parameter(std::string_view name) {
  for (const auto& p : Model::kParameters)
    if (p.name == name) return &p;
  return nullptr;
}

/// The model's parameter names (kParameters order) and units.
template <Catalogue Variant>
std::vector<std::string> parameter_names(const Variant& model) {
  return std::visit([](const auto& m) { return parameter_names_of<std::decay_t<decltype(m)>>(); },
                    model);
}

/// The entry called `name` of the model's table; std::invalid_argument naming the model's
/// parameters when it has none such.
template <Catalogue Variant, class F>
decltype(auto) with_parameter(const Variant& model, std::string_view name, F&& f) {
  return std::visit(
      [&](const auto& m) -> decltype(auto) {
        using Model = std::decay_t<decltype(m)>;
        const LawParameter<Model>* p = find_parameter<Model>(name);
        if (!p) throw_no_such_parameter(Model::kType, name, parameter_names_of<Model>());
        return f(m, *p);
      },
      model);
}

template <Catalogue Variant>
std::string_view parameter_unit(const Variant& model, std::string_view name) {
  return with_parameter(model, name, [](const auto&, const auto& p) { return p.unit; });
}

template <Catalogue Variant>
bool has_parameter(const Variant& model, std::string_view name) {
  return std::visit(
      [&](const auto& m) { return find_parameter<std::decay_t<decltype(m)>>(name) != nullptr; },
      model);
}

/// The fitter's default bounds of a parameter (empty: not fitted by default).
template <Catalogue Variant>
FitBounds fit_bounds(const Variant& model, std::string_view name) {
  return with_parameter(model, name, [](const auto&, const auto& p) { return p.fit; });
}

/// A parameter by name; std::invalid_argument naming the model's parameters when it has none such.
template <Catalogue Variant>
double parameter(const Variant& model, std::string_view name) {
  return with_parameter(model, name, [](const auto& m, const auto& p) { return m.*p.member; });
}

template <Catalogue Variant>
void set_parameter(Variant& model, std::string_view name, double value) {
  std::visit(
      [&](auto& m) {
        using Model = std::decay_t<decltype(m)>;
        const LawParameter<Model>* p = find_parameter<Model>(name);
        if (!p) throw_no_such_parameter(Model::kType, name, parameter_names_of<Model>());
        m.*p->member = value;
      },
      model);
}

}  // namespace impact
