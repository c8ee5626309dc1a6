// Every sub-model catalogue (models/core/catalogue.hpp): flow stress, equation of state, shear
// modulus, damage, and erosion's table of names. For every catalogued type of every slot:
//   - a sample document (a shipped material's block where one exists) reads without a problem,
//     is written back, and reads back to the same document and the same parameters by name;
//   - every kParameters entry is written under its own name from its own member (setting a
//     parameter by name changes that key of the written document, and only that one; a
//     parameter the model's form does not use may be left out of the document);
//   - every struct member is in kParameters unless listed here as a choice, an optional value or
//     one of the material's temperatures (a member left out of the table fails the count);
//   - an unknown type is refused with the list of the known ones.
#include <boost/test/unit_test.hpp>
#include <cstddef>
#include <string>
#include <type_traits>

#include "models/core/catalogue.hpp"
#include "models/damage/damage_law.hpp"
#include "models/elasticity/shear_modulus.hpp"
#include "models/eos/equation_of_state.hpp"
#include "models/failure/erosion.hpp"
#include "models/flow_stress/flow_stress_law.hpp"

using namespace impact;

// ---- Member count of an aggregate (the struct's data members), by brace initialisation.
// Outside the anonymous namespace: a conversion declared there and never defined is an error to
// clang (-Wundefined-internal), though it is named only in unevaluated contexts.
namespace catalogue_test {
struct AnyMember {
  template <class T>
  operator T&() const&& noexcept;  // never defined: used in unevaluated context only
};
}  // namespace catalogue_test

