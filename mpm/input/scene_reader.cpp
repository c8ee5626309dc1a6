#include "mpm/input/scene_reader.hpp"

#include "mpm/input/block_readers.hpp"
#include "mpm/scene/fitted_range.hpp"

namespace impact::mpm {

Scene read_scene(const Json& document, const std::string& file, InputKeyRecorder* keys) {
  using namespace scene_input;  // the blocks (block_readers.hpp)
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
  read_constants(root, doc, s.constants);
  check_face_velocities(problems, s);
  read_output(root, doc, file, s.time.max_time, s.constants, s.output);
  read_materials(root, doc, s.materials);
  read_objects(root, doc, s.materials, s.constants, s.objects);
  apply_physics_overrides(s.physics, s.materials);
  if (problems.empty()) check_planar_scene(problems, s);
  if (problems.empty()) check_objects_in_grid(problems, s);  // grid and objects valid
  if (problems.empty()) check_initial_fields(problems, s);   // expressions at the seed points
  if (problems.empty()) check_object_speeds(problems, s);    // numbers and expression peaks
  warn_of_idle_expression_names(problems, s);
  read_observables(problems, doc, s);
  check_field_count(problems, s);
  check_rigid_objects(problems, s);
  root.reject_unknown_keys();
  problems.throw_if_any();
  s.warnings.insert(s.warnings.end(), problems.warnings().begin(), problems.warnings().end());
  if (s.grid.has_moving_faces()) warn_of_face_travel(s);
  for (std::string& w : fitted_range_warnings(s)) s.warnings.push_back(std::move(w));
  warn_of_contact_within_one_material(s);
  warn_of_physics_no_material_uses(s);
  return s;
}

Scene load_scene(const std::string& file) {
  return read_scene(load_scene_document(file), file);
}

}  // namespace impact::mpm
