#include "models/material/material.hpp"

namespace impact {

namespace {

// fitted_range: both bounds of each quantity, the lower below the upper.
FittedRange read_fitted_range(JsonReader& r) {
  FittedRange f;
  const Range rates = Range::open(0.0, 1e12), temperatures = Range::open(0.0, 1e4);
  f.strain_rate_min = r.number("strain_rate_min", rates, "lowest strain rate of the fit [1/s]");
  f.strain_rate_max = r.number("strain_rate_max", rates, "highest strain rate of the fit [1/s]");
  f.temperature_min = r.quantity("temperature_min", Quantity::temperature, temperatures,
                                 "lowest temperature of the fit [K]");
  f.temperature_max = r.quantity("temperature_max", Quantity::temperature, temperatures,
                                 "highest temperature of the fit [K]");
  if (f.strain_rate_min > f.strain_rate_max)
    r.problems().add(r.key_path("strain_rate_max"), "expected at least strain_rate_min");
  if (f.temperature_min > f.temperature_max)
    r.problems().add(r.key_path("temperature_max"), "expected at least temperature_min");
  r.reject_unknown_keys();
  return f;
}

ObjectiveRate read_objective_rate(JsonReader& r) {
  const std::string name =
      r.choice("objective_rate", {"green_naghdi", "green_naghdi_incremental", "jaumann"},
               "stress rate: polar (Green-Naghdi) rotation, the same rotation integrated from its "
               "spin, or the Jaumann spin",
               "green_naghdi");
  return name == "jaumann"                    ? ObjectiveRate::jaumann
         : name == "green_naghdi_incremental" ? ObjectiveRate::green_naghdi_incremental
                                              : ObjectiveRate::green_naghdi;
}

}  // namespace

Material read_material(const Json& document, const std::string& file, InputKeyRecorder* keys) {
  InputProblems problems(file);
  problems.record_keys_to(keys);
  if (!document.is_object()) {
    problems.add("", "expected a JSON object with the material's properties");
    problems.throw_if_any();
  }
  JsonReader root(document, "", problems);
  ElasticPlasticParams p;
  const std::string name = root.string("name", "material name");
  root.read_elsewhere("description", [] {
    return KeyDescription{"any", "", "", "documentation only; not read"};
  });
  root.read_elsewhere("sources", [] {
    return KeyDescription{"any", "", "", "the sources of each value, documentation only; not read"};
  });
  // Ranges refuse what is physically impossible (no solid is denser than 30000 kg/m^3 or stiffer
  // than 2e12 Pa); a possible but implausible SI value that looks typed in g/cm^3, GPa, MPa,
  // J/(g K) or degC is read with a warning naming the likely unit (units_check.hpp): a foam's
  // density of a few kg/m^3 must not be refused.
  p.density = root.quantity("density", Quantity::density, Range::open_closed(0.0, 30000.0),
                            "reference density [kg/m^3]");
  p.shear_modulus = root.quantity("shear_modulus", Quantity::elastic_modulus,
                                  Range::open_closed(0.0, 2e12), "shear modulus mu [Pa]");
  p.bulk_modulus = root.quantity("bulk_modulus", Quantity::elastic_modulus,
                                 Range::open_closed(0.0, 2e12), "bulk modulus K [Pa]");
  const double conductivity = root.number_or("thermal_conductivity", 0.0, Range::non_negative(),
                                             "thermal conductivity [W/(m K)]");
  JsonReader cm = root.child("constitutive_model", "the constitutive model and its sub-models");
  const std::size_t before_type = problems.count();
  const std::string type = cm.choice(
      "type", {"elastic_plastic", "neo_hookean"},
      "constitutive model: the hypoelastic-plastic composition of the report, or the hyperelastic "
      "compressible neo-Hookean solid (docs/models.md)",
      "elastic_plastic");
  // The type decides what every other key means: an unknown one ends the reading here, before a
  // list of what an elastic-plastic file would miss buries its name.
  if (problems.count() > before_type) problems.throw_if_any();
  if (type == "neo_hookean") {
    // Elastic: stress from F with mu and lambda = K - 2 mu / 3, nothing else to read. Every key
    // of the composed model is refused by name (unknown here), temperatures and heat included.
    p.type = ConstitutiveType::neo_hookean;
    // lambda < 0 (nu < 0) makes the volumetric energy -mu ln J + lambda/2 (ln J)^2 non-convex
    // once mu + lambda (1 - ln J) < 0: the pressure falls under moderate compression (nu = -0.5:
    // from J = 0.59) and the mean stress turns tensile. Refused, naming nu.
    if (p.bulk_modulus > 0.0 && p.shear_modulus > 0.0 &&
        p.bulk_modulus < 2.0 / 3.0 * p.shear_modulus) {
      const double nu = (3.0 * p.bulk_modulus - 2.0 * p.shear_modulus) /
                        (2.0 * (3.0 * p.bulk_modulus + p.shear_modulus));
      problems.add("/bulk_modulus",
                   "expected at least 2/3 of shear_modulus for neo_hookean (lambda = K - 2 mu / 3 "
                   ">= 0, Poisson's ratio >= 0; got nu = " +
                       std::to_string(nu) +
                       "): with lambda < 0 its volumetric energy is not "
                       "convex and it softens under compression");
    }
    p.heating.enabled = false;
    p.melting.do_melting = false;
    p.tepla.enabled = false;
    // The composed model's keys, named as what they are here: keys the law would ignore.
    for (const char* key :
         {"specific_heat", "room_temperature", "melt_temperature", "fitted_range"})
      if (root.has(key)) {
        problems.add(root.key_path(key), "a neo_hookean material has no " + std::string(key) +
                                             " (it would be ignored): remove the key");
        root.ignore(key);
      }
    if (const auto block = document.find("constitutive_model");
        block != document.end() && block->is_object())
      for (const auto& item : block->items())
        if (item.key() != "type") {
          problems.add(cm.key_path(item.key()),
                       "a neo_hookean material has no " + item.key() +
                           " (its stress is a function of F alone; it would be ignored): remove "
                           "the key, or set it to null in an override");
          cm.ignore(item.key());
        }
    cm.reject_unknown_keys();
    root.reject_unknown_keys();
    problems.throw_if_any();
    return Material{
        name, file, conductivity, ElasticPlastic(std::move(p)), std::nullopt, problems.warnings()};
  }
  p.specific_heat = root.quantity("specific_heat", Quantity::specific_heat,
                                  Range::open_closed(0.0, 1e5), "specific heat cp [J/(kg K)]");
  p.room_temperature =
      root.quantity_or("room_temperature", 294.0, Quantity::temperature, Range::open(0.0, 1e4),
                       "room (reference) temperature T_r [K]");
  p.melt_temperature = root.quantity("melt_temperature", Quantity::temperature,
                                     Range::open(0.0, 1e4), "melting temperature T_m [K]");
  if (p.melt_temperature <= p.room_temperature) {
    problems.add("/melt_temperature", "expected a melting temperature above room_temperature");
  }

  std::optional<FittedRange> fitted;
  if (auto range = root.optional_child("fitted_range",
                                       "the strain rates and temperatures the parameters were "
                                       "fitted on (mpm warns outside them)"))
    fitted = read_fitted_range(*range);

  p.objective_rate = read_objective_rate(cm);
  const std::string algorithm =
      cm.choice("return_algorithm", {"newton", "report_2004"},
                "plastic return: consistent Newton or the report's one-shot rescale", "newton");
  p.return_algorithm =
      algorithm == "report_2004" ? ReturnAlgorithm::report_2004 : ReturnAlgorithm::newton;
  p.return_tolerance.relative_residual = cm.number_or(
      "return_tolerance", 1e-12, Range::open(0.0, 1e-3), "relative residual of the radial return");
  p.equation_of_state = read_equation_of_state(cm);
  if (auto modulus = cm.optional_child("shear_modulus", "shear modulus model"))
    p.shear_modulus_model = read_shear_modulus(*modulus);

  JsonReader flow = cm.child("flow_stress", "flow stress model");
  p.flow_stress = read_flow_stress(flow, p.room_temperature, p.melt_temperature);

  if (auto yield = cm.optional_child("yield_condition", "yield condition")) {
    yield->choice("type", {"von_mises"}, "yield condition", "von_mises");
    yield->reject_unknown_keys();
  }
  if (auto damage = cm.optional_child("damage", "damage model"))
    p.damage = read_damage(*damage, p.room_temperature, p.melt_temperature);
  if (auto block = cm.optional_child("tepla", "TEPLA-F failure")) p.tepla = read_tepla(*block);
  if (auto block = cm.optional_child("melting", "melting")) p.melting = read_melting(*block);
  if (auto block = cm.optional_child("adiabatic_heating", "adiabatic heating")) {
    p.heating = read_adiabatic_heating(*block);
  }
  if (auto block = cm.optional_child("stability_check", "stability check")) {
    p.stability = read_stability(*block);
  }
  if (auto block = cm.optional_child("erosion", "erosion of failed points")) {
    p.erosion = read_erosion(*block);
  }
  cm.reject_unknown_keys();
  root.reject_unknown_keys();
  problems.throw_if_any();
  return Material{
      name, file, conductivity, ElasticPlastic(std::move(p)), fitted, problems.warnings()};
}

Material load_material(const std::string& file, const Json& overrides) {
  Json document = load_json_file(file);
  if (!overrides.is_null() && !(overrides.is_object() && overrides.empty())) {
    document.merge_patch(overrides);
  }
  return read_material(document, file);
}

Material load_material(const std::string& file, const std::vector<Json>& patches) {
  Json document = load_json_file(file);
  for (const Json& patch : patches) document.merge_patch(patch);
  return read_material(document, file);
}

Json to_json(const Material& material) {
  const ElasticPlasticParams& p = material.model.params();
  Json j;
  j["name"] = material.name;
  j["density"] = p.density;
  j["shear_modulus"] = p.shear_modulus;
  j["bulk_modulus"] = p.bulk_modulus;
  if (material.model.hyperelastic()) {
    j["thermal_conductivity"] = material.thermal_conductivity;
    j["constitutive_model"] = {{"type", "neo_hookean"}};
    return j;
  }
  j["specific_heat"] = p.specific_heat;
  j["thermal_conductivity"] = material.thermal_conductivity;
  j["room_temperature"] = p.room_temperature;
  j["melt_temperature"] = p.melt_temperature;
  if (const auto& f = material.fitted_range) {
    j["fitted_range"] = {{"strain_rate_min", f->strain_rate_min},
                         {"strain_rate_max", f->strain_rate_max},
                         {"temperature_min", f->temperature_min},
                         {"temperature_max", f->temperature_max}};
  }
  Json& cm = j["constitutive_model"];
  cm["type"] = "elastic_plastic";
  cm["objective_rate"] = p.objective_rate == ObjectiveRate::jaumann ? "jaumann"
                         : p.objective_rate == ObjectiveRate::green_naghdi_incremental
                             ? "green_naghdi_incremental"
                             : "green_naghdi";
  cm["return_algorithm"] =
      p.return_algorithm == ReturnAlgorithm::report_2004 ? "report_2004" : "newton";
  cm["return_tolerance"] = p.return_tolerance.relative_residual;
  cm["equation_of_state"] = to_json(p.equation_of_state);
  if (!is_constant(p.shear_modulus_model)) cm["shear_modulus"] = to_json(p.shear_modulus_model);
  cm["flow_stress"] = to_json(p.flow_stress);
  cm["yield_condition"] = {{"type", "von_mises"}};
  cm["damage"] = to_json(p.damage);
  cm["tepla"] = {
      {"enabled", p.tepla.enabled},
      {"critical_porosity", p.tepla.critical_porosity},
      {"initial_porosity", p.tepla.initial_porosity},
      {"evolve_porosity", p.tepla.evolve_porosity},
      {"nucleation_fraction", p.tepla.nucleation_fraction},
      {"nucleation_strain", p.tepla.nucleation_strain},
      {"nucleation_std", p.tepla.nucleation_std},
      {"porosity_growth", p.tepla.growth == PorosityGrowth::tension ? "tension" : "dilatation"}};
  cm["melting"] = {{"do_melting", p.melting.do_melting}};
  if (p.melting.curve == MeltingCurve::steinberg_cochran_guinan) {
    cm["melting"]["curve"] = "steinberg_cochran_guinan";
    cm["melting"]["gamma0"] = p.melting.gamma0;
    cm["melting"]["a"] = p.melting.a;
  }
  cm["adiabatic_heating"] = {{"enabled", p.heating.enabled},
                             {"taylor_quinney", p.heating.taylor_quinney}};
  static constexpr const char* kChecks[] = {"none", "drucker", "becker", "drucker_becker"};
  cm["stability_check"] = {
      {"type", kChecks[static_cast<int>(p.stability.check)]},
      {"normal_search",
       p.stability.search == NormalSearch::principal_plane ? "principal_plane" : "full_sphere"},
      {"rate_slope",
       p.stability.rate_slope == RateSlope::constant_rate ? "constant_rate" : "algorithmic"},
      {"outcome", p.stability.outcome == StabilityOutcome::fail ? "fail" : "report"},
      {"drucker_steps", p.stability.drucker_loading_only ? "loading" : "plastic"}};
  cm["erosion"] = {{"algorithm", std::string(erosion_name(p.erosion))}};
  return j;
}

}  // namespace impact