namespace {

using catalogue_test::AnyMember;
template <class T, class... Members>
constexpr std::size_t member_count() {
  if constexpr (requires { T{Members{}..., AnyMember{}}; })
    return member_count<T, Members..., AnyMember>();
  else
    return sizeof...(Members);
}

// Members that are deliberately not parameters by name (choices and optional values, which a
// model's own reader and writer handle, and the material's temperatures), per model. A new model
// needs a line here: without it the test does not compile.
template <class Model>
constexpr std::size_t kOtherMembers = Model::kNoSuchModelInThisTest;
// clang-format off
template <> constexpr std::size_t kOtherMembers<JohnsonCookParams> = 3;  // room, melt T; rate_form
template <> constexpr std::size_t kOtherMembers<ZerilliArmstrongParams> = 1;        // form
template <> constexpr std::size_t kOtherMembers<SteinbergCochranGuinanParams> = 2;  // rate_form; 300 K
template <> constexpr std::size_t kOtherMembers<PrestonTonksWallaceParams> = 1;  // melt T
template <> constexpr std::size_t kOtherMembers<MechanicalThresholdStressParams> = 3;  // modulus block; melt T; above T_c
template <> constexpr std::size_t kOtherMembers<CowperSymondsParams> = 0;
template <> constexpr std::size_t kOtherMembers<DefaultHypoParams> = 1;   // modulus
template <> constexpr std::size_t kOtherMembers<MieGruneisenParams> = 1;  // energy
template <> constexpr std::size_t kOtherMembers<ConstantShearModulus> = 0;
template <> constexpr std::size_t kOtherMembers<VarshniShearModulus> = 0;
template <> constexpr std::size_t kOtherMembers<SteinbergShearModulus> = 0;
template <> constexpr std::size_t kOtherMembers<NadalLePoacShearModulus> = 0;
template <> constexpr std::size_t kOtherMembers<NoDamage> = 0;
template <> constexpr std::size_t kOtherMembers<JohnsonCookDamageParams> = 3;  // cutoff; room, melt T
// clang-format on

template <class Slot>
void check_every_member_is_catalogued() {
  for_each_model<Slot>([](const auto* tag) {
    using Model = std::decay_t<decltype(*tag)>;
    BOOST_TEST_CONTEXT(Model::kType) {
      BOOST_TEST(member_count<Model>() == std::size(Model::kParameters) + kOtherMembers<Model>);
    }
  });
}

// A model whose table misses its member b.
struct Two {
  double a = 0.0;
  double b = 0.0;
  static constexpr std::string_view kType = "two";
  static constexpr LawParameter<Two> kParameters[] = {{"a", "-", &Two::a}};
};

// ---- Samples: one document per catalogued type (the test fails naming a type without one).
Json material_block(const std::string& file, const std::string& slot) {
  return load_json_file(std::string(IMPACT_SOURCE_DIR) + "/data/materials/" + file +
                        ".json")["constitutive_model"][slot];
}

// The shipped materials' temperatures are those of their files; these are in range for all.
constexpr double kRoom = 294.0, kMelt = 1356.0;

Json flow_sample(std::string_view type) {
  if (type == "johnson_cook") return material_block("al6061_t6", "flow_stress");
  if (type == "zerilli_armstrong") return material_block("ofhc_copper_za", "flow_stress");
  if (type == "steinberg_cochran_guinan") return material_block("ofhc_copper_scg", "flow_stress");
  if (type == "preston_tonks_wallace") return material_block("tantalum_ptw", "flow_stress");
  if (type == "mechanical_threshold_stress")
    return material_block("ofhc_copper_mts", "flow_stress");
  if (type == "cowper_symonds")  // Jones (1989)'s mild steel with Swift hardening
    return {{"type", "cowper_symonds"},
            {"K", 5e8},
            {"eps0", 0.01},
            {"n", 0.2},
            {"D", 40.4},
            {"q", 5.0},
            {"minimum_strain_rate", 1e-5}};
  return nullptr;
}

Json eos_sample(std::string_view type) {
  if (type == "default_hypo")
    return {{"type", "default_hypo"}, {"default_hypo", {{"modulus", "report_eq2_lame"}}}};
  if (type == "mie_gruneisen") {
    Json j = material_block("ofhc_copper_jc", "equation_of_state");
    j["mie_gruneisen"]["energy"] = "cp_temperature";  // the choice is written back too
    return j;
  }
  return nullptr;
}

Json shear_sample(std::string_view type) {
  if (type == "constant") return {{"type", "constant"}};
  if (type == "varshni") return {{"type", "varshni"}, {"D", 3.0e9}, {"T0", 180.0}};
  if (type == "steinberg_cochran_guinan") return material_block("ofhc_copper_scg", "shear_modulus");
  if (type == "nadal_le_poac")  // copper (Nadal & Le Poac 2003)
    return {{"type", "nadal_le_poac"},
            {"dG_dp", 1.5},
            {"zeta", 0.04},
            {"C", 0.057},
            {"molar_mass", 63.546e-3}};
  return nullptr;
}

Json damage_sample(std::string_view type) {
  if (type == "none") return {{"type", "none"}};
  if (type == "johnson_cook") {
    Json j = material_block("al6061_t6", "damage");
    j["cutoff_triaxiality"] = -1.0 / 3.0;  // the optional value is written back too
    return j;
  }
  return nullptr;
}

// ---- Each slot's reader and writer, one signature for the checks below: read(document) and the
// written document's parameters.
struct FlowSlot {
  using Variant = FlowStressLaw;
  static Json sample(std::string_view type) { return flow_sample(type); }
  static Variant read(JsonReader& r) { return read_flow_stress(r, kRoom, kMelt); }
  static Json parameters_of(const Json& written) { return written; }
};
struct EosSlot {
  using Variant = EquationOfState;
  static Json sample(std::string_view type) { return eos_sample(type); }
  static Variant read(JsonReader& cm) { return read_equation_of_state(cm); }
  // The reader takes the constitutive_model block that holds equation_of_state.
  static Json enclosed(const Json& document) { return {{"equation_of_state", document}}; }
  static Json parameters_of(const Json& written) {
    return written[written["type"].get<std::string>()];
  }
};
struct ShearSlot {
  using Variant = ShearModulusLaw;
  static Json sample(std::string_view type) { return shear_sample(type); }
  static Variant read(JsonReader& r) { return read_shear_modulus(r); }
  static Json parameters_of(const Json& written) { return written; }
};
struct DamageSlot {
  using Variant = DamageLaw;
  static Json sample(std::string_view type) { return damage_sample(type); }
  static Variant read(JsonReader& r) { return read_damage(r, kRoom, kMelt); }
  static Json parameters_of(const Json& written) { return written; }
};

template <class Slot>
typename Slot::Variant read_document(const Json& document, InputProblems& problems) {
  if constexpr (requires { Slot::enclosed(document); }) {
    const Json enclosing = Slot::enclosed(document);
    JsonReader r(enclosing, "", problems);
    return Slot::read(r);
  } else {
    JsonReader r(document, "/slot", problems);
    return Slot::read(r);
  }
}

template <class Slot>
void check_round_trip() {
  using Variant = typename Slot::Variant;
  for (const std::string_view type : model_types<Variant>()) {
    BOOST_TEST_CONTEXT(type) {
      const Json sample = Slot::sample(type);
      BOOST_TEST_REQUIRE(!sample.is_null(), "no sample document for " << type);
      InputProblems problems("sample.json");
      const Variant model = read_document<Slot>(sample, problems);
      BOOST_TEST_REQUIRE(problems.empty());
      BOOST_TEST(model_type(model) == type);
      const Json written = to_json(model);
      BOOST_TEST(written["type"] == type);
      const Variant again = read_document<Slot>(written, problems);
      BOOST_TEST(problems.empty());
      BOOST_TEST(to_json(again) == written);
      const Json parameters = Slot::parameters_of(written);
      std::size_t k = 0;
      for (const std::string& name : parameter_names(model)) {
        BOOST_TEST_CONTEXT(name) {
          BOOST_TEST(has_parameter(model, name));
          BOOST_TEST(parameter(again, name) == parameter(model, name));
          // A parameter its form does not use may be left out (Zerilli-Armstrong fcc: C1, C5, n).
          const bool written_out = parameters.contains(name);
          if (written_out) BOOST_TEST(parameters.at(name).get<double>() == parameter(model, name));
          // Set by name: that key of the written document changes, and no other.
          Variant changed = model;
          const double value = parameter(model, name) * 1.5 + 1.0 + static_cast<double>(k++);
          set_parameter(changed, name, value);
          BOOST_TEST(parameter(changed, name) == value);
          Json expected = parameters;
          if (written_out) expected[name] = value;
          BOOST_TEST(Slot::parameters_of(to_json(changed)) == expected);
        }
      }
      BOOST_TEST(!has_parameter(model, "no_such_parameter"));
      BOOST_CHECK_THROW(parameter(model, "no_such_parameter"), std::invalid_argument);
    }
  }
}

// The problems of reading `document` (empty if none).
template <class Slot>
std::string problems_of(const Json& document) {
  InputProblems problems("mat.json");
  read_document<Slot>(document, problems);
  try {
    problems.throw_if_any();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

template <class Variant>
std::string known_list() {
  std::string list;
  for (const std::string_view type : model_types<Variant>())
    list += (list.empty() ? "" : ", ") + std::string(type);
  return list;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(catalogue)

BOOST_AUTO_TEST_CASE(every_struct_member_is_a_parameter_or_listed) {
  check_every_member_is_catalogued<FlowStressLaw>();
  check_every_member_is_catalogued<EquationOfState>();
  check_every_member_is_catalogued<ShearModulusLaw>();
  check_every_member_is_catalogued<DamageLaw>();
}

BOOST_AUTO_TEST_CASE(the_member_count_sees_a_member_left_out_of_the_table) {
  BOOST_TEST(member_count<Two>() == 2u);
  BOOST_TEST(std::size(Two::kParameters) == 1u);  // b is missing: the count above would fail
}

BOOST_AUTO_TEST_CASE(flow_stress_laws_round_trip_by_name) {
  check_round_trip<FlowSlot>();
}
BOOST_AUTO_TEST_CASE(equations_of_state_round_trip_by_name) {
  check_round_trip<EosSlot>();
}
BOOST_AUTO_TEST_CASE(shear_moduli_round_trip_by_name) {
  check_round_trip<ShearSlot>();
}
BOOST_AUTO_TEST_CASE(damage_models_round_trip_by_name) {
  check_round_trip<DamageSlot>();
}

BOOST_AUTO_TEST_CASE(unknown_types_are_refused_naming_the_known_ones) {
  const Json bogus = {{"type", "bogus"}};
  const auto refused = [](const std::string& text, const std::string& known) {
    BOOST_TEST_CONTEXT(text) {
      BOOST_TEST(text.find("type: unknown name \"bogus\"; known: " + known) != std::string::npos);
    }
  };
  refused(problems_of<FlowSlot>(bogus), known_list<FlowStressLaw>());
  refused(problems_of<EosSlot>(bogus), known_list<EquationOfState>());
  refused(problems_of<ShearSlot>(bogus), known_list<ShearModulusLaw>());
  refused(problems_of<DamageSlot>(bogus), known_list<DamageLaw>());
  BOOST_TEST(known_list<EquationOfState>() == "default_hypo, mie_gruneisen");
  BOOST_TEST(known_list<DamageLaw>() == "none, johnson_cook");
}

BOOST_AUTO_TEST_CASE(an_eos_with_parameters_needs_its_block) {
  const std::string text = problems_of<EosSlot>(Json{{"type", "mie_gruneisen"}});
  BOOST_TEST(text.find("/equation_of_state/mie_gruneisen: missing object with C0, Gamma0, S_alpha "
                       "(required when type is mie_gruneisen)") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(erosion_names_come_from_one_table) {
  BOOST_TEST(erosion_names().size() == 4u);
  for (const std::string_view name : erosion_names()) {
    const auto algorithm = erosion_from_name(name);
    BOOST_TEST_REQUIRE(algorithm.has_value());
    BOOST_TEST(erosion_name(*algorithm) == name);
  }
  InputProblems problems("mat.json");
  const Json j = {{"algorithm", "bogus"}};
  JsonReader r(j, "/erosion", problems);
  read_erosion(r);
  std::string text;
  try {
    problems.throw_if_any();
  } catch (const InputError& e) {
    text = e.what();
  }
  BOOST_TEST(text.find("algorithm: unknown name \"bogus\"; known: none, AllowNoTension, "
                       "KeepStress, ZeroStress") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_missing_parameter_is_named_with_the_models_parameters) {
  const EquationOfState mg = MieGruneisenParams{3940.0, 2.02, 1.489};
  BOOST_CHECK_EXCEPTION(parameter(mg, "S"), std::invalid_argument, [](const auto& e) {
    return std::string(e.what()) == "mie_gruneisen has no parameter S (it has C0, Gamma0, S_alpha)";
  });
  BOOST_CHECK_EXCEPTION(
      parameter(ShearModulusLaw{}, "D"), std::invalid_argument, [](const auto& e) {
        return std::string(e.what()) == "constant has no parameter D (it has none)";
      });
  BOOST_TEST(parameter_unit(ShearModulusLaw{VarshniShearModulus{}}, "T0") == "K");
}

BOOST_AUTO_TEST_SUITE_END()
