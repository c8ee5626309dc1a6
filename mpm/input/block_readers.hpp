// The scene reader's blocks (internal to mpm/input/): each reads one block of a scene document
// into its part of the Scene, recording every problem with its key path; read_scene
// (scene_reader.cpp) calls them in order and then the checks across blocks (scene_checks.cpp).
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "models/core/input.hpp"
#include "mpm/input/scene_reader.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm::scene_input {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// node[key], or an empty object when node is not an object or has no such key.
inline const Json& at(const Json& node, const char* key) {
  return node.is_object() && node.contains(key) ? node[key] : empty_json_object();
}

/// Three integers in [lo, hi] (grid_reader.cpp).
std::array<int, 3> read_int3(JsonReader& r, const Json& node, std::string_view key, int lo, int hi,
                             std::string_view meaning, std::optional<std::array<int, 3>> fallback);

// grid_reader.cpp
Json with_plane_arrays_completed(const Json& doc, InputProblems& problems);
void read_grid(JsonReader& root, const Json& doc, GridSpec& g);

// settings_reader.cpp: time, solver, physics
void read_time(JsonReader& root, TimeSpec& t, std::vector<std::string>& warnings);
void read_solver(JsonReader& root, const Json& doc, SolverSpec& s);
void read_physics(JsonReader& root, PhysicsSpec& ph);
void apply_physics_overrides(const PhysicsSpec& ph, std::vector<SceneMaterial>& materials);

// output_reader.cpp
void read_output(JsonReader& root, const Json& doc, const std::string& file, double max_time,
                 const NamedConstants& constants, OutputSpec& o);
void read_observables(InputProblems& problems, const Json& doc, Scene& s);

// expression_reader.cpp: /constants, and three components each a number or an expression (a
// component's problem names its key path, the character and why; absent: `fallback`, or zero
// for a key without a default)
void read_constants(JsonReader& root, const Json& doc, NamedConstants& out);
/// Warns of a constant no expression names, and of an initial velocity that reads t (always 0).
void warn_of_idle_expression_names(InputProblems& problems, const Scene& s);
/// "expression \"TEXT\" at character N: why" (or "at its end"): how a refused expression is named.
std::string expression_problem_message(const std::string& text, const ExpressionProblem& problem);
VectorExpression read_vector_expression(JsonReader& r, const Json& node, std::string_view key,
                                        std::string_view meaning, const NamedConstants& constants,
                                        const std::optional<Vec3>& fallback);

// bodies_reader.cpp: materials and objects
void read_materials(JsonReader& root, const Json& doc, std::vector<SceneMaterial>& out);
void read_objects(JsonReader& root, const Json& doc, const std::vector<SceneMaterial>& materials,
                  const NamedConstants& constants, std::vector<SceneObject>& out);

// scene_checks.cpp: across blocks
void check_objects_in_grid(InputProblems& problems, const Scene& s);
void check_planar_scene(InputProblems& problems, Scene& s);
void check_field_count(InputProblems& problems, const Scene& s);
/// Rigid objects: multi-field contact, a material of their own, a velocity of numbers, no body
/// force.
void check_rigid_objects(InputProblems& problems, const Scene& s);
/// The expressions of the objects' velocities and body forces at their seed points (t = 0): a
/// value that is not finite is refused, naming the point; sets each object's velocity peak and
/// initial body-force peak for the estimates, and checks the velocity's units there.
void check_initial_fields(InputProblems& problems, Scene& s);
/// Each object's (peak) initial speed below the speed of light.
void check_object_speeds(InputProblems& problems, const Scene& s);
/// grid.face_velocity's expressions: they compile with the scene's constants and read t alone.
void check_face_velocities(InputProblems& problems, const Scene& s);
/// A warning in s.warnings for each moving face that travels more than a quarter of its cell.
void warn_of_face_travel(Scene& s);
void warn_of_contact_within_one_material(Scene& s);
/// A warning when physics switches erosion, melting or heating and every material is
/// hyperelastic (the switches act on elastic-plastic models only).
void warn_of_physics_no_material_uses(Scene& s);

}  // namespace impact::mpm::scene_input
