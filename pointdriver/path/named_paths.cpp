#include "pointdriver/path/named_paths.hpp"
#include "pointdriver/format/text_format.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>

namespace impact::pointdriver {

namespace {

/// Keys every named type shares; copied onto each generated leg.
struct Common {
  Json step_keys = Json::object();  // steps | max_strain_increment | first_step
  Json thermal = nullptr;
  Json start_temperature = nullptr;
  Json rotation = nullptr;  // {"axis", "angle"}, validated by the leg reader
};

Common read_common(JsonReader& r) {
  Common c;
  if (r.has("steps"))
    c.step_keys["steps"] = r.number("steps", Range::closed(1, 1e9), "steps per leg");
  if (r.has("max_strain_increment")) {
    c.step_keys["max_strain_increment"] = r.number("max_strain_increment", Range::open_closed(0, 1),
                                                   "largest strain increment of a step");
  }
  if (r.has("first_step")) {
    c.step_keys["first_step"] =
        r.number("first_step", Range::positive(), "first step of log-spaced steps [s]");
  }
  if (r.has("thermal")) {
    c.thermal = r.choice("thermal", {"isothermal", "adiabatic"}, "temperature evolution");
  }
  if (r.has("temperature")) {
    c.start_temperature =
        r.number("temperature", Range::open(0, 1e4), "temperature set at the start [K]");
  }
  if (auto rot = r.optional_child("rotation", "superposed rigid rotation {axis, angle}")) {
    rot->ignore("axis");
    rot->ignore("angle");
    rot->reject_unknown_keys();
  }
  return c;
}

/// A velocity gradient with every component fixed: zero except `nonzero`.
Json fixed_velocity_gradient(std::initializer_list<std::pair<const char*, double>> nonzero) {
  Json L = Json::object();
  for (const char* name : {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"}) L[name] = 0.0;
  for (const auto& [name, value] : nonzero) L[name] = value;
  return L;
}

/// The given components plus zero shear components: for an isotropic material a path with no
/// shear stress has no shear strain, and fixing them halves the mixed-control unknowns.
Json no_shear(std::initializer_list<std::pair<const char*, double>> given) {
  Json L = Json::object();
  for (const char* name : {"xy", "xz", "yx", "yz", "zx", "zy"}) L[name] = 0.0;
  for (const auto& [name, value] : given) L[name] = value;
  return L;
}

/// Duration of a leg that reaches `strain` at `rate`; both signed and of the same sign.
double duration_of(JsonReader& r, double strain, double rate) {
  if (std::isnan(strain) || std::isnan(rate)) return 1.0;  // already reported as missing
  if (!(strain * rate > 0.0)) {
    r.problems().add(r.key_path("strain_rate"),
                     "expected a nonzero strain_rate with the sign of strain (got strain " +
                         std::to_string(strain) + ", strain_rate " + std::to_string(rate) + ")");
    return 1.0;
  }
  return strain / rate;
}

class Builder {
 public:
  Builder(JsonReader& r, Common c) : r_(r), c_(std::move(c)) {}

  Json& add(double duration, const std::string& label) {
    Json l = c_.step_keys;
    l["label"] = label;
    l["duration"] = duration;
    if (!c_.thermal.is_null()) l["thermal"] = c_.thermal;
    if (legs_.empty() && !c_.start_temperature.is_null()) {
      l["start_temperature"] = c_.start_temperature;
    }
    legs_.push_back(std::move(l));
    return legs_.back();
  }

  Json uniaxial_stress_leg(double strain, double rate, const std::string& label) {
    Json& l = add(duration_of(r_, strain, rate), label);
    l["velocity_gradient"] = no_shear({{"xx", rate}});
    l["stress"] = {{"yy", 0.0}, {"zz", 0.0}};
    return l;
  }

  /// The legs, with the rotation angle spread in proportion to each leg's duration.
  Json finish(const Json& raw) {
    if (raw.contains("rotation") && raw["rotation"].is_object()) {
      double total = 0.0;
      for (const Json& l : legs_) total += l["duration"].get<double>();
      const Json& rot = raw["rotation"];
      const double angle = rot.value("angle", 0.0);
      for (Json& l : legs_) {
        l["rotation"] = rot;
        if (rot.contains("angle") && rot["angle"].is_number() && total > 0.0) {
          l["rotation"]["angle"] = angle * l["duration"].get<double>() / total;
        }
      }
    }
    return legs_;
  }

 private:
  JsonReader& r_;
  Common c_;
  Json legs_ = Json::array();
};

using Expander = std::function<void(JsonReader&, Builder&)>;

const std::map<std::string, Expander>& expanders() {
  static const std::map<std::string, Expander> table = {
      {"uniaxial_strain",
       [](JsonReader& r, Builder& b) {
         const double e = r.number("strain", Range::any(), "final axial log strain [-]");
         const double rate = r.number("strain_rate", Range::any(), "axial strain rate [1/s]");
         b.add(duration_of(r, e, rate), "uniaxial strain")["velocity_gradient"] =
             fixed_velocity_gradient({{"xx", rate}});
       }},
      {"uniaxial_stress",
       [](JsonReader& r, Builder& b) {
         const double e = r.number("strain", Range::any(), "final axial log strain [-]");
         const double rate = r.number("strain_rate", Range::any(), "axial strain rate [1/s]");
         b.uniaxial_stress_leg(e, rate, "uniaxial stress");
       }},
      {"equibiaxial_stress",
       [](JsonReader& r, Builder& b) {
         const double e = r.number("strain", Range::any(), "final in-plane log strain [-]");
         const double rate = r.number("strain_rate", Range::any(), "in-plane strain rate [1/s]");
         Json& l = b.add(duration_of(r, e, rate), "equibiaxial stress");
         l["velocity_gradient"] = no_shear({{"xx", rate}, {"yy", rate}});
         l["stress"] = {{"zz", 0.0}};
       }},
      {"pure_shear",
       [](JsonReader& r, Builder& b) {
         const double g = r.number("gamma", Range::any(), "engineering shear strain 2 eps_xy [-]");
         const double rate = r.number("gamma_rate", Range::any(), "shear rate 2 D_xy [1/s]");
         b.add(duration_of(r, g, rate), "pure shear")["velocity_gradient"] =
             fixed_velocity_gradient({{"xy", rate / 2}, {"yx", rate / 2}});
       }},
      {"simple_shear",
       [](JsonReader& r, Builder& b) {
         const double g = r.number("gamma", Range::any(), "shear F_xy at the end [-]");
         const double rate = r.number("gamma_rate", Range::any(), "shear rate L_xy [1/s]");
         Json& l = b.add(duration_of(r, g, rate), "simple shear");
         l["deformation_gradient"] = {{"xx", 1.0}, {"xy", g},   {"xz", 0.0},
                                      {"yx", 0.0}, {"yy", 1.0}, {"yz", 0.0},
                                      {"zx", 0.0}, {"zy", 0.0}, {"zz", 1.0}};
       }},
      {"hydrostatic",
       [](JsonReader& r, Builder& b) {
         const double e = r.number("strain", Range::any(), "final log strain per axis [-]");
         const double rate = r.number("strain_rate", Range::any(), "strain rate per axis [1/s]");
         b.add(duration_of(r, e, rate), "hydrostatic")["velocity_gradient"] =
             fixed_velocity_gradient({{"xx", rate}, {"yy", rate}, {"zz", rate}});
       }},
      {"triaxial",
       [](JsonReader& r, Builder& b) {
         const double p =
             r.number("confining_pressure", Range::non_negative(), "confining pressure [Pa]");
         const double tc = r.number("confinement_duration", Range::positive(),
                                    "duration of the hydrostatic confinement leg [s]");
         const double e = r.number("strain", Range::any(), "final axial log strain [-]");
         const double rate = r.number("strain_rate", Range::any(), "axial strain rate [1/s]");
         Json& c = b.add(tc, "confinement");
         c["stress"] = {{"xx", -p}, {"yy", -p}, {"zz", -p}};
         c["velocity_gradient"] = no_shear({});
         Json& l = b.add(duration_of(r, e, rate), "axial loading");
         l["velocity_gradient"] = no_shear({{"xx", rate}});
         l["stress"] = {{"yy", -p}, {"zz", -p}};
       }},
      {"load_unload_reverse",
       [](JsonReader& r, Builder& b) {
         const double e = r.number("strain", Range::any(), "axial log strain of loading [-]");
         const double rate = r.number("strain_rate", Range::any(), "axial strain rate [1/s]");
         const double tu = r.number("unload_duration", Range::positive(),
                                    "duration of unloading to zero axial stress [s]");
         const double er = r.number("reverse_strain", Range::positive(),
                                    "magnitude of the reverse strain increment [-]");
         b.uniaxial_stress_leg(e, rate, "load");
         Json& u = b.add(tu, "unload");
         u["stress"] = {{"xx", 0.0}, {"yy", 0.0}, {"zz", 0.0}};
         u["velocity_gradient"] = no_shear({});
         b.uniaxial_stress_leg(-std::copysign(er, e), -rate, "reverse");
       }},
      // Arrays of equal length, read by expand_jumps().
      {"strain_rate_jump",
       [](JsonReader& r, Builder&) {
         r.ignore("strain_rates");
         r.ignore("strains");
       }},
      {"temperature_jump",
       [](JsonReader& r, Builder&) {
         r.ignore("temperatures");
         r.ignore("strains");
       }},
      {"constant_triaxiality",
       [](JsonReader& r, Builder& b) {
         const double eta = r.number("triaxiality", Range::closed(-2.0, 2.0),
                                     "stress triaxiality sigma_m / sigma_eq [-]");
         const double e = r.number("strain", Range::any(), "final axial log strain [-]");
         const double rate = r.number("strain_rate", Range::any(), "axial strain rate [1/s]");
         // sigma = diag(s, k s, k s): eta = sign(s) (1 + 2k) / (3 (1 - k)); tension along x for
         // eta >= 0, compression for eta < 0, so that k < 1 always.
         const double a = std::abs(eta);
         const double k = (3 * a - 1) / (3 * a + 2);
         if ((eta >= 0) != (e > 0)) {
           r.problems().add(r.key_path("strain"),
                            "expected strain > 0 for triaxiality >= 0 and < 0 for triaxiality < 0");
         }
         Json& l = b.add(duration_of(r, e, rate), "constant triaxiality");
         l["velocity_gradient"] = no_shear({{"xx", rate}});
         l["stress_ratio"] = {{"of", "xx"}, {"yy", k}, {"zz", k}};
       }},
  };
  return table;
}

/// strain_rate_jump / temperature_jump: arrays of equal length, one uniaxial-stress leg each.
void expand_jumps(JsonReader& r, Builder& b, const Json& raw, bool temperature) {
  const char* list_key = temperature ? "temperatures" : "strain_rates";
  const auto numbers = [&](const char* key) {
    std::vector<double> v;
    if (!raw.contains(key) || !raw[key].is_array() || raw[key].empty()) {
      r.problems().add(r.key_path(key), "expected a non-empty array of numbers");
      return v;
    }
    for (std::size_t i = 0; i < raw[key].size(); ++i) {
      if (!raw[key][i].is_number()) {
        r.problems().add(r.key_path(key) + "/" + std::to_string(i), "expected a number");
        return std::vector<double>{};
      }
      v.push_back(raw[key][i].get<double>());
    }
    return v;
  };
  const std::vector<double> values = numbers(list_key);
  const std::vector<double> strains = numbers("strains");
  if (values.empty() || strains.empty()) return;
  if (values.size() != strains.size()) {
    r.problems().add(r.key_path("strains"), std::string("expected as many entries as ") + list_key);
    return;
  }
  const double rate =
      temperature ? r.number("strain_rate", Range::any(), "axial strain rate [1/s]") : 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (temperature) {
      if (!(values[i] > 0.0)) {
        r.problems().add(r.key_path(list_key) + "/" + std::to_string(i),
                         "expected a temperature > 0 [K]");
        return;
      }
      b.uniaxial_stress_leg(strains[i], std::copysign(rate, strains[i]),
                            "T = " + format_number(values[i]) + " K");
    } else {
      b.uniaxial_stress_leg(strains[i], std::copysign(values[i], strains[i]),
                            "rate " + format_number(values[i]) + " /s");
    }
  }
}

}  // namespace

const std::vector<std::string>& named_path_types() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& [name, fn] : expanders()) v.push_back(name);
    return v;
  }();
  return names;
}

