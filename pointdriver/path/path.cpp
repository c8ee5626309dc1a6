#include "pointdriver/path/path.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <filesystem>

#include "pointdriver/path/named_paths.hpp"

namespace impact::pointdriver {

namespace {

namespace fs = std::filesystem;

int index_of(const auto& names, std::string_view name) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (name == names[i]) return static_cast<int>(i);
  }
  return -1;
}

/// Reads {"xx": v, ...} into `out`; keys must be among `names`.
/// With a quantity, each value is also checked for a likely unit slip (a warning).
template <std::size_t N>
void read_components(JsonReader& parent, std::string_view key,
                     const std::array<const char*, N>& names, Range range, std::string_view meaning,
                     std::array<std::optional<double>, N>& out,
                     std::optional<Quantity> quantity = std::nullopt) {
  auto block = parent.optional_child(key, meaning);
  if (!block) return;
  for (std::size_t i = 0; i < N; ++i) {
    if (!block->has(names[i])) continue;
    out[i] = quantity ? block->quantity(names[i], *quantity, range, meaning)
                      : block->number(names[i], range, meaning);
  }
  block->reject_unknown_keys();
}

Vec3 read_vector(JsonReader& r, std::string_view key, std::string_view meaning, const Json& raw) {
  r.ignore(key);
  const Json* v = raw.contains(std::string(key)) ? &raw[std::string(key)] : nullptr;
  if (!v) {
    r.problems().add(r.key_path(key), std::string("required: ") + std::string(meaning));
    return Vec3::UnitZ();
  }
  if (!v->is_array() || v->size() != 3 || !(*v)[0].is_number() || !(*v)[1].is_number() ||
      !(*v)[2].is_number()) {
    r.problems().add(r.key_path(key), "expected an array of three numbers (" +
                                          std::string(meaning) + "), got " + v->dump());
    return Vec3::UnitZ();
  }
  const Vec3 a((*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>());
  if (!(a.norm() > 0.0)) {
    r.problems().add(r.key_path(key), "expected a nonzero axis");
    return Vec3::UnitZ();
  }
  return a.normalized();
}

/// Growth factor g of n steps whose first is h0 and whose sum is T: h0 (g^n - 1)/(g - 1) = T.
double log_spacing_growth(double h0, double T, int n) {
  if (n == 1 || std::abs(h0 * n - T) <= 1e-14 * T) return 1.0;
  struct Data {
    double h0, T;
    int n;
  } d{h0, T, n};
  gsl_function f;
  f.function = [](double lg, void* p) {
    const auto& q = *static_cast<Data*>(p);
    return std::log(q.h0 * std::expm1(q.n * lg) / std::expm1(lg)) - std::log(q.T);
  };
  f.params = &d;
  double lo = h0 * n < T ? 1e-12 : -50.0 / n;
  double hi = h0 * n < T ? 50.0 / n : -1e-12;
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_set_error_handler_off();
  gsl_root_fsolver_set(s, &f, lo, hi);
  double root = 0.5 * (lo + hi);
  for (int i = 0; i < 200; ++i) {
    gsl_root_fsolver_iterate(s);
    root = gsl_root_fsolver_root(s);
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0,
                               1e-14) == GSL_SUCCESS) {
      break;
    }
  }
  gsl_root_fsolver_free(s);
  return std::exp(root);
}

Thermal read_thermal(JsonReader& r, Thermal fallback) {
  const char* names[] = {"isothermal", "adiabatic", "prescribed"};
  const std::string t = r.choice("thermal", {"isothermal", "adiabatic", "prescribed"},
                                 "temperature: held, from plastic work (eq. 8) or prescribed",
                                 names[static_cast<int>(fallback)]);
  return t == "adiabatic"    ? Thermal::adiabatic
         : t == "prescribed" ? Thermal::prescribed
                             : Thermal::isothermal;
}

