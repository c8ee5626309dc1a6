// The scene's output block: intervals, snapshots, gauges, particle paths, the crater and the
// other observables (docs/scenes.md#output).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "mpm/input/block_readers.hpp"
#include "mpm/input/scene_keys.hpp"
#include "mpm/particles/snapshot_fields.hpp"
#include "mpm/scene/seed_points.hpp"

namespace impact::mpm::scene_input {

namespace fs = std::filesystem;

void read_output(JsonReader& root, const Json& doc, const std::string& file, double max_time,
                 const NamedConstants& constants, OutputSpec& o) {
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
  const VectorExpression exact = read_vector_expression(
      r, n, "exact_displacement",
      "exact displacement u(X, t) [m] of the particles: history columns displacement_error_rms "
      "and _max (absent: none)",
      constants, std::nullopt);
  if (n.is_object() && n.contains("exact_displacement")) o.exact_displacement = exact;
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
      std::vector<std::string> known;
      for (const SnapshotField& k : snapshot_fields()) known.push_back(k.name);
      for (std::size_t i = 0; i < f.size(); ++i) {
        const std::string where = r.key_path("fields") + "/" + std::to_string(i);
        if (!f[i].is_string()) {
          r.problems().add(where, "expected a field name (a string), got " + f[i].dump());
          continue;
        }
        const std::string name = f[i].get<std::string>();
        if (!find_snapshot_field(name)) {
          std::string message = "unknown field " + f[i].dump();
          if (const auto near = nearest_name(name, known))
            message += " (did you mean " + *near + "?)";
          std::string list;
          for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
          r.problems().add(where, message + "; known: " + list);
        } else if (std::find(o.fields.begin(), o.fields.end(), name) != o.fields.end()) {
          // Two arrays of one name in a .vtu: readers keep one of them.
          r.problems().add(where, "field \"" + name + "\" is listed twice");
        } else {
          o.fields.push_back(name);
        }
      }
    }
  }
  r.reject_unknown_keys();
}

namespace {

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

// output.gauges: named history columns, each an object's particles in a region (docs/scenes.md).
void read_gauges(InputProblems& problems, const Json& out, Scene& s, bool check_seeds) {
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

// output.crater: the crater profile of an object's face (docs/mpm.md#crater).
void read_crater(InputProblems& problems, const Json& out, Scene& s, bool check_seeds) {
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
      // An axisymmetric crater is centred on the axis of symmetry, y = z = 0: the key that is not
      // 0 is named (a missing one is already a problem of its own).
      const auto off = [](double a) { return std::isfinite(a) && a != 0.0; };
      const auto& [y, z] = *spec.axis;
      if (s.grid.geometry_facts().rings && (off(y) || off(z)))
        problems.add(c.key_path(off(y) ? "axis_y" : "axis_z"),
                     "the crater of an axisymmetric scene is centred on the axis of symmetry: "
                     "expected axis_y = axis_z = 0, or neither key");
    }
    c.reject_unknown_keys();
    if (object >= 0 && std::isfinite(spec.face)) {
      spec.object = object;
      const double dx = s.grid.cell_size(0, s.grid.cell_along(0, spec.face));
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

// output.particle_paths: the path of the particle nearest a position, one file each.
void read_particle_paths(InputProblems& problems, const Json& out, Scene& s) {
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

}  // namespace

// output.gauges, output.crater and output.particle_paths (docs/scenes.md): need the objects, and
// (for "no particle inside") the grid and the objects' geometry, so they are read after
// everything else.
void read_observables(InputProblems& problems, const Json& doc, Scene& s) {
  const Json& out = at(doc, "output");
  const bool check_seeds = problems.empty();  // grid and objects valid: the seeds can be counted
  if (!out.is_object()) return;
  if (out.contains("gauges")) read_gauges(problems, out, s, check_seeds);
  if (out.contains("crater")) read_crater(problems, out, s, check_seeds);
  if (out.contains("particle_paths")) read_particle_paths(problems, out, s);
}

}  // namespace impact::mpm::scene_input