Json expand_named_leg(JsonReader& r, const Json& raw) {
  const std::string type = r.string("type", "named path type");
  const auto it = expanders().find(type);
  if (it == expanders().end()) {
    std::string known;
    for (const auto& name : named_path_types()) known += (known.empty() ? "" : ", ") + name;
    const auto near = nearest_name(type, named_path_types());
    r.problems().add(r.key_path("type"), "unknown named path '" + type + "'" +
                                             (near ? " (did you mean " + *near + "?)" : "") +
                                             "; known: " + known);
    return Json::array();
  }
  const std::size_t problems_before = r.problems().count();
  Builder b(r, read_common(r));
  it->second(r, b);
  if (r.problems().count() != problems_before) {
    r.reject_unknown_keys();
    return Json::array();  // its own keys are wrong: expanding would only repeat the problem
  }
  if (type == "strain_rate_jump" || type == "temperature_jump") {
    expand_jumps(r, b, raw, type == "temperature_jump");
  }
  r.reject_unknown_keys();
  Json legs = b.finish(raw);
  if (type == "temperature_jump" && raw.contains("temperatures") &&
      legs.size() == raw["temperatures"].size()) {
    for (std::size_t i = 0; i < legs.size(); ++i)
      legs[i]["start_temperature"] = raw["temperatures"][i];
  }
  return legs;
}

}  // namespace impact::pointdriver
