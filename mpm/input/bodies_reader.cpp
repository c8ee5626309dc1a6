// The scene's materials and objects (docs/scenes.md#objects-and-the-grid).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include "mpm/input/block_readers.hpp"
#include "mpm/input/scene_keys.hpp"

namespace impact::mpm::scene_input {

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
                  const NamedConstants& constants, std::vector<SceneObject>& out) {
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
    obj.velocity_field = read_vector_expression(
        o, on, "velocity", "initial velocity [m/s]; an expression is evaluated at t = 0", constants,
        Vec3::Zero());
    obj.velocity = obj.velocity_field.value;  // an expression's peak joins after the checks
    for (int d = 0; d < 3; ++d) {
      if (obj.velocity_field.text[std::size_t(d)].empty())
        o.problems().check_units(o.key_path("velocity") + "/" + std::to_string(d), Quantity::speed,
                                 obj.velocity(d));
    }
    obj.body_force = read_vector_expression(
        o, on, "body_force", "body force per unit mass b(X, t) [m/s^2], beside solver.gravity",
        constants, Vec3::Zero());
    obj.rigid = o.boolean_or("rigid", false,
                             "a rigid body: it moves at `velocity` for ever, other bodies contact "
                             "it (docs/scenes.md#rigid-objects)");
    // Unset, a rigid object takes physics.contact.mu (std::nullopt, not that number: the checks
    // tell a key written on a deformable object from one left out).
    constexpr std::string_view kMuMeaning =
        "a rigid object's Coulomb coefficient against the bodies it meets [-]";
    if (o.has("mu"))
      obj.mu = o.number("mu", Range::closed(0.0, 10.0), kMuMeaning);
    else
      o.read_elsewhere("mu", [&] {
        return KeyDescription{"number", Range::closed(0.0, 10.0).describe(), "physics.contact.mu",
                              std::string(kMuMeaning)};
      });
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

}  // namespace impact::mpm::scene_input