Leg read_leg(JsonReader& r, const Json& raw, Thermal default_thermal) {
  Leg leg;
  leg.label = r.string_or("label", "", "a name for the leg in the output");
  leg.duration = r.number("duration", Range::positive(), "duration of the leg [s]");
  read_components(r, "velocity_gradient", tensor_names, Range::any(),
                  "velocity gradient L_ij [1/s]", leg.velocity_gradient);
  read_components(r, "deformation_gradient", tensor_names, Range::any(),
                  "deformation gradient F_ij at the leg's end [-]", leg.deformation_gradient);
  read_components(r, "stress", stress_names, Range::any(), "Cauchy stress at the leg's end [Pa]",
                  leg.stress, Quantity::stress);
  if (auto ratio = r.optional_child("stress_ratio", "sigma_c = ratio * sigma_of")) {
    const std::string of = ratio->choice("of", {"xx", "yy", "zz", "xy", "yz", "zx"},
                                         "the stress component the ratios refer to");
    leg.ratio_of = std::max(0, index_of(stress_names, of));
    for (std::size_t i = 0; i < 6; ++i) {
      if (ratio->has(stress_names[i])) {
        leg.stress_ratio[i] = ratio->number(stress_names[i], Range::any(), "stress ratio [-]");
      }
    }
    ratio->reject_unknown_keys();
    if (leg.stress_ratio[leg.ratio_of]) {
      r.problems().add(r.key_path("stress_ratio") + "/" + of,
                       "a component cannot be a ratio of itself");
    }
  }
  // One control per component.
  for (std::size_t c = 0; c < 6; ++c) {
    const auto [i, j] = stress_index[c];
    const bool given_stress = leg.stress[c] || leg.stress_ratio[c];
    if (leg.stress[c] && leg.stress_ratio[c]) {
      r.problems().add(r.key_path("stress_ratio") + "/" + stress_names[c],
                       "also given in stress: give each component one control");
    }
    const int ij = 3 * i + j, ji = 3 * j + i;
    const auto kinematic = [&](int k) {
      return leg.velocity_gradient[k].has_value() || leg.deformation_gradient[k].has_value();
    };
    for (int k : {ij, ji}) {
      if (leg.velocity_gradient[k] && leg.deformation_gradient[k]) {
        r.problems().add(r.key_path("deformation_gradient") + "/" + tensor_names[k],
                         "also given in velocity_gradient: give each component one control");
      }
    }
    const bool fully_kinematic = i == j ? kinematic(ij) : kinematic(ij) && kinematic(ji);
    if (given_stress && fully_kinematic) {
      r.problems().add(
          r.key_path(leg.stress[c] ? "stress" : "stress_ratio") + "/" + stress_names[c],
          i == j ? "also prescribed kinematically: give each component one control"
                 : "both shear components are prescribed kinematically: the stress "
                   "cannot be prescribed too");
    }
  }
  for (int d : {0, 4, 8}) {
    if (leg.deformation_gradient[d] && !(*leg.deformation_gradient[d] > 0.0)) {
      r.problems().add(r.key_path("deformation_gradient") + "/" + tensor_names[d],
                       "expected a positive stretch");
    }
  }

  // Steps: a count, or from the largest prescribed velocity-gradient component.
  if (r.has("steps")) {
    leg.steps =
        clamped_int(r.number("steps", Range::closed(1, 1e9), "steps in the leg"), 1, 1000000000);
    if (r.has("max_strain_increment")) {
      r.problems().add(r.key_path("max_strain_increment"), "give steps or max_strain_increment");
    }
  } else if (r.has("max_strain_increment")) {
    const double inc = r.number("max_strain_increment", Range::open_closed(0, 1),
                                "largest strain increment of a step [-]");
    double rate = 0.0;
    for (const auto& l : leg.velocity_gradient) rate = std::max(rate, l ? std::abs(*l) : 0.0);
    if (!(rate > 0.0)) {
      r.problems().add(r.key_path("max_strain_increment"),
                       "needs a nonzero velocity_gradient component; give steps instead");
    }
    const double steps = std::ceil(rate * leg.duration / inc - 1e-9);
    if (steps > 1e9) {
      r.problems().add(r.key_path("max_strain_increment"),
                       "gives " + Json(steps).dump() + " steps; expected at most 1e9");
    }
    leg.steps = clamped_int(steps, 1, 1000000000);
  } else {
    r.problems().add(r.key_path("steps"), "required: steps (or max_strain_increment)");
  }
  if (r.has("first_step")) {
    const double h0 = r.number("first_step", Range::positive(), "first of log-spaced steps [s]");
    if (leg.steps > 0 && h0 <= leg.duration / leg.steps) {
      leg.growth = log_spacing_growth(h0, leg.duration, leg.steps);
    } else if (leg.steps > 0) {
      r.problems().add(
          r.key_path("first_step"),
          "expected a first step <= duration / steps = " + Json(leg.duration / leg.steps).dump() +
              " s (log-spaced steps grow from the first one)");
    }
  }

  leg.thermal = read_thermal(r, default_thermal);
  if (leg.thermal == Thermal::prescribed) {
    leg.end_temperature = r.quantity("temperature", Quantity::temperature, Range::open(0, 1e4),
                                     "temperature at the leg's end (prescribed thermal) [K]");
  }
  if (r.has("start_temperature")) {
    leg.start_temperature =
        r.quantity("start_temperature", Quantity::temperature, Range::open(0, 1e4),
                   "temperature set at the leg's start [K]");
  }
  if (auto rot = r.optional_child("rotation", "superposed rigid rotation over the leg")) {
    leg.rotation_axis = read_vector(*rot, "axis", "rotation axis", raw["rotation"]);
    leg.rotation_angle = rot->number("angle", Range::any(), "rotation angle over the leg [rad]");
    rot->reject_unknown_keys();
  }
  r.reject_unknown_keys();
  return leg;
}

