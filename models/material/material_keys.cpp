#include "models/material/material_keys.hpp"

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/damage/damage_law.hpp"
#include "models/elasticity/shear_modulus.hpp"
#include "models/eos/equation_of_state.hpp"
#include "models/flow_stress/flow_stress_law.hpp"
#include "models/material/material.hpp"

namespace impact {

namespace {

// Every optional block and key switched on. The values are admissible (most from the shipped
// materials, data/materials/) and otherwise arbitrary: only the keys the reader asks for matter.
Json sample_material() {
  return {{"name", "every key of the material format"},
          {"description", "documentation"},
          {"sources", "documentation"},
          {"density", 2700.0},
          {"shear_modulus", 26e9},
          {"bulk_modulus", 66.4e9},
          {"specific_heat", 896.0},
          {"thermal_conductivity", 166.9},
          {"room_temperature", 294.0},
          {"melt_temperature", 925.0},
          {"fitted_range",
           {{"strain_rate_min", 1e-3},
            {"strain_rate_max", 1e4},
            {"temperature_min", 200.0},
            {"temperature_max", 800.0}}},
          {"constitutive_model",
           {{"type", "elastic_plastic"},
            {"objective_rate", "green_naghdi"},
            {"return_algorithm", "newton"},
            {"return_tolerance", 1e-12},
            {"equation_of_state",
             {{"type", "default_hypo"},
              {"default_hypo", {{"modulus", "bulk"}}},
              {"mie_gruneisen",
               {{"C0", 5386.0}, {"Gamma0", 1.99}, {"S_alpha", 1.339}, {"energy", "evolved"}}}}},
            {"shear_modulus", {{"type", "constant"}}},
            {"flow_stress", Json::object()},  // set by each sample below
            {"yield_condition", {{"type", "von_mises"}}},
            {"damage", {{"type", "none"}}},
            {"tepla",
             {{"enabled", true},
              {"critical_porosity", 0.5},
              {"initial_porosity", 0.0},
              {"evolve_porosity", true},
              {"nucleation_fraction", 0.1},
              {"nucleation_strain", 0.3},
              {"nucleation_std", 0.1},
              {"porosity_growth", "tension"}}},
            {"melting",
             {{"do_melting", true},
              {"curve", "steinberg_cochran_guinan"},
              {"gamma0", 1.97},
              {"a", 1.5}}},
            {"adiabatic_heating", {{"enabled", true}, {"taylor_quinney", 0.9}}},
            {"stability_check",
             {{"type", "drucker_becker"},
              {"normal_search", "principal_plane"},
              {"rate_slope", "constant_rate"},
              {"drucker_steps", "loading"},
              {"outcome", "report"}}},
            {"erosion", {{"algorithm", "AllowNoTension"}}}}}};
}

Json johnson_cook_sample() {
  return {{"type", "johnson_cook"},
          {"A", 324e6},
          {"B", 114e6},
          {"n", 0.42},
          {"C", 0.002},
          {"m", 1.34},
          {"reference_strain_rate", 1.0},
          {"rate_form", "clamped"}};
}

// Each slot's samples: every model of its catalogue, and a second sample where a model's keys
// depend on a value (Zerilli-Armstrong's bcc form, Steinberg-Lund rates, an MTS barrier, which
// makes the barrier's keys required: that sample comes first).
std::vector<Json> flow_stress_samples() {
  return {johnson_cook_sample(),
          {{"type", "zerilli_armstrong"},
           {"form", "fcc"},
           {"C0", 46.5e6},
           {"C2", 890e6},
           {"C3", 0.0028},
           {"C4", 0.000115}},
          {{"type", "zerilli_armstrong"},
           {"form", "bcc"},
           {"C0", 0.0},
           {"C1", 1033e6},
           {"C5", 266e6},
           {"n", 0.289},
           {"C3", 0.00698},
           {"C4", 0.000415}},
          {{"type", "steinberg_cochran_guinan"},
           {"Y0", 120e6},
           {"Y_max", 640e6},
           {"beta", 36.0},
           {"n", 0.45},
           {"initial_plastic_strain", 0.0},
           {"G0", 47.7e9},
           {"dG_dp", 1.35},
           {"dG_dT", -17.98e6},
           {"rate_form", "steinberg_lund"},
           {"C1", 0.71e6},
           {"U_k", 0.31 * 1.602176634e-19},
           {"Y_P", 0.97e9},
           {"C2", 12e-3}},
          {{"type", "preston_tonks_wallace"},
           {"theta", 0.02},
           {"p", 0.0},
           {"s0", 0.012},
           {"s_inf", 0.00325},
           {"kappa", 0.6},
           {"gamma", 4e-5},
           {"y0", 0.01},
           {"y_inf", 0.00125},
           {"y1", 0.012},
           {"y2", 0.4},
           {"beta", 0.23},
           {"G0", 72.2e9},
           {"alpha", 0.23},
           {"molar_mass", 0.180948}},
          {{"type", "mechanical_threshold_stress"},
           {"sigma_a", 40e6},
           {"sigma_i", 1e9},
           {"g0_i", 0.5},
           {"eps0_i", 1e13},
           {"p_i", 0.5},
           {"q_i", 1.5},
           {"g0_e", 1.6},
           {"eps0_e", 1e7},
           {"p_e", 2.0 / 3.0},
           {"q_e", 1.0},
           {"a0", 2.39e9},
           {"a1", 12e6},
           {"a2", 1.696e6},
           {"a3", 0.0},
           {"alpha", 2.0},
           {"sigma_es0", 770e6},
           {"g0_es", 0.2625},
           {"eps0_es", 1e7},
           {"burgers", 2.56e-10},
           {"mu0", 47.7e9},
           {"D", 3e9},
           {"T0", 180.0}},
          // MTS with stage IV, the nested shear-modulus block and the set above T_c (Banerjee's
          // 4340, Rc 38).
          {{"type", "mechanical_threshold_stress"},
           {"sigma_a", 50e6},
           {"sigma_i", 1528.1e6},
           {"g0_i", 0.41229},
           {"eps0_i", 1e8},
           {"p_i", 2.0 / 3.0},
           {"q_i", 1.0},
           {"g0_e", 1.6},
           {"eps0_e", 1e7},
           {"p_e", 2.0 / 3.0},
           {"q_e", 1.0},
           {"a0", 10589.5e6},
           {"a1", 48.6378e6},
           {"a2", -60.4827e6},
           {"a3", 3.60117e6},
           {"aIV0", 1574.65e6},
           {"aIV1", 2.1881e6},
           {"aIV2", 4.83983e6},
           {"aIV3", 1.05692e6},
           {"alpha", 3.0},
           {"sigma_es0", 1118e6},
           {"g0_es", 0.16867},
           {"eps0_es", 1e7},
           {"burgers", 2.48e-10},
           {"mu0", 90e9},
           {"shear_modulus",
            {{"type", "nadal_le_poac"},
             {"dG_dp", 1.8},
             {"zeta", 0.04},
             {"C", 0.080},
             {"molar_mass", 55.947e-3}}},
           {"above_critical_temperature",
            {{"T_c", 1040.0},
             {"sigma_i", 896.14e6},
             {"g0_i", 0.57582},
             {"sigma_es0", 377.62e6},
             {"g0_es", 0.40382},
             {"a0", 18796.9e6},
             {"a1", 0.0},
             {"a2", -173.046e6},
             {"a3", 6.35958e6},
             {"aIV0", 3548.44e6},
             {"aIV1", 0.0},
             {"aIV2", -37.1949e6},
             {"aIV3", 1.03591e6}}}},
          {{"type", "cowper_symonds"},
           {"K", 500e6},
           {"n", 0.2},
           {"eps0", 0.01},
           {"D", 6500.0},
           {"q", 4.0}}};
}

std::vector<Json> shear_modulus_samples() {
  return {{{"type", "constant"}},
          {{"type", "varshni"}, {"D", 3e9}, {"T0", 180.0}},
          {{"type", "steinberg_cochran_guinan"}, {"dG_dp", 1.35}, {"dG_dT", -17.98e6}},
          {{"type", "nadal_le_poac"},
           {"dG_dp", 1.35},
           {"zeta", 0.04},
           {"C", 0.057},
           {"molar_mass", 0.0635}}};
}

std::vector<Json> damage_samples() {
  return {{{"type", "none"}},
          {{"type", "johnson_cook"},
           {"D1", -0.77},
           {"D2", 1.45},
           {"D3", -0.47},
           {"D4", 0.0},
           {"D5", 1.6},
           {"reference_strain_rate", 1.0},
           {"min_fracture_strain", 1e-3},
           {"cutoff_triaxiality", -1.0 / 3.0}}};
}

// A model added to a catalogue needs a sample here, or its keys would go unrecorded and
// unchecked: a missing one is a logic error naming the slot and the type.
template <Catalogue Variant>
void require_every_type(std::string_view slot, const std::set<std::string>& sampled) {
  for (std::string_view type : model_types<Variant>()) {
    if (sampled.count(std::string(type)) == 0)
      throw std::logic_error("material_keys: no sample of " + std::string(slot) + " type " +
                             std::string(type) + " (models/material/material_keys.cpp)");
  }
}

// Reads `document` and records its keys into `keys`, a slot's keys under the slot's type.
void record_keys_of(const Json& document, InputKeyRecorder& keys) {
  InputKeyRecorder read;
  read_material(document, "material.json", &read);
  const Json& cm = document["constitutive_model"];
  for (const InputKey& k : read.keys()) {
    std::string path = k.path;
    for (std::string_view slot : kMaterialSlots) {
      const std::string prefix = "/constitutive_model/" + std::string(slot) + "/";
      if (path.rfind(prefix, 0) != 0 || path == prefix + "type") continue;
      const std::string type = cm[std::string(slot)]["type"].get<std::string>();
      path = prefix.substr(0, prefix.size() - 1) + "[" + type + "]/" + path.substr(prefix.size());
    }
    keys.record(path, k.description);
  }
}

}  // namespace

InputKeyRecorder material_keys() {
  InputKeyRecorder keys;
  Json sample = sample_material();
  sample["constitutive_model"]["flow_stress"] = johnson_cook_sample();
  record_keys_of(sample, keys);
  const auto each = [&](const char* slot, const std::vector<Json>& models) {
    std::set<std::string> types;
    for (const Json& model : models) {
      Json document = sample;
      document["constitutive_model"][slot] = model;
      record_keys_of(document, keys);
      types.insert(model["type"].get<std::string>());
    }
    return types;
  };
  require_every_type<FlowStressLaw>("flow_stress", each("flow_stress", flow_stress_samples()));
  require_every_type<ShearModulusLaw>("shear_modulus",
                                      each("shear_modulus", shear_modulus_samples()));
  require_every_type<DamageLaw>("damage", each("damage", damage_samples()));
  // Every EOS's block is in the sample (each present block is read, chosen or not).
  std::set<std::string> blocks;
  for (const auto& item : sample["constitutive_model"]["equation_of_state"].items())
    blocks.insert(item.key());
  require_every_type<EquationOfState>("equation_of_state", blocks);
  return keys;
}

}  // namespace impact
