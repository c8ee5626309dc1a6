#include "mpm/input/scene_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <limits>
#include <sstream>

#include "mpm/input/scene_keys.hpp"
#include "mpm/scene/fitted_range.hpp"
#include "mpm/scene/grid_coverage.hpp"
#include "mpm/scene/planar_form.hpp"
#include "mpm/scene/seed_points.hpp"
#include "mpm/shape/shape.hpp"

namespace impact::mpm {

namespace fs = std::filesystem;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Relative material paths in a file are relative to that file; rewrite them before merging so a
// base scene reached through `extends` keeps pointing at its own materials.
void resolve_material_paths(Json& doc, const fs::path& dir) {
  if (!doc.is_object() || !doc.contains("materials") || !doc["materials"].is_object()) return;
  for (auto& item : doc["materials"].items()) {
    Json& m = item.value();
    if (!m.is_object() || !m.contains("file") || !m["file"].is_string()) continue;
    const fs::path p(m["file"].get<std::string>());
    if (p.is_relative()) m["file"] = (dir / p).lexically_normal().string();
  }
}

// "a.json -> b.json -> a.json": the files of an extends chain, as they were reached.
std::string chain_text(const std::vector<std::string>& chain, const std::string& last) {
  std::string text;
  for (const auto& f : chain) text += f + " -> ";
  return text + last;
}

// `chain` holds the files that extend this one (outermost first), to detect cycles.
Json load_with_extends(const std::string& file, std::vector<std::string>& chain,
                       ExtendsChain* layers) {
  constexpr std::size_t kMaxDepth = 16;
  Json doc = load_json_file(file);
  if (!doc.is_object()) throw InputError({file + ": expected a JSON object (a scene)"});
  const fs::path dir = fs::path(file).parent_path();
  resolve_material_paths(doc, dir);
  if (!doc.contains("extends")) {
    if (layers != nullptr) layers->emplace_back(file, doc);
    return doc;
  }
  if (!doc["extends"].is_string()) {
    throw InputError({file + ": /extends: expected a string (path of the base scene), got " +
                      doc["extends"].dump()});
  }
  const std::string named = doc["extends"].get<std::string>();
  const fs::path base_path = fs::path(named).is_relative() ? dir / named : fs::path(named);
  const std::string base = base_path.lexically_normal().string();
  std::error_code ec;
  if (const auto kind = not_a_regular_file(base_path.string())) {
    // A FIFO or a device (/dev/zero) would block or stream forever: refused unread.
    throw InputError(
        {file + ": /extends: the base scene '" + named + "' " + *kind + "; expected a scene file"});
  }
  if (!fs::is_regular_file(base_path, ec)) {
    throw InputError({file + ": /extends: cannot open the base scene '" + named + "' (looked for " +
                      base + ", relative to the file that names it)"});
  }
  chain.push_back(file);
  const fs::path canonical_base = fs::weakly_canonical(base_path, ec);
  for (const auto& f : chain) {
    if (fs::weakly_canonical(f, ec) == canonical_base) {
      throw InputError({file + ": /extends: circular extends: " + chain_text(chain, base)});
    }
  }
  if (chain.size() > kMaxDepth) {
    throw InputError({file + ": /extends: expected at most " + std::to_string(kMaxDepth) +
                      " levels of extends: " + chain_text(chain, base)});
  }
  Json merged = load_with_extends(base, chain, layers);
  chain.pop_back();
  doc.erase("extends");
  if (layers != nullptr) layers->emplace_back(file, doc);
  merged.merge_patch(doc);  // RFC 7396: objects merge key by key, null deletes, arrays replace
  return merged;
}

std::array<int, 3> read_int3(JsonReader& r, const Json& node, std::string_view key, int lo, int hi,
                             std::string_view meaning, std::optional<std::array<int, 3>> fallback) {
  const Vec3 v =
      read_vec3(r, node, key, meaning,
                fallback ? std::optional<Vec3>(Vec3((*fallback)[0], (*fallback)[1], (*fallback)[2]))
                         : std::nullopt);
  r.amend_description(key, [&](KeyDescription& d) {
    d.type = "[3 integers]";
    d.range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  });
  std::array<int, 3> out{};
  for (int d = 0; d < 3; ++d) {
    if (!(v(d) >= lo && v(d) <= hi && v(d) == std::floor(v(d)))) {
      if (!std::isnan(v(d))) {
        r.problems().add(r.key_path(key), "expected integers in [" + std::to_string(lo) + ", " +
                                              std::to_string(hi) + "] (" + std::string(meaning) +
                                              ")");
      }
      return fallback.value_or(std::array<int, 3>{1, 1, 1});
    }
    out[d] = static_cast<int>(v(d));
  }
  return out;
}

const Json& at(const Json& node, const char* key) {
  return node.is_object() && node.contains(key) ? node[key] : empty_json_object();
}

const char* const kGeometryNames[] = {"3d", "axisymmetric", "plane_strain"};

// The grid geometry the document asks for (grid.geometry, validated by read_grid; an unknown
// value reads as 3d here).
GridGeometry document_geometry(const Json& doc) {
  const Json& g = at(at(doc, "grid"), "geometry");
  if (g == kGeometryNames[1]) return GridGeometry::axisymmetric;
  if (g == kGeometryNames[2]) return GridGeometry::plane_strain;
  return GridGeometry::three_d;
}

// A 2D grid is written in its plane: grid.lower, grid.upper and grid.cells take [x, y], as do
// objects' particles_per_cell and solver.ranks_per_axis. They are read as the 3D grid of one
// cell of 1 m along z, centred on z = 0 (scene.hpp GridGeometry): this completes each [x, y]
// with its z value, and refuses three numbers where two are expected. Every other vector (the
// objects' geometry, velocities, gauge regions) stays 3D: the bodies are the 3D twin's.
Json with_plane_arrays_completed(const Json& doc, InputProblems& problems) {
  if (document_geometry(doc) == GridGeometry::three_d) return doc;
  Json out = doc;
  const auto complete = [&](Json& node, const std::string& path, const char* key, double z) {
    if (!node.is_object() || !node.contains(key) || !node[key].is_array()) return;
    Json& a = node[key];
    if (a.size() == 2) {
      a.push_back(z);
    } else if (a.size() == 3) {
      problems.add(path + "/" + key,
                   "expected an array of 2 numbers [x, y] on a 2D grid "
                   "(grid.geometry \"" +
                       at(doc["grid"], "geometry").get<std::string>() + "\"), got " + a.dump());
      a[2] = z;  // read on, so that the other problems show too
    }
  };
  Json& grid = out["grid"];
  complete(grid, "/grid", "lower", -0.5);
  complete(grid, "/grid", "upper", 0.5);
  complete(grid, "/grid", "cells", 1);
  if (out.contains("solver") && out["solver"].is_object())
    complete(out["solver"], "/solver", "ranks_per_axis", 1);
  if (out.contains("objects") && out["objects"].is_object())
    for (auto& item : out["objects"].items())
      complete(item.value(), "/objects/" + item.key(), "particles_per_cell", 1);
  // Positions in the plane may be written [x, y] too (the particles lie at z = 0); [x, y, z]
  // stays valid for them, as for the bodies.
  const auto position = [](Json& node, const char* key) {
    if (node.is_object() && node.contains(key) && node[key].is_array() && node[key].size() == 2)
      node[key].push_back(0.0);
  };
  if (out.contains("output") && out["output"].is_object()) {
    Json& output = out["output"];
    if (output.contains("gauges") && output["gauges"].is_object())
      for (auto& item : output["gauges"].items())
        if (item.value().is_object() && item.value().contains("region")) {
          position(item.value()["region"], "lower");
          position(item.value()["region"], "upper");
        }
    if (output.contains("particle_paths") && output["particle_paths"].is_object())
      for (auto& item : output["particle_paths"].items()) position(item.value(), "position");
  }
  return out;
}

void read_grid(JsonReader& root, const Json& doc, GridSpec& g) {
  JsonReader r = root.child("grid", "background grid");
  const Json& n = at(doc, "grid");
  const std::string geometry =
      r.choice("geometry", {kGeometryNames[0], kGeometryNames[1], kGeometryNames[2]},
               "3d, or a 2D grid in the x-y plane: axisymmetric (x the axis, y the radius >= 0; "
               "totals of the revolved body) or plane_strain (per metre along z)",
               kGeometryNames[0]);
  g.geometry = geometry == kGeometryNames[1]   ? GridGeometry::axisymmetric
               : geometry == kGeometryNames[2] ? GridGeometry::plane_strain
                                               : GridGeometry::three_d;
  g.lower = read_vec3(r, n, "lower", "lower corner of the grid [m] ([x, y] on a 2D grid)");
  g.upper = read_vec3(r, n, "upper", "upper corner of the grid [m] ([x, y] on a 2D grid)");
  g.cells =
      read_int3(r, n, "cells", 1, 100000, "cells per axis ([x, y] on a 2D grid)", std::nullopt);
  // The grid stores (cells + 3) nodes per axis (ghost layers) and indexes them with int; a 2D
  // grid one node plane along z.
  const double stored_nodes =
      (g.cells[0] + 3.0) * (g.cells[1] + 3.0) * (g.planar() ? 1.0 : g.cells[2] + 3.0);
  if (stored_nodes > static_cast<double>(std::numeric_limits<int>::max())) {
    std::ostringstream m;
    m << "(cells + 3) per axis multiplied is " << stored_nodes
      << " stored grid nodes: expected at most 2147483647 (2^31 - 1)";
    r.problems().add(r.key_path("cells"), m.str());
  }
  if (!((g.upper - g.lower).array() > 0.0).all()) {
    r.problems().add(r.key_path("upper"), "expected upper > lower on every axis");
  } else if (auto hint = unit_hint(Quantity::length, (g.upper - g.lower).maxCoeff())) {
    // A scene typed in millimetres shows in the grid, which spans every object.
    r.problems().warn(r.key_path("upper"),
                      "largest extent (upper - lower) " + *hint + "; the value is used as given");
  }
  if (g.geometry == GridGeometry::axisymmetric && g.lower(1) != 0.0 && std::isfinite(g.lower(1))) {
    std::ostringstream got;  // as typed, 1e-09 too (std::to_string would print 0.000000)
    got << g.lower(1);
    r.problems().add(r.key_path("lower") + "/1",
                     "an axisymmetric grid starts at the axis, y = 0 (y is the radius); expected "
                     "0, got " +
                         got.str());
  }
  g.faces.fill(FaceCondition::symmetric);
  // A 2D grid has no faces along z (its one cell of 1 m is not a mesh axis): they are free.
  const int faces = g.planar() ? 4 : 6;
  if (g.planar()) g.faces[4] = g.faces[5] = FaceCondition::free;
  if (auto b = r.optional_child("boundary", "condition per face: symmetric, fixed, free or wall")) {
    for (int f = 4; f < 6 && g.planar(); ++f)
      if (b->has(kFaceNames[f])) {
        b->problems().add(b->key_path(kFaceNames[f]),
                          std::string("a 2D grid (grid.geometry \"") + geometry +
                              "\") has no face along z; expected faces x-, x+, y- and y+ only");
        b->ignore(kFaceNames[f]);
      }
    for (int f = 0; f < faces; ++f) {
      const std::string c = b->choice(kFaceNames[f], {"symmetric", "fixed", "free", "wall"},
                                      "grid face condition (symmetric: frictionless mirror plane; "
                                      "wall: rigid wall that never pulls, with friction)",
                                      "symmetric");
      g.faces[f] = c == "fixed"  ? FaceCondition::fixed
                   : c == "free" ? FaceCondition::free
                   : c == "wall" ? FaceCondition::wall
                                 : FaceCondition::symmetric;
      if (f == 2 && g.geometry == GridGeometry::axisymmetric && c != "symmetric")
        b->problems().add(b->key_path(kFaceNames[f]),
                          "the face y- of an axisymmetric grid is the axis of symmetry, where the "
                          "radial velocity is zero: expected \"symmetric\", got \"" +
                              c + "\"");
    }
    b->reject_unknown_keys();
  }
  if (auto w = r.optional_child("wall_friction", "Coulomb friction coefficient per wall face")) {
    for (int f = 0; f < 6; ++f) {
      if (!w->has(kFaceNames[f])) continue;
      if (g.faces[f] != FaceCondition::wall) {
        w->problems().add(w->key_path(kFaceNames[f]),
                          std::string("face ") + kFaceNames[f] +
                              " is not a wall: friction acts only on a face whose "
                              "grid.boundary." +
                              kFaceNames[f] + " is \"wall\"");
        w->ignore(kFaceNames[f]);  // reported above, not also as an unknown key
        continue;
      }
      g.wall_friction[f] =
          w->number(kFaceNames[f], Range::closed(0.0, 10.0), "Coulomb coefficient mu [-]");
      w->amend_description(kFaceNames[f], [](KeyDescription& d) { d.default_value = "0"; });
    }
    w->reject_unknown_keys();
  }
  g.active_blocks = r.boolean_or(
      "active_blocks", true,
      "grid work only where the particles are (false: every node of the box every step)");
  g.outflow = r.choice("outflow", {"stop", "remove"},
                       "a particle that leaves the grid: stop the run, or remove it and book its "
                       "mass, momentum and kinetic energy as outflow",
                       "stop") == "remove"
                  ? Outflow::remove
                  : Outflow::stop;
  r.reject_unknown_keys();
}

// The explicit step is stable up to about multiplier 1 (CFL); larger values are allowed so that a
// user can test where it fails (docs/accuracy.md#stability-map), but never silently.
constexpr double kMaxMultiplier = 1.5;

void read_time(JsonReader& root, TimeSpec& t, std::vector<std::string>& warnings) {
  JsonReader r = root.child("time", "time stepping (the report's <Time> block)");
  t.max_time = r.number("max_time", Range::positive(), "end time [s]");
  t.initial_dt = r.number_or("initial_dt", kInf, Range::positive(),
                             "first step, capped at the stable step [s]; default: stable step");
  t.min_dt = r.number_or("min_dt", 0.0, Range::non_negative(),
                         "the run stops when the step falls below this [s]");
  t.max_dt = r.number_or("max_dt", kInf, Range::positive(), "cap on the step [s]");
  t.multiplier = r.number_or("multiplier", 0.5, Range::open_closed(0.0, kMaxMultiplier),
                             "factor on the stable step (CFL number) [-]");
  if (t.multiplier > 1.0 && t.multiplier <= kMaxMultiplier) {
    std::ostringstream w;
    w << r.problems().file() << ": " << r.key_path("multiplier") << ": " << t.multiplier
      << " is above 1, the 1-D CFL limit of the stable step: the run may go unstable (the "
         "energy-growth check, time.max_energy_growth, stops it; docs/accuracy.md)";
    warnings.push_back(w.str());
  }
  t.max_energy_growth =
      r.number_or("max_energy_growth", 1.0, Range::positive(),
                  "the run stops when energy_error exceeds this (+1 = +100 % of the energy that "
                  "entered) [-]");
  t.max_estimated_steps = r.number_or(
      "max_estimated_steps", TimeSpec{}.max_estimated_steps, Range::positive(),
      "mpm run refuses a scene whose step count, estimated before the run (max_time over the "
      "first stable step), exceeds this [-]");
  t.max_estimated_particle_steps = r.number_or(
      "max_estimated_particle_steps", TimeSpec{}.max_estimated_particle_steps, Range::positive(),
      "mpm run refuses a scene whose particle-steps, estimated before the run (the particles "
      "the geometry seeds times the estimated steps), exceed this [-]");
  if (t.min_dt > t.max_dt) r.problems().add(r.key_path("min_dt"), "expected min_dt <= max_dt");
  r.reject_unknown_keys();
}

void read_solver(JsonReader& root, const Json& doc, SolverSpec& s) {
  // Every solver and output key has a default, so the blocks themselves are optional.
  JsonReader r = root.optional_child("solver", "algorithm choices")
                     .value_or(JsonReader(empty_json_object(), "/solver", root.problems()));
  s.interpolation = r.choice("interpolation", shape_names(),
                             "shape functions (mpm/shape/shape.hpp)", shape_names().front());
  s.scheme = r.choice("scheme", {"usl", "musl"}, "update scheme", "musl") == "usl" ? Scheme::usl
                                                                                   : Scheme::musl;
  s.f_integration =
      r.choice("deformation_gradient", {"forward_euler", "exponential"},
               "F_{n+1} = (I + L dt) F_n or exp(L dt) F_n", "forward_euler") == "exponential"
          ? FIntegration::exponential
          : FIntegration::forward_euler;
  s.gravity =
      read_vec3(r, at(doc, "solver"), "gravity", "body force per unit mass [m/s^2]", Vec3::Zero());
  s.rebalance_above = r.number_or(
      "rebalance_above", 1.2, Range::open(1.0, std::numeric_limits<double>::infinity()),
      "several ranks: re-balance the boxes when the largest particle count exceeds this multiple "
      "of the mean [-]");
  const Json& solver = at(doc, "solver");
  if (solver.is_object() && solver.contains("ranks_per_axis") &&
      solver["ranks_per_axis"].is_string()) {
    s.split = r.choice("ranks_per_axis", {"fewest_cut_faces", "least_loaded"},
                       "several ranks: the split cutting the fewest node faces, or the least "
                       "loaded boxes",
                       "fewest_cut_faces") == "least_loaded"
                  ? SplitRule::least_loaded
                  : SplitRule::fewest_cut_faces;
  } else {
    s.ranks_per_axis = read_int3(
        r, solver, "ranks_per_axis", 0, 1 << 20,
        "several ranks: boxes per axis, their product the rank count; [0, 0, 0] chooses the "
        "split cutting the fewest node faces (\"fewest_cut_faces\"), \"least_loaded\" the "
        "least loaded boxes",
        std::array<int, 3>{0, 0, 0});
  }
  const auto& p = s.ranks_per_axis;
  if ((p[0] == 0 || p[1] == 0 || p[2] == 0) && !(p[0] == 0 && p[1] == 0 && p[2] == 0))
    r.problems().add(r.key_path("ranks_per_axis"),
                     "expected three integers >= 1, [0, 0, 0] for the automatic split, or "
                     "\"least_loaded\"");
  r.reject_unknown_keys();
}

void read_physics(JsonReader& root, PhysicsSpec& ph) {
  JsonReader r = root.optional_child("physics", "optional physics (the report's <MPM> flags)")
                     .value_or(JsonReader(empty_json_object(), "/physics", root.problems()));
  if (auto c = r.optional_child("contact", "interaction of the materials' velocity fields")) {
    // "approach" is the report's name for the same model as "friction" (contact/contact.hpp).
    const std::string type = c->choice("type", {"single_velocity", "friction", "approach"},
                                       "contact model", "single_velocity");
    ph.contact.type =
        type == "single_velocity" ? ContactType::single_velocity : ContactType::friction;
    ph.contact.mu =
        c->number_or("mu", 0.0, Range::non_negative(), "Coulomb friction coefficient [-]");
    const std::string normal =
        c->choice("normal", {"mass_gradients", "larger_volume", "logistic_regression"},
                  "contact normal at a node", "mass_gradients");
    ph.contact.normal = normal == "larger_volume"         ? ContactNormal::larger_volume
                        : normal == "logistic_regression" ? ContactNormal::logistic_regression
                                                          : ContactNormal::mass_gradients;
    // One shared velocity field has no contact surface: a friction coefficient or a normal rule
    // there would be read and ignored, so it is refused (issue 53). A scene that extends one with
    // friction removes the inherited keys with null (RFC 7396).
    if (ph.contact.type == ContactType::single_velocity)
      for (const char* key : {"mu", "normal"})
        if (c->has(key))
          c->problems().add(c->key_path(key),
                            "read only by the \"friction\" contact (also called \"approach\"); "
                            "\"single_velocity\" is one velocity field with no contact surface: "
                            "remove the key (null removes one inherited through \"extends\") or "
                            "set type to \"friction\"");
    c->reject_unknown_keys();
  }
  if (auto a = r.optional_child("artificial_viscosity", "bulk viscosity, report eq. 12")) {
    ph.artificial_viscosity.enabled = a->boolean_or("enabled", true, "switch");
    ph.artificial_viscosity.linear =
        a->number_or("linear", 0.2, Range::non_negative(), "C_L, linear coefficient [-]");
    ph.artificial_viscosity.quadratic =
        a->number_or("quadratic", 2.0, Range::non_negative(), "C_0, quadratic coefficient [-]");
    a->reject_unknown_keys();
  }
  ph.create_new_particles = r.boolean_or("create_new_particles", false,
                                         "move failed particles to a companion velocity field");
  ph.on_numerical_fault =
      r.choice("on_numerical_fault", {"stop", "fail_particle"},
               "what a particle's numerical fault does: stop the run, or flag the particle failed "
               "and go on",
               "stop") == "fail_particle"
          ? NumericalFaultAction::fail_particle
          : NumericalFaultAction::stop;
  if (r.has("erosion")) {
    const std::string e =
        r.choice("erosion", {"none", "AllowNoTension", "KeepStress", "ZeroStress"},
                 "erosion algorithm for every material", "none");
    ph.erosion = erosion_from_name(e);
  }
  if (r.has("do_melting")) {
    ph.do_melting = r.boolean_or("do_melting", true, "remove the deviator of melted particles");
  }
  if (r.has("turn_on_adiabatic_heating")) {
    ph.adiabatic_heating =
        r.boolean_or("turn_on_adiabatic_heating", true, "heat particles by plastic work");
  }
  // Absent, each material keeps its own file's choice: no one default value. The catalogue of
  // keys is shared by every read (mpm keys read the sample scene five times): added once.
  for (const char* key : {"erosion", "do_melting", "turn_on_adiabatic_heating"}) {
    r.amend_description(key, [](KeyDescription& d) {
      constexpr std::string_view kNote = " (absent: each material file's own choice)";
      d.default_value = std::string(kComputedDefault);
      if (d.meaning.find(kNote) == std::string::npos) d.meaning += kNote;
    });
  }
  r.reject_unknown_keys();
}

// The scene's physics flags override every material's own choice (the report set them once, in
// its <MPM> block, for all materials).
void apply_physics_overrides(const PhysicsSpec& ph, std::vector<SceneMaterial>& materials) {
  for (SceneMaterial& m : materials) {
    ElasticPlasticParams p = m.material.model.params();
    if (ph.erosion) p.erosion = *ph.erosion;
    if (ph.do_melting) p.melting.do_melting = *ph.do_melting;
    if (ph.adiabatic_heating) p.heating.enabled = *ph.adiabatic_heating;
    m.material.model = ElasticPlastic(p);
  }
}

void read_output(JsonReader& root, const Json& doc, const std::string& file, double max_time,
                 OutputSpec& o) {
  JsonReader r = root.optional_child("output", "what is written and where")
                     .value_or(JsonReader(empty_json_object(), "/output", root.problems()));
  const Json& n = at(doc, "output");
  o.directory = r.string_or("directory", "out/" + fs::path(file).stem().string(),
                            "output directory (relative to the working directory)");
  o.interval = r.number_or("interval", max_time / 100.0, Range::positive(),
                           "history row and snapshot interval [s]; default max_time/100");
  o.snapshots = r.boolean_or("snapshots", true, "write particles/step_NNNNNN.vtu and a .pvd");
  o.plastic_work = r.boolean_or("plastic_work", false,
                                "history column plastic_work [J]: the plastic work done so far");
  const double every =
      r.number_or("checkpoint_interval_steps", 0.0, Range::closed(0.0, 1e15),
                  "write DIR/checkpoint.bin every this many steps (0: off; mpm run --restart DIR)");
  if (every != std::floor(every)) {
    r.problems().add(r.key_path("checkpoint_interval_steps"),
                     "expected a whole number of steps (0: off)");
  }
  o.checkpoint_interval_steps = static_cast<long>(every);
  o.fields = {"velocity", "stress", "plastic_strain", "temperature", "damage", "mass"};
  r.read_elsewhere("fields", [&] {
    std::string names;
    for (const auto& f : o.fields) names += (names.empty() ? "" : ", ") + f;
    return KeyDescription{"array of names", "", names, "VTU point data"};
  });
  // Read by read_observables(), once the objects are known.
  r.read_elsewhere("gauges", [] {
    return KeyDescription{"object", "", "", "named history gauges: one history.csv column each"};
  });
  r.read_elsewhere("crater", [] {
    return KeyDescription{"object", "", "", "crater depth and diameter in summary.json"};
  });
  r.read_elsewhere("particle_paths", [] {
    return KeyDescription{"object", "", "", "point-driver paths of chosen particles"};
  });
  if (n.is_object() && n.contains("fields")) {
    const Json& f = n["fields"];
    o.fields.clear();
    if (!f.is_array()) {
      r.problems().add(r.key_path("fields"), "expected an array of field names");
    } else {
      for (std::size_t i = 0; i < f.size(); ++i) {
        const auto& known = known_output_fields();
        if (!f[i].is_string() ||
            std::find(known.begin(), known.end(), f[i].get<std::string>()) == known.end()) {
          std::string list;
          for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
          r.problems().add(r.key_path("fields") + "/" + std::to_string(i),
                           "unknown field " + f[i].dump() + "; known: " + list);
        } else {
          o.fields.push_back(f[i].get<std::string>());
        }
      }
    }
  }
  r.reject_unknown_keys();
}

void read_materials(JsonReader& root, const Json& doc, std::vector<SceneMaterial>& out) {
  // Material files name themselves in their problems and warnings; the scene entry is prefixed.
  JsonReader r = root.child("materials", "named materials");
  const Json& n = at(doc, "materials");
  if (!n.is_object()) return;
  for (const auto& item : n.items()) {
    JsonReader m = r.child(item.key(), "a material: file and inline overrides");
    const std::string file = m.string("file", "material file, e.g. data/materials/al6061_t6.json");
    m.read_elsewhere("overrides", [] {
      return KeyDescription{"object", "", "{}",
                            "JSON merge patch applied to the material file before validation"};
    });
    const Json& ov = at(item.value(), "overrides");
    if (item.value().is_object() && item.value().contains("overrides") && !ov.is_object()) {
      m.problems().add(m.key_path("overrides"), "expected an object (a JSON merge patch)");
    }
    m.reject_unknown_keys();
    if (file.empty()) continue;
    try {
      out.push_back({item.key(), load_material(file, ov.is_object() ? ov : Json::object())});
      m.problems().warn_nested(m.key_path("file"), "in material ", out.back().material.warnings);
    } catch (const InputError& e) {
      // The material reader names the material file; say which scene entry asked for it.
      m.problems().add_nested(m.key_path("file"), "in material ", e);
    }
  }
  if (out.empty() && r.problems().empty()) {
    r.problems().add("/materials", "expected at least one material");
  }
}

void read_objects(JsonReader& root, const Json& doc, const std::vector<SceneMaterial>& materials,
                  std::vector<SceneObject>& out) {
  JsonReader r = root.child("objects", "named objects (bodies) to seed with particles");
  const Json& n = at(doc, "objects");
  if (!n.is_object()) return;
  for (const auto& item : n.items()) {
    JsonReader o = r.child(item.key(), "an object");
    const Json& on = item.value();
    SceneObject obj;
    obj.name = item.key();
    const std::string mat = o.string("material", "name of an entry of /materials");
    auto it = std::find_if(materials.begin(), materials.end(),
                           [&](const SceneMaterial& m) { return m.name == mat; });
    // A declared material that failed to load has its own problem already: no second one here.
    const Json& declared = at(doc, "materials");
    if (it == materials.end() && !mat.empty() &&
        !(declared.is_object() && declared.contains(mat))) {
      std::string list;
      if (declared.is_object()) {
        for (const auto& m : declared.items()) list += (list.empty() ? "" : ", ") + m.key();
      }
      o.problems().add(o.key_path("material"), "unknown material \"" + mat + "\"; known: " + list);
    } else if (it != materials.end()) {
      obj.material = static_cast<int>(it - materials.begin());
    }
    JsonReader g = o.child("geometry", "shape of the object");
    obj.geometry = read_geometry(g, at(on, "geometry"));
    g.reject_unknown_keys();
    obj.velocity = read_vec3(o, on, "velocity", "initial velocity [m/s]", Vec3::Zero());
    for (int d = 0; d < 3; ++d) {
      o.problems().check_units(o.key_path("velocity") + "/" + std::to_string(d), Quantity::speed,
                               obj.velocity(d));
    }
    obj.temperature = o.quantity_or("temperature", 294.0, Quantity::temperature,
                                    Range::open(0.0, 1e4), "initial temperature [K]");
    obj.particles_per_cell =
        read_int3(o, on, "particles_per_cell", 1, 16,
                  "particles per cell per axis (the report's res)", std::array<int, 3>{2, 2, 2});
    o.reject_unknown_keys();
    out.push_back(std::move(obj));
  }
  if (out.empty() && r.problems().empty()) {
    r.problems().add("/objects", "expected at least one object");
  }
}

std::string object_names(const std::vector<SceneObject>& objects) {
  std::string list;
  for (const auto& o : objects) list += (list.empty() ? "" : ", ") + o.name;
  return list;
}

// The index of the object named at `key` of `r`, or -1 (a problem listing the known objects).
int read_object_name(JsonReader& r, const std::vector<SceneObject>& objects,
                     std::string_view meaning) {
  const std::string name = r.string("object", meaning);
  if (name.empty()) return -1;
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (objects[i].name == name) return static_cast<int>(i);
  r.problems().add(r.key_path("object"),
                   "unknown object \"" + name + "\"; known: " + object_names(objects));
  return -1;
}

// A name that becomes part of an output (a history column, a file name): letters, digits and _.
bool is_output_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// output.gauges and output.crater (docs/scenes.md): need the objects, and (for "no particle
// inside") the grid and the objects' geometry, so they are read after everything else.
void read_observables(InputProblems& problems, const Json& doc, Scene& s) {
  const Json& out = at(doc, "output");
  const bool check_seeds = problems.empty();  // grid and objects valid: the seeds can be counted
  if (out.is_object() && out.contains("gauges")) {
    const Json& gauges = out["gauges"];
    JsonReader r(gauges, "/output/gauges", problems);
    if (!gauges.is_object()) {
      problems.add("/output/gauges", "expected an object of named gauges");
    } else {
      for (const auto& item : gauges.items()) {
        JsonReader g = r.child(item.key(), "a gauge: type, object, region, component");
        const std::string& name = item.key();
        if (!is_output_name(name)) {
          problems.add(r.key_path(name),
                       "expected a gauge name of letters, digits and _ (it becomes the history "
                       "column gauge_<name>)");
        }
        GaugeSpec spec;
        spec.name = name;
        const std::string type = g.choice("type", {"velocity", "strain", "pressure"},
                                          "what the gauge averages over its particles");
        spec.type = type == "strain"     ? GaugeType::strain
                    : type == "pressure" ? GaugeType::pressure
                                         : GaugeType::velocity;
        const int object = read_object_name(g, s.objects, "name of an entry of /objects");
        JsonReader region = g.child("region", "box of initial particle positions [m]");
        const Json& rn = at(item.value(), "region");
        spec.lower = read_vec3(region, rn, "lower", "lower corner of the region [m]");
        spec.upper = read_vec3(region, rn, "upper", "upper corner of the region [m]");
        const bool box_ok = (spec.upper.array() >= spec.lower.array()).all();
        if (!box_ok && spec.lower.allFinite() && spec.upper.allFinite()) {
          problems.add(region.key_path("upper"), "expected upper >= lower on every axis");
        }
        region.reject_unknown_keys();
        if (type == "pressure") {
          if (g.has("component")) {
            g.ignore("component");
            problems.add(g.key_path("component"),
                         "a pressure gauge has no component (remove the key)");
          }
        } else if (!type.empty()) {
          const std::string c =
              g.choice("component", {"x", "y", "z"},
                       type == "strain" ? "axis of the log strain" : "velocity component");
          spec.component = c == "y" ? 1 : c == "z" ? 2 : 0;
        }
        g.reject_unknown_keys();
        if (object < 0) continue;
        spec.object = object;
        // The first seed point found will do: the count (mpm check, summary.json) waits until
        // the memory and step estimates have let the scene through.
        if (check_seeds && box_ok &&
            !seeds_a_point(s, static_cast<std::size_t>(object), spec.lower, spec.upper)) {
          problems.add(g.key_path("region"), "no particle of object \"" + s.objects[object].name +
                                                 "\" inside (initial positions): expected a "
                                                 "region that contains at least one particle");
        }
        s.output.gauges.push_back(std::move(spec));
      }
    }
  }
  if (out.is_object() && out.contains("crater")) {
    const Json& cn = out["crater"];
    JsonReader c(cn.is_object() ? cn : empty_json_object(), "/output/crater", problems);
    if (!cn.is_object()) {
      problems.add("/output/crater", "expected an object {\"object\": ..., \"face\": ...}");
    } else {
      CraterSpec spec;
      const int object = read_object_name(c, s.objects, "the impacted object");
      spec.face = c.number("face", Range::any(), "x of the impacted face [m] (impact along +x)");
      if (c.has("axis_y") || c.has("axis_z")) {  // both or neither
        spec.axis = std::array<double, 2>{
            c.number("axis_y", Range::any(), "y of the crater axis [m] (quarter model: 0)"),
            c.number("axis_z", Range::any(), "z of the crater axis [m] (quarter model: 0)")};
        // An axisymmetric crater is centred on the axis of symmetry, y = z = 0.
        if (s.grid.geometry == GridGeometry::axisymmetric &&
            ((*spec.axis)[0] != 0.0 || (*spec.axis)[1] != 0.0))
          problems.add(c.key_path("axis_y"),
                       "the crater of an axisymmetric scene is centred on the axis of symmetry: "
                       "expected axis_y = axis_z = 0, or neither key");
      }
      c.reject_unknown_keys();
      if (object >= 0 && std::isfinite(spec.face)) {
        spec.object = object;
        const double dx = s.grid.spacing()(0);
        if (check_seeds && !seeds_a_point(s, static_cast<std::size_t>(object),
                                          Vec3(spec.face - dx, s.grid.lower(1), s.grid.lower(2)),
                                          Vec3(spec.face + dx, s.grid.upper(1), s.grid.upper(2)))) {
          problems.add(c.key_path("face"),
                       "no particle of object \"" + s.objects[object].name +
                           "\" within one cell of the face: expected the x of a face of it [m]");
        }
        s.output.crater = spec;
      }
    }
  }
  if (out.is_object() && out.contains("particle_paths")) {
    const Json& paths = out["particle_paths"];
    JsonReader r(paths, "/output/particle_paths", problems);
    if (!paths.is_object()) {
      problems.add("/output/particle_paths", "expected an object of named particle paths");
    } else {
      for (const auto& item : paths.items()) {
        JsonReader g = r.child(item.key(), "a particle path: object, position");
        const std::string& name = item.key();
        if (!is_output_name(name)) {
          problems.add(r.key_path(name),
                       "expected a name of letters, digits and _ (it becomes the file "
                       "paths/<name>.json)");
        }
        ParticlePathSpec spec;
        spec.name = name;
        const int object = read_object_name(g, s.objects, "name of an entry of /objects");
        spec.position = read_vec3(g, item.value(), "position",
                                  "initial position [m]; the object's nearest particle is taken");
        g.reject_unknown_keys();
        if (object < 0) continue;
        spec.object = object;
        s.output.particle_paths.push_back(std::move(spec));
      }
    }
  }
}

std::string vec_text(const Vec3& v) {
  std::ostringstream o;
  o.precision(4);
  o << '[' << v(0) << ", " << v(1) << ", " << v(2) << ']';
  return o.str();
}

// Below this fraction of its volume inside the grid a body is refused: a length typed in mm
// makes a body 1e9 times too large (mpm check measured a volume ratio of 1.9e-9), and a scene
// that means to seed a thousandth of a body should give the body the size it means.
constexpr double kMinInside = 1e-3;
// Above this fraction lost beyond the grid (not mirrored by a symmetric face) a body is warned
// about; below it the loss is within the seeding's own staircase (volume ratios 0.97-1.03 on the
// shipped scenes) and the coverage lattice's resolution.
constexpr double kMaxSilentLoss = 0.01;

// Every object must lie in the grid: one wholly or almost wholly outside (no particle, or a
// body typed in mm on a grid in m) is refused, one the grid clips is warned about. The checks are
// on the whole scene, so every rank of a run finds the same.
void check_objects_in_grid(InputProblems& problems, const Scene& s) {
  const GridSpec& g = s.grid;
  // A 2D grid as it was typed, [x, y] (its z extent is the reader's, scene.hpp GridGeometry).
  const auto corner = [&](const Vec3& v) {
    if (!g.planar()) return vec_text(v);
    std::ostringstream o;
    o.precision(4);
    o << '[' << v(0) << ", " << v(1) << ']';
    return o.str();
  };
  const std::string grid_text = corner(g.lower) + " to " + corner(g.upper) + " m";
  for (std::size_t oi = 0; oi < s.objects.size(); ++oi) {
    const SceneObject& o = s.objects[oi];
    const std::string key = "/objects/" + o.name + "/geometry";
    const auto [lo, hi] = bounds(o.geometry);
    const std::string box_text = "its bounding box " + vec_text(lo) + " to " + vec_text(hi) + " m";
    const GridCoverage c = grid_coverage(o.geometry, g);
    std::ostringstream m;
    m.precision(3);
    if (c.disjoint || (c.sampled && c.inside == 0.0 && c.inside_bound >= kMinInside)) {
      m << "lies wholly outside the grid " << grid_text << " (" << box_text
        << "): no particle would be seeded; expected a body inside the grid";
      problems.add(key, m.str());
      continue;
    }
    // The bound is exact; the lattice may miss a sliver inside a body much larger than the grid.
    const bool bounded = c.inside_bound < kMinInside;
    if (bounded || (c.sampled && c.inside < kMinInside)) {
      const double share = bounded ? c.inside_bound : c.inside;
      m << (bounded ? "at most " : "only about ");
      if (share > 0.0) {
        m << share;
      } else {  // below the doubles: a body of 1e300 m
        m << "a share below 1e-300";
      }
      const double v = volume(o.geometry);
      m << " of its volume (";
      if (std::isfinite(v)) {
        m << v;
      } else {
        m << "beyond 1.8e+308";
      }
      m << " m^3) lies inside the grid " << grid_text << " (" << box_text << "); expected at least "
        << kMinInside << " (lengths in m";
      if (auto hint = unit_hint(Quantity::length, (hi - lo).maxCoeff()))
        m << "; its largest extent " << *hint;
      m << ')';
      problems.add(key, m.str());
      continue;
    }
    if (!seeds_a_point(s, oi)) {
      const Vec3 spacing = g.spacing().cwiseQuotient(
          Vec3(o.particles_per_cell[0], o.particles_per_cell[1], o.particles_per_cell[2]));
      m << "no particle would be seeded: none of the seed points (sub-cell centres, spacing "
        << vec_text(spacing) << " m) lies inside it and outside every earlier object (" << box_text
        << "); expected a body larger than the seed spacing (refine grid.cells or "
        << "particles_per_cell)";
      problems.add(key, m.str());
      continue;
    }
    if (c.lost > kMaxSilentLoss) {
      std::string faces;
      for (std::size_t f = 0; f < 6; ++f)
        if (c.lost_through[f]) faces += (faces.empty() ? "" : ", ") + std::string(kFaceNames[f]);
      m << "clipped by the grid: about " << c.inside << " of its volume lies inside the grid "
        << grid_text << "; " << c.lost << " lies beyond the face(s) " << faces
        << " and is not seeded (" << box_text << "); the part inside is used as given";
      problems.warn(key, m.str());
    }
  }
}

// On a 2D grid every body must have its 2D form (mpm/scene/planar_form.hpp) and move in the
// plane: along the axis when axisymmetric (a uniform radial velocity is no body of revolution's),
// with no z component in plane strain; gravity likewise.
void check_planar_scene(InputProblems& problems, Scene& s) {
  const GridGeometry kind = s.grid.geometry;
  if (kind == GridGeometry::three_d) return;
  const bool axi = kind == GridGeometry::axisymmetric;
  const std::string grid = std::string("grid.geometry \"") + kGeometryNames[int(kind)] + "\"";
  const auto moves_in_plane = [&](const Vec3& v) { return v(2) == 0.0 && (!axi || v(1) == 0.0); };
  const std::string expected =
      axi ? "expected [v, 0, 0]: a body of revolution moves along its axis x"
          : "expected [vx, vy, 0]: a plane-strain body moves in the x-y plane";
  for (SceneObject& o : s.objects) {
    const std::string key = "/objects/" + o.name;
    const std::string why = planar_form_problem(o.geometry, kind);
    if (!why.empty()) problems.add(key + "/geometry", why + " (" + grid + ")");
    if (!moves_in_plane(o.velocity))
      problems.add(key + "/velocity",
                   "initial velocity " + vec_text(o.velocity) + " on " + grid + ": " + expected);
    o.particles_per_cell[2] = 1;  // the one cell along z
  }
  if (!moves_in_plane(s.solver.gravity))
    problems.add("/solver/gravity",
                 "gravity " + vec_text(s.solver.gravity) + " on " + grid + ": " + expected);
  if (s.solver.ranks_per_axis[2] > 1)
    problems.add("/solver/ranks_per_axis",
                 "a 2D grid is split in x and y only; expected [px, py] (" + grid + ")");
}

// Multi-field contact keeps per-node arrays of kMaxContactFields fields (contact.cpp): a scene
// with more velocity fields is refused here rather than have the rest ignored.
void check_field_count(InputProblems& problems, const Scene& s) {
  const int fields = s.field_count();
  if (fields <= kMaxContactFields) return;
  const bool conversion = s.physics.create_new_particles;
  std::ostringstream m;
  m << s.materials.size() << " materials make " << fields << " velocity fields"
    << (conversion ? " (each with a companion field: physics.create_new_particles)" : "")
    << " under physics.contact.type \""
    << (s.physics.contact.type == ContactType::friction ? "friction" : "approach")
    << "\": expected at most " << kMaxContactFields << " fields ("
    << (conversion ? kMaxContactFields / 2 : kMaxContactFields)
    << " materials), or contact \"single_velocity\" (one field)";
  problems.add("/materials", m.str());
}

// Contact separates materials, not objects (a material's particles share one velocity field): two
// objects of one material meet as one body, as with single_velocity. Valid, and what a scene of
// one body cut into objects wants, but a user who set friction between them gets no contact.
void warn_of_contact_within_one_material(Scene& s) {
  if (s.physics.contact.type != ContactType::friction || s.physics.create_new_particles ||
      s.objects.size() < 2)
    return;
  for (const SceneObject& o : s.objects)
    if (o.material != s.objects.front().material) return;
  s.warnings.push_back(
      "/physics/contact: \"friction\" acts between materials, and every object here is of "
      "material \"" +
      s.materials[s.objects.front().material].name +
      "\": they share one velocity field and meet as one body, as with \"single_velocity\"; "
      "give each body its own material (the same file under another name) for contact between "
      "them");
}

}  // namespace

