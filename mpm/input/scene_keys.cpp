#include "mpm/input/scene_keys.hpp"

#include <vector>

#include "mpm/input/scene_reader.hpp"

namespace impact::mpm {

namespace {

// Every optional block and key switched on; one object, a box. The values are admissible and
// otherwise arbitrary: only the keys the reader asks for matter.
Json sample_scene(const std::string& material_file, double max_time) {
  const std::string n(kSceneKeyName);
  Json faces = Json::object();
  Json friction = Json::object();
  for (const char* face : kFaceNames) {
    faces[face] = "wall";
    friction[face] = 0.1;
  }
  Json scene = {
      {"description", "every key of the scene format"},
      {"materials", {{n, {{"file", material_file}, {"overrides", Json::object()}}}}},
      {"objects",
       {{n,
         {{"material", n},
          {"geometry",
           {{"type", "box"}, {"lower", {2e-3, 2e-3, 2e-3}}, {"upper", {8e-3, 8e-3, 8e-3}}}},
          {"velocity", {1.0, 0.0, 0.0}},
          {"temperature", 294.0},
          {"particles_per_cell", {2, 2, 2}}}}}},
      {"grid",
       {{"lower", {0.0, 0.0, 0.0}},
        {"upper", {1e-2, 1e-2, 1e-2}},
        {"cells", {4, 4, 4}},
        {"boundary", faces},
        {"wall_friction", friction},
        {"active_blocks", true},
        {"outflow", "stop"}}},
      {"time",
       {{"max_time", max_time},
        {"initial_dt", 1e-9},
        {"min_dt", 0.0},
        {"max_dt", 1e-6},
        {"multiplier", 0.5},
        {"max_energy_growth", 1.0}}},
      {"solver",
       {{"interpolation", "gimp"},
        {"scheme", "musl"},
        {"deformation_gradient", "forward_euler"},
        {"gravity", {0.0, 0.0, 0.0}},
        {"rebalance_above", 1.2},
        {"ranks_per_axis", {0, 0, 0}},
        {"shuffle_particles", 0}}},
      {"physics",
       {{"contact", {{"type", "friction"}, {"mu", 0.1}, {"normal", "mass_gradients"}}},
        {"artificial_viscosity", {{"enabled", true}, {"linear", 0.2}, {"quadratic", 2.0}}},
        {"create_new_particles", false},
        {"on_numerical_fault", "stop"},
        {"erosion", "none"},
        {"do_melting", true},
        {"turn_on_adiabatic_heating", true}}},
      {"output",
       {{"directory", "out"},
        {"interval", max_time / 10.0},
        {"snapshots", false},
        {"checkpoint_interval_steps", 0},
        {"fields", {"velocity"}},
        {"gauges",
         {{n,
           {{"type", "velocity"},
            {"object", n},
            {"region", {{"lower", {2e-3, 2e-3, 2e-3}}, {"upper", {8e-3, 8e-3, 8e-3}}}},
            {"component", "x"}}}}},
        {"crater", {{"object", n}, {"face", 2e-3}, {"axis_y", 5e-3}, {"axis_z", 5e-3}}},
        {"particle_paths", {{n, {{"object", n}, {"position", {5e-3, 5e-3, 5e-3}}}}}}}}};
  return scene;
}

// The geometry types other than the sample's box, each in the same place.
std::vector<Json> other_geometries() {
  const Json bottom = {3e-3, 5e-3, 5e-3};
  const Json top = {7e-3, 5e-3, 5e-3};
  return {{{"type", "sphere"}, {"center", {5e-3, 5e-3, 5e-3}}, {"radius", 2e-3}},
          {{"type", "cylinder"}, {"bottom", bottom}, {"top", top}, {"radius", 2e-3}},
          {{"type", "hollow_cylinder"},
           {"bottom", bottom},
           {"top", top},
           {"radius", 2e-3},
           {"thickness", 1e-3},
           {"cap_thickness", 1e-3}},
          {{"type", "union"},
           {"parts",
            {{std::string(kSceneKeyName),
              {{"type", "box"}, {"lower", {2e-3, 2e-3, 2e-3}}, {"upper", {8e-3, 8e-3, 8e-3}}}}}}}};
}

}  // namespace

InputKeyRecorder scene_keys(const std::string& material_file) {
  InputKeyRecorder keys;
  keys.record("/extends", {"string", "", "",
                           "base scene, a path relative to the file that names it (read by "
                           "load_scene_document before the reader)"});
  constexpr double kMaxTime = 1e-5;
  const Json sample = sample_scene(material_file, kMaxTime);
  read_scene(sample, "a.json", &keys);
  for (const Json& geometry : other_geometries()) {
    Json scene = sample;
    scene["objects"][std::string(kSceneKeyName)]["geometry"] = geometry;
    read_scene(scene, "a.json", &keys);
  }
  // The moving faces are mirror faces; the sample's faces are walls with friction.
  Json mirrors = sample;
  mirrors["grid"].erase("wall_friction");
  for (const char* face : kFaceNames) {
    mirrors["grid"]["boundary"][face] = "symmetric";
    mirrors["grid"]["face_velocity"][face] = 0.0;
  }
  read_scene(mirrors, "a.json", &keys);
  // A graded grid (grid.refine: its keys as one box).
  Json graded = sample;
  graded["physics"]["contact"] = {{"type", "single_velocity"}};
  graded["grid"]["refine"] = {
      {"lower", {0.0, 0.0, 0.0}}, {"upper", {5e-3, 5e-3, 5e-3}}, {"factor", 2.0}, {"growth", 1.2}};
  read_scene(graded, "a.json", &keys);
  // A default that changes with the scene's other values is computed from them, not a constant.
  InputKeyRecorder other;
  read_scene(sample_scene(material_file, 2.0 * kMaxTime), "b.json", &other);
  for (const InputKey& k : other.keys()) {
    KeyDescription* d = keys.find(k.path);
    if (d != nullptr && d->default_value && d->default_value != k.description.default_value)
      d->default_value = std::string(kComputedDefault);
  }
  return keys;
}

}  // namespace impact::mpm