Mat3 read_tensor(JsonReader& parent, std::string_view key, std::string_view meaning,
                 const Mat3& fallback) {
  std::array<std::optional<double>, 9> c;
  read_components(parent, key, tensor_names, Range::any(), meaning, c);
  Mat3 m = fallback;
  for (int k = 0; k < 9; ++k) {
    if (c[k]) m(k / 3, k % 3) = *c[k];
  }
  return m;
}

Mat3 read_stress(JsonReader& parent, std::string_view key) {
  std::array<std::optional<double>, 6> c;
  read_components(parent, key, stress_names, Range::any(), "Cauchy stress [Pa]", c,
                  Quantity::stress);
  Mat3 s = Mat3::Zero();
  for (int k = 0; k < 6; ++k) {
    const auto [i, j] = stress_index[k];
    s(i, j) = s(j, i) = c[k].value_or(0.0);
  }
  return s;
}

/// The material file: as given (from the working directory), else beside the path file or in
/// one of its parent directories (so data/paths/x.json can name data/materials/y.json).
/// fs::exists without throwing (a name too long for the file system is simply not found).
bool file_exists(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

std::string locate_material(const std::string& name, const std::string& path_file) {
  if (file_exists(name) || fs::path(name).is_absolute()) return name;
  for (fs::path dir = fs::absolute(path_file).parent_path(); !dir.empty();
       dir = dir.parent_path()) {
    if (file_exists(dir / name)) return (dir / name).string();
    if (dir == dir.parent_path()) break;
  }
  return name;
}

}  // namespace