Json load_scene_document(const std::string& file, ExtendsChain* chain) {
  std::vector<std::string> extending;
  return load_with_extends(file, extending, chain);
}

void resolve_patch_material_paths(Json& patch) {
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  if (!ec) resolve_material_paths(patch, cwd);
}

PatchOrigins extends_origins(const ExtendsChain& chain) {
  std::vector<Json> documents;
  for (const auto& layer : chain) documents.push_back(layer.second);
  const std::string file = chain.empty() ? std::string() : chain.back().first;
  return PatchOrigins(
      file, documents,
      [&](std::size_t k) {
        return k + 1 == chain.size() ? std::string()
                                     : chain[k].first + " (extended by " + file + ")";
      },
      /*over_file=*/false);
}

Scene read_scene(const Json& document, const std::string& file, InputKeyRecorder* keys) {
  InputProblems problems(file);
  problems.record_keys_to(keys);
  // A 2D grid's [x, y] arrays read as the 3D ones they stand for (with_plane_arrays_completed).
  const Json in_plane = with_plane_arrays_completed(document, problems);
  const Json& doc = in_plane;
  JsonReader root(doc, "", problems);
  Scene s;
  s.file = file;
  s.resolved = document;
  root.read_elsewhere("description", [] {
    return KeyDescription{"string", "", "", "free text, ignored"};
  });
  read_grid(root, doc, s.grid);
  read_time(root, s.time, s.warnings);
  read_solver(root, doc, s.solver);
  read_physics(root, s.physics);
  read_output(root, doc, file, s.time.max_time, s.output);
  read_materials(root, doc, s.materials);
  read_objects(root, doc, s.materials, s.objects);
  apply_physics_overrides(s.physics, s.materials);
  if (problems.empty()) check_planar_scene(problems, s);
  if (problems.empty()) check_objects_in_grid(problems, s);  // grid and objects valid
  read_observables(problems, doc, s);
  check_field_count(problems, s);
  root.reject_unknown_keys();
  problems.throw_if_any();
  s.warnings.insert(s.warnings.end(), problems.warnings().begin(), problems.warnings().end());
  for (std::string& w : fitted_range_warnings(s)) s.warnings.push_back(std::move(w));
  warn_of_contact_within_one_material(s);
  return s;
}

Scene load_scene(const std::string& file) {
  return read_scene(load_scene_document(file), file);
}

}  // namespace impact::mpm
