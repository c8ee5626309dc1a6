// A scene file (data/scenes/*.json, every key in docs/scenes.md) read into a validated Scene: the
// only place that touches the scene JSON. `extends` names a base scene; the file's own content is
// applied over it as an RFC 7396 JSON merge patch, recursively. Errors name file + key path.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "models/kinematics/deformation_gradient.hpp"
#include "models/material/material.hpp"
#include "mpm/geometry/geometry.hpp"

namespace impact::mpm {

enum class Interpolation { linear, gimp };  ///< 8-node trilinear or 27-node uGIMP
enum class Scheme { usl, musl };            ///< update stress last / modified USL
enum class FaceCondition { symmetric, fixed, free };

/// Faces in the order x-, x+, y-, y+, z-, z+ (index 2*axis + side).
inline constexpr std::array<const char*, 6> kFaceNames = {"x-", "x+", "y-", "y+", "z-", "z+"};

struct GridSpec {
  Vec3 lower, upper;                     ///< [m]
  std::array<int, 3> cells{};            ///< cells per axis
  std::array<FaceCondition, 6> faces{};  ///< per face, kFaceNames order
  Vec3 spacing() const { return (upper - lower).cwiseQuotient(Vec3(cells[0], cells[1], cells[2])); }
};

struct TimeSpec {
  double max_time = 0.0;    ///< end time [s]
  double initial_dt = 0.0;  ///< first step is min(initial_dt, stable dt) [s]
  double min_dt = 0.0;      ///< the run stops if the stable dt falls below this [s]
  double max_dt = 0.0;      ///< cap on dt [s]
  double multiplier = 0.5;  ///< CFL factor on the stable dt [-]
};

struct SolverSpec {
  Interpolation interpolation = Interpolation::gimp;
  Scheme scheme = Scheme::musl;
  FIntegration f_integration = FIntegration::forward_euler;
  Vec3 gravity = Vec3::Zero();  ///< body force per unit mass [m/s^2]
};

struct OutputSpec {
  std::string directory;            ///< where history.csv etc. go
  double interval = 0.0;            ///< history row and snapshot interval [s]
  bool snapshots = true;            ///< write particles/step_NNNNNN.vtu
  std::vector<std::string> fields;  ///< VTU point-data fields
};

struct SceneMaterial {
  std::string name;
  Material material;
};

struct SceneObject {
  std::string name;
  Geometry geometry;
  int material = 0;                                ///< index into Scene::materials
  Vec3 velocity = Vec3::Zero();                    ///< initial velocity [m/s]
  double temperature = 294.0;                      ///< initial temperature [K]
  std::array<int, 3> particles_per_cell{2, 2, 2};  ///< the report's `res`
};

struct Scene {
  std::string file;
  Json resolved;  ///< the merged document (after extends), as run
  GridSpec grid;
  TimeSpec time;
  SolverSpec solver;
  OutputSpec output;
  std::vector<SceneMaterial> materials;
  std::vector<SceneObject> objects;
};

/// Reads `file`, resolves `extends` chains (relative paths are relative to the file naming them),
/// then validates. Throws InputError with every problem.
Scene load_scene(const std::string& file);
/// The merged document only (extends resolved, material file paths made relative to the cwd).
Json load_scene_document(const std::string& file);
/// Validates an already-merged document; `file` is used in messages.
Scene read_scene(const Json& document, const std::string& file);

/// The VTU point-data fields known to the writer.
inline const std::vector<std::string>& known_output_fields() {
  static const std::vector<std::string> f = {
      "velocity", "stress",   "plastic_strain", "temperature", "damage", "mass",
      "volume",   "pressure", "von_mises",      "material",    "object"};
  return f;
}

}  // namespace impact::mpm