Path read_path(const Json& document, const std::string& file) {
  InputProblems problems(file);
  if (!document.is_object()) {
    problems.add("", "expected a JSON object with material, temperature and legs");
    problems.throw_if_any();
  }
  Path path;
  path.file = file;
  JsonReader root(document, "", problems);
  root.ignore("description");

  // Material: "file.json" or {"file": ..., "overrides": {...}} (a merge patch).
  std::string material_file;
  Json overrides = Json::object();
  if (document.contains("material") && document["material"].is_string()) {
    material_file = root.string("material", "material file");
  } else if (auto m = root.optional_child("material", "material file and inline overrides")) {
    material_file = m->string("file", "material file");
    m->ignore("overrides");
    if (document["material"].contains("overrides")) {
      overrides = document["material"]["overrides"];
      if (!overrides.is_object()) {
        problems.add("/material/overrides", "expected an object (a JSON merge patch)");
      }
    }
    m->reject_unknown_keys();
  } else {
    problems.add("/material", "required: a material file name or {\"file\", \"overrides\"}");
  }
  path.material_source = document.value("material", Json());

  path.temperature = root.quantity("temperature", Quantity::temperature, Range::open(0, 1e4),
                                   "initial temperature [K]");
  const Thermal default_thermal = read_thermal(root, Thermal::isothermal);
  const std::string policy = root.choice("failure_policy", {"stop", "freeze", "continue"},
                                         "what to do when a failure criterion fires", "stop");
  path.failure_policy = policy == "freeze"     ? FailurePolicy::freeze
                        : policy == "continue" ? FailurePolicy::continue_
                                               : FailurePolicy::stop;

  if (auto s = root.optional_child("solver", "mixed-control solver settings")) {
    auto& st = path.solver;
    st.stress_tolerance = s->number_or("stress_tolerance", st.stress_tolerance, Range::positive(),
                                       "tolerance on each controlled stress component [Pa]");
    st.relative_stress_tolerance = s->number_or(
        "relative_stress_tolerance", st.relative_stress_tolerance, Range::non_negative(),
        "tolerance on each controlled stress component relative to the largest stress [-]");
    st.strain_tolerance = s->number_or("strain_tolerance", st.strain_tolerance, Range::positive(),
                                       "tolerance on each controlled F component [-]");
    st.max_iterations =
        clamped_int(s->number_or("max_iterations", st.max_iterations, Range::closed(1, 1000),
                                 "Newton iterations per try"),
                    1, 1000);
    st.max_cutbacks = clamped_int(
        s->number_or("max_cutbacks", st.max_cutbacks, Range::closed(0, 30), "step halvings"), 0,
        30);
    const std::string j = s->choice("jacobian", {"central_difference", "elastic"}, "Newton matrix",
                                    "central_difference");
    st.jacobian = j == "elastic" ? SolverSettings::Jacobian::elastic
                                 : SolverSettings::Jacobian::central_difference;
    s->reject_unknown_keys();
  }

  // Initial state: "initial_stress" alone, or a whole "initial_state" (as a replay file writes).
  Mat3 initial_stress =
      root.has("initial_stress") ? read_stress(root, "initial_stress") : Mat3::Zero();
  PointState s0;
  bool has_state = false;
  if (auto st = root.optional_child("initial_state", "start state (as written by a replay file)")) {
    has_state = true;
    if (root.has("initial_stress")) {
      problems.add("/initial_stress", "give initial_stress or initial_state/stress, not both");
    }
    initial_stress = read_stress(*st, "stress");
    s0.F = read_tensor(*st, "deformation_gradient", "deformation gradient [-]", Mat3::Identity());
    s0.R = read_tensor(*st, "polar_rotation", "rotation R of F = R U [-]", Mat3::Identity());
    path.initial_frame =
        read_tensor(*st, "frame_rotation", "superposed rotation Q [-]", Mat3::Identity());
    s0.plastic_strain = st->number_or("plastic_strain", 0.0, Range::non_negative(), "[-]");
    s0.plastic_strain_rate =
        st->number_or("plastic_strain_rate", 0.0, Range::non_negative(), "[1/s]");
    s0.internal_energy = st->number_or("internal_energy", 0.0, Range::any(), "[J/kg]");
    s0.damage = st->number_or("damage", 0.0, Range::non_negative(), "[-]");
    s0.porosity = st->number_or("porosity", 0.0, Range::closed(0, 1), "[-]");
    s0.failed = st->boolean_or("failed", false, "failed by a criterion before the start");
    st->reject_unknown_keys();
    if (!(s0.F.determinant() > 0.0)) {
      problems.add("/initial_state/deformation_gradient", "expected det F > 0");
    }
  }

  // Legs: explicit, or named (with "type") expanded into explicit ones first.
  Json resolved_legs = Json::array();
  std::vector<std::string> origins;  // key path of each resolved leg: /legs/i, or /legs/i[k] for
                                     // the k-th leg a named leg expanded into
  if (!document.contains("legs") || !document["legs"].is_array() || document["legs"].empty()) {
    problems.add("/legs", "required: a non-empty array of legs");
    root.ignore("legs");  // reported above: not also an "unknown key"
  } else {
    root.ignore("legs");
    const Json& legs = document["legs"];
    for (std::size_t i = 0; i < legs.size(); ++i) {
      const std::string where = "/legs/" + std::to_string(i);
      if (!legs[i].is_object()) {
        problems.add(where, "expected a leg object");
        continue;
      }
      if (legs[i].contains("type")) {
        JsonReader named(legs[i], where, problems);
        int k = 0;
        for (Json& l : expand_named_leg(named, legs[i])) {
          resolved_legs.push_back(std::move(l));
          origins.push_back(where + "[" + std::to_string(k++) + "]");
        }
      } else {
        resolved_legs.push_back(legs[i]);
        origins.push_back(where);
      }
    }
    double total_steps = 0.0;
    for (std::size_t i = 0; i < resolved_legs.size(); ++i) {
      JsonReader lr(resolved_legs[i], origins[i], problems);
      path.legs.push_back(read_leg(lr, resolved_legs[i], default_thermal));
      total_steps += path.legs.back().steps;
    }
    // The step counter is an int: at most 1e9 steps in all, as in one leg.
    if (total_steps > 1e9) {
      problems.add("/legs", "the legs have " + std::to_string(static_cast<long long>(total_steps)) +
                                " steps in all; expected at most 1e9");
    }
  }
  root.ignore("checks");
  path.checks = read_checks(document, file, problems);
  root.reject_unknown_keys();
  const std::string material_path = locate_material(material_file, file);
  const std::string material_key = document.contains("material") && document["material"].is_string()
                                       ? "/material"
                                       : "/material/file";
  if (!material_file.empty() && !file_exists(material_path)) {
    problems.add(material_key,
                 "cannot find the material file '" + material_file +
                     "' (looked in the working directory, beside the path file and in its parent "
                     "directories)");
  }
  problems.throw_if_any();

  // The material file names itself in its problems and warnings; the path's entry is prefixed.
  try {
    path.material = load_material(material_path, overrides);
  } catch (const InputError& e) {
    problems.add_nested(material_key, "in material ", e);
    problems.throw_if_any();
  }
  problems.warn_nested(material_key, "in material ", path.material.warnings);
  path.warnings = problems.warnings();
  const ElasticPlastic& model = path.material.model;
  path.initial_state = has_state ? s0 : model.initial_state(path.temperature);
  if (has_state) path.initial_state.temperature = path.temperature;
  path.initial_state.stress = initial_stress;

  path.resolved = document;
  path.resolved["legs"] = resolved_legs;
  return path;
}

Path load_path(const std::string& file, const std::vector<Json>& patches) {
  Json document = load_json_file(file);
  for (const Json& p : patches) document.merge_patch(p);
  return read_path(document, file);
}

}  // namespace impact::pointdriver
