#include "pointdriver/fit/fit_config.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "models/material/material.hpp"

namespace impact::pointdriver::fit {

namespace fs = std::filesystem;

namespace {

// Greedy with one backtrack point, the last '*': O(|p| |s|) at worst. The recursion it replaces
// tried every split at every '*' and was exponential in their number (the fuzzer's
// "*a*a*a...": a 15 s timeout on one file name).
bool wildcard(const std::string& p, const std::string& s) {
  std::size_t i = 0, j = 0;
  std::size_t star = std::string::npos, resume = 0;  // the last '*' and where its match ends
  while (j < s.size()) {
    if (i < p.size() && (p[i] == '?' || (p[i] != '*' && p[i] == s[j]))) {
      ++i;
      ++j;
    } else if (i < p.size() && p[i] == '*') {
      star = i++;
      resume = j;  // the '*' matches nothing so far
    } else if (star != std::string::npos) {
      i = star + 1;  // the '*' takes one more character
      j = ++resume;
    } else {
      return false;
    }
  }
  while (i < p.size() && p[i] == '*') ++i;
  return i == p.size();
}

/// Default bounds of the damage parameters (the strength ones are the law's: FitBounds).
constexpr std::array<std::array<double, 2>, 5> kDamageBounds{
    {{-3.0, 3.0}, {-10.0, 10.0}, {-10.0, 10.0}, {-1.0, 1.0}, {-10.0, 10.0}}};
constexpr std::array<const char*, 5> kDamageNames{"D1", "D2", "D3", "D4", "D5"};

/// A referenced file that is not there: named with the key path that refers to it.
void check_exists(InputProblems& problems, const std::string& key_path, const std::string& what,
                  const std::string& name, const std::string& resolved) {
  std::error_code ec;
  if (name.empty() || fs::is_regular_file(resolved, ec)) return;
  if (const auto kind = not_a_regular_file(resolved)) {  // there, but no file
    problems.add(key_path, "the " + what + " '" + name + "' " + *kind + "; expected a file");
    return;
  }
  problems.add(key_path, "cannot find the " + what + " '" + name +
                             "' (looked in the working directory, beside the configuration file "
                             "and in its parent directories)");
}

DataEntry data_entry(std::string file, double weight) {
  DataEntry e;
  e.file = std::move(file);
  e.weight = weight;
  return e;
}

std::vector<DataEntry> read_data(JsonReader& r, const Json& doc, const std::string& file) {
  std::vector<DataEntry> out;
  const Json* data = doc.contains("data") ? &doc["data"] : nullptr;
  r.ignore("data");
  if (!data || !data->is_array() || data->empty()) {
    r.problems().add("/data", "required: a non-empty list of {\"file\": ...} or {\"glob\": ...}");
    return out;
  }
  for (std::size_t i = 0; i < data->size(); ++i) {
    const std::string at = "/data/" + std::to_string(i);
    const Json& d = (*data)[i];
    if (d.is_string()) {
      out.push_back(data_entry(resolve_file(d.get<std::string>(), file), 1.0));
      check_exists(r.problems(), at, "experiment file", d.get<std::string>(), out.back().file);
      continue;
    }
    if (!d.is_object()) {
      r.problems().add(at, "expected a file name or an object {\"file\"|\"glob\", \"weight\"}");
      continue;
    }
    JsonReader e(d, at, r.problems());
    const double w = e.number_or("weight", 1.0, Range::positive(), "weight of these curves");
    std::optional<double> rate, temperature;
    if (e.has("strain_rate"))
      rate = e.number("strain_rate", Range::positive(), "replaces the files' strain rate [1/s]");
    if (e.has("temperature"))
      temperature = e.quantity("temperature", Quantity::temperature, Range::positive(),
                               "replaces the files' initial temperature [K]");
    const std::size_t first = out.size();
    if (e.has("file") == e.has("glob")) {
      r.problems().add(at, "give exactly one of \"file\" and \"glob\"");
    } else if (e.has("file")) {
      const std::string name = e.string("file", "experiment file");
      out.push_back(data_entry(resolve_file(name, file), w));
      check_exists(r.problems(), e.key_path("file"), "experiment file", name, out.back().file);
    } else {
      const std::string pattern = e.string("glob", "experiment files ('*' and '?')");
      const std::string dir = fs::path(pattern).parent_path().string();
      // A bare pattern ("lee_*.csv") means beside the configuration file, not the working
      // directory (which always exists and would otherwise win in resolve_file).
      const std::string resolved_dir = dir.empty()
                                           ? fs::absolute(fs::path(file)).parent_path().string()
                                           : resolve_file(dir, file);
      const auto files =
          glob_files((fs::path(resolved_dir) / fs::path(pattern).filename()).string());
      if (files.empty()) r.problems().add(at + "/glob", "no file matches '" + pattern + "'");
      for (const auto& f : files) out.push_back(data_entry(f, w));
    }
    for (std::size_t k = first; k < out.size(); ++k) {
      out[k].strain_rate = rate;
      out[k].temperature = temperature;
    }
    e.reject_unknown_keys();
  }
  return out;
}

CurveSettings read_driver(JsonReader& r) {
  CurveSettings c;
  c.adiabatic_above_rate =
      r.number_or("adiabatic_above_rate", c.adiabatic_above_rate, Range::non_negative(),
                  "tests at or above this strain rate are adiabatic unless their file says [1/s]");
  if (auto d = r.optional_child("driver", "driver settings")) {
    c.steps = clamped_int(
        d->number_or("steps", c.steps, Range::closed(5, 100000), "driver steps per test"), 5,
        100000);
    c.first_step_fraction = d->number_or("first_step_fraction", c.first_step_fraction,
                                         Range::open(0.0, 1.0), "first step / path duration");
    c.threads = clamped_int(
        d->number_or("threads", 0, Range::closed(0, 1024), "worker threads (0: all cores)"), 0,
        1024);
    d->reject_unknown_keys();
  }
  return c;
}

/// Material-level keys of the configuration, as a merge patch over the material file.
Json material_patch(JsonReader& r, const Json& doc) {
  Json patch = Json::object();
  if (doc.contains("material_overrides")) {
    r.ignore("material_overrides");
    if (!doc["material_overrides"].is_object())
      r.problems().add("/material_overrides", "expected an object (a JSON merge patch)");
    else
      patch = doc["material_overrides"];
  }
  if (r.has("reference_strain_rate"))
    patch["constitutive_model"]["flow_stress"]["reference_strain_rate"] = r.number(
        "reference_strain_rate", Range::positive(), "reference strain rate of the fit [1/s]");
  if (r.has("room_temperature"))
    patch["room_temperature"] = r.quantity("room_temperature", Quantity::temperature,
                                           Range::positive(), "room temperature [K]");
  if (r.has("melt_temperature"))
    patch["melt_temperature"] = r.quantity("melt_temperature", Quantity::temperature,
                                           Range::positive(), "melt temperature [K]");
  if (r.has("taylor_quinney"))
    patch["constitutive_model"]["adiabatic_heating"]["taylor_quinney"] =
        r.number("taylor_quinney", Range::closed(0, 1), "Taylor-Quinney coefficient chi");
  return patch;
}

constexpr std::array<const char*, 2> kTemperatureShortcuts = {"room_temperature",
                                                              "melt_temperature"};

/// The material the configuration starts from, with its overrides: read now, so that a missing
/// or bad material is reported against the configuration's key path before anything runs.
struct CheckedMaterial {
  std::vector<std::string> warnings;
  std::optional<FlowStressLaw> law;  ///< when the material loaded
};
CheckedMaterial check_material(InputProblems& problems, const std::string& name,
                               const std::string& resolved, const Json& overrides,
                               const Json& shortcuts) {
  std::error_code ec;
  if (name.empty()) return {};
  if (!fs::is_regular_file(resolved, ec)) {
    check_exists(problems, "/material", "material file", name, resolved);
    return {};
  }
  try {
    const Material material = load_material(resolved, overrides);
    if (material.model.hyperelastic()) {  // no flow stress or damage to fit
      problems.add("/material",
                   name +
                       ": constitutive_model.type is neo_hookean; fitting and checking need an "
                       "elastic_plastic material (its flow_stress and damage)");
      return {};
    }
    std::vector<std::string> warnings = material.warnings;
    // A temperature shortcut (room_temperature, melt_temperature) is the material's value now:
    // its units warning was given at the configuration's own key, so the material's is a repeat.
    std::erase_if(warnings, [&](const std::string& w) {
      return std::any_of(kTemperatureShortcuts.begin(), kTemperatureShortcuts.end(),
                         [&](const char* key) {
                           return shortcuts.contains(key) &&
                                  w.find(": /" + std::string(key) + ": ") != std::string::npos;
                         });
    });
    return {warnings, material.model.params().flow_stress};
  } catch (const InputError& e) {
    problems.add_nested("/material", "in material ", e);
  }
  return {};
}

}  // namespace

const ParameterSpec* find_parameter(const FitConfig& config, std::string_view name) {
  for (const ParameterSpec& s : config.parameters)
    if (s.name == name) return &s;
  return nullptr;
}

std::string resolve_file(const std::string& name, const std::string& relative_to) {
  const fs::path p(name);
  std::error_code ec;  // a name too long for the file system is simply not found
  if (p.is_absolute() || fs::exists(p, ec)) return name;
  fs::path dir = fs::absolute(fs::path(relative_to)).parent_path();
  while (!dir.empty()) {
    if (fs::exists(dir / p, ec)) return (dir / p).lexically_normal().string();
    if (dir == dir.parent_path()) break;
    dir = dir.parent_path();
  }
  return name;
}

std::vector<std::string> glob_files(const std::string& pattern) {
  const fs::path p(pattern);
  fs::path dir = p.parent_path();
  if (dir.empty()) dir = ".";
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file()) continue;
    if (wildcard(p.filename().string(), entry.path().filename().string()))
      out.push_back((p.parent_path() / entry.path().filename()).string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

FitConfig read_fit_config(const std::string& file) {
  return read_fit_config(load_json_file(file), file);
}

FitConfig read_fit_config(const Json& doc, const std::string& file) {
  InputProblems problems(file);
  FitConfig c;
  c.file = file;
  if (!doc.is_object()) {
    problems.add("", "expected a JSON object");
    problems.throw_if_any();
  }
  JsonReader r(doc, "", problems);
  r.ignore("description");
  c.mode = r.choice("mode", {"strength", "damage"}, "what is fitted", "strength");
  const std::string material_name = r.string("material", "material file to start from");
  c.material_file = resolve_file(material_name, file);
  c.overrides = material_patch(r, doc);
  c.data = read_data(r, doc, file);
  c.curves = read_driver(r);
  c.initial_guess =
      r.choice("initial_guess", {"staged", "start"}, "where the global fit starts", "staged");
  c.room_tolerance = r.number_or("room_temperature_tolerance", 10.0, Range::positive(),
                                 "tests within this of room temperature are 'room' [K]");
  const bool damage = c.mode == "damage";
  // The material now: strength mode fits its law's parameters, by name.
  const CheckedMaterial material =
      check_material(problems, material_name, c.material_file, c.overrides, doc);
  if (damage) {
    for (std::size_t i = 0; i < 5; ++i)
      c.parameters.push_back(
          {kDamageNames[i], "-", true, std::nullopt, kDamageBounds[i][0], kDamageBounds[i][1]});
  } else if (material.law) {
    const FlowStressLaw& law = *material.law;
    for (const std::string& name : parameter_names(law)) {
      const FitBounds b = fit_bounds(law, name);
      c.parameters.push_back({name, std::string(parameter_unit(law, name)),
                              !b.empty() && parameter(law, name) != 0.0, std::nullopt, b.lower,
                              b.upper});
    }
  }
  if (auto ps = r.optional_child("parameters", "free/fixed parameters, start values, bounds")) {
    for (ParameterSpec& s : c.parameters) {
      auto q = ps->optional_child(s.name, "parameter " + s.name);
      if (!q) continue;
      s.free = q->boolean_or("free", s.free, "fitted (true) or held at its start value (false)");
      if (q->has("start")) s.start = q->number("start", Range::any(), "start value (SI)");
      const double inf = std::numeric_limits<double>::infinity();
      const Range finite{-inf, inf, true, true};  // bounds enter the logistic transform
      const bool has_lower = q->has("lower"), has_upper = q->has("upper");
      s.lower = q->number_or("lower", s.lower, finite, "lower bound (SI)");
      s.upper = q->number_or("upper", s.upper, finite, "upper bound (SI)");
      if (s.unit == "Pa") {  // a stress given in MPa is warned about
        if (s.start) problems.check_units(q->key_path("start"), Quantity::stress, *s.start);
        if (has_lower) problems.check_units(q->key_path("lower"), Quantity::stress, s.lower);
        if (has_upper) problems.check_units(q->key_path("upper"), Quantity::stress, s.upper);
      }
      const bool bounds_ok = std::isfinite(s.lower) && std::isfinite(s.upper);
      if (bounds_ok && s.free && !(s.lower < s.upper))
        problems.add(q->key_path(has_lower || has_upper ? "upper" : "lower"),
                     has_lower || has_upper
                         ? "upper bound must exceed the lower bound"
                         : "a free parameter with no default range: give \"lower\" and \"upper\"");
      else if (bounds_ok && s.start && std::isfinite(*s.start) && s.free &&
               !(s.lower < *s.start && *s.start < s.upper))
        problems.add(q->key_path("start"), "start value must lie strictly inside the bounds");
      q->reject_unknown_keys();
    }
    // Not one of the law's parameters: the reader names the ones it has.
    if (damage || material.law) ps->reject_unknown_keys();
  }
  if (auto s = r.optional_child("solver", "least-squares settings")) {
    c.solver.max_iterations = clamped_int(s->number_or("max_iterations", c.solver.max_iterations,
                                                       Range::closed(1, 100000), "iterations"),
                                          1, 100000);
    c.solver.xtol = s->number_or("xtol", c.solver.xtol, Range::positive(), "step tolerance");
    c.solver.gtol = s->number_or("gtol", c.solver.gtol, Range::positive(), "gradient tolerance");
    c.solver.ftol = s->number_or("ftol", c.solver.ftol, Range::positive(), "residual tolerance");
    c.solver.fd_step = s->number_or("fd_step", c.solver.fd_step, Range::open(0, 1),
                                    "finite-difference step in the scaled variables");
    s->reject_unknown_keys();
  }
  if (auto o = r.optional_child("output", "where the report goes")) {
    c.output_directory = o->string_or("directory", c.output_directory, "output directory");
    c.output_material = o->string_or("material", "", "fitted material file name");
    c.figures = o->boolean_or("figures", true, "write figures (python3-matplotlib)");
    o->reject_unknown_keys();
  }
  r.reject_unknown_keys();
  problems.warn_nested("/material", "in material ", material.warnings);
  problems.throw_if_any();
  c.warnings = problems.warnings();
  if (c.output_material.empty())
    c.output_material = fs::path(c.material_file).stem().string() + "_fitted.json";
  return c;
}

CheckConfig read_check_config(const std::string& file) {
  return read_check_config(load_json_file(file), file);
}

CheckConfig read_check_config(const Json& doc, const std::string& file) {
  InputProblems problems(file);
  CheckConfig c;
  c.file = file;
  if (!doc.is_object()) {
    problems.add("", "expected a JSON object");
    problems.throw_if_any();
  }
  JsonReader r(doc, "", problems);
  r.ignore("description");
  const std::string material_name = r.string("material", "material file (the set checked)");
  c.material_file = resolve_file(material_name, file);
  c.overrides = material_patch(r, doc);
  c.data = read_data(r, doc, file);
  c.curves = read_driver(r);
  if (auto t = r.optional_child("tolerance", "per-curve limits; exit 3 when one is exceeded")) {
    // Stress tolerances [Pa] are checked for a value in MPa (a warning); rms_percent is in %.
    auto opt = [&](const char* key, const char* meaning,
                   bool stress = true) -> std::optional<double> {
      if (!t->has(key)) return std::nullopt;
      return stress ? t->quantity(key, Quantity::stress, Range::positive(), meaning)
                    : t->number(key, Range::positive(), meaning);
    };
    c.tolerance.rms = opt("rms", "RMS stress error per curve [Pa]");
    c.tolerance.max = opt("max", "largest absolute stress error per curve [Pa]");
    c.tolerance.mean_signed = opt("mean_signed", "|mean signed stress error| per curve [Pa]");
    c.tolerance.rms_percent =
        opt("rms_percent", "RMS error per curve, % of its mean stress", false);
    c.overall_rms = opt("overall_rms", "RMS stress error over every point [Pa]");
    t->reject_unknown_keys();
  }
  if (auto o = r.optional_child("output", "where the report goes")) {
    c.output_directory = o->string_or("directory", c.output_directory, "output directory");
    c.figures = o->boolean_or("figures", true, "write figures (python3-matplotlib)");
    o->reject_unknown_keys();
  }
  r.reject_unknown_keys();
  problems.warn_nested(
      "/material", "in material ",
      check_material(problems, material_name, c.material_file, c.overrides, doc).warnings);
  problems.throw_if_any();
  c.warnings = problems.warnings();
  return c;
}

std::vector<Experiment> read_experiments(const std::vector<DataEntry>& data,
                                         double youngs_modulus) {
  std::vector<Experiment> out;
  std::vector<std::string> problems;
  for (const auto& d : data) {
    try {
      out.push_back(read_experiment(d.file, youngs_modulus));
      Experiment& x = out.back();
      x.weight *= d.weight;
      const auto replaced = [&](const char* what, double& value, double by, const char* unit) {
        std::ostringstream note;
        note << what << ' ' << value << " -> " << by << ' ' << unit << " (the configuration's)";
        x.conversions.push_back(note.str());
        value = by;
      };
      if (d.strain_rate) replaced("strain_rate", x.strain_rate, *d.strain_rate, "1/s");
      if (d.temperature) replaced("temperature", x.temperature, *d.temperature, "K");
    } catch (const InputError& e) {
      problems.insert(problems.end(), e.problems().begin(), e.problems().end());
    }
  }
  if (!problems.empty()) throw InputError(problems);
  return out;
}

}  // namespace impact::pointdriver::fit
