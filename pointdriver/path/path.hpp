// A prescribed path for one material point: the validated form of a path file (data/paths/*.json,
// keys in docs/pointdriver.md). A path is a material, a start state and a list of legs; each leg
// fixes, per component of the 3x3 problem, either
//   - a velocity-gradient component L_ij [1/s] (L = D + W, held over the leg),
//   - a deformation-gradient component F_ij at the leg's end [-] (constant-L, i.e. exponential,
//     interpolation: F(t) = exp(L t) F_0 when all nine are given; per component otherwise, see
//     docs/pointdriver.md), or
//   - a Cauchy stress component sigma_ij [Pa] at the leg's end (mixed control; ramped linearly
//     from the leg's start), or a ratio sigma_ij = r sigma_kl (constant triaxiality paths).
// Components given nothing are stress-free, as in MTest; an off-diagonal pair (ij, ji) with
// neither given is stress-free with no spin (W_ij = 0).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "models/core/point_state.hpp"
#include "models/core/tensor.hpp"
#include "models/material/material.hpp"
#include "pointdriver/path/checks.hpp"

namespace impact::pointdriver {

/// Temperature in a leg: held, computed from plastic work (report eq. 8) or prescribed.
enum class Thermal { isothermal, adiabatic, prescribed };

/// What to do when a failure criterion of the material fires (TEPLA, melting, Drucker, Becker).
enum class FailurePolicy {
  stop,      ///< write the failing step and end the run
  freeze,    ///< keep the material state of the failing step for the rest of the path
  continue_  ///< keep going with the material's erosion rule (report sec. 3)
};

/// Component indices: velocity and deformation gradients flatten as 3i+j ("xx"=0, "xy"=1, ...);
/// stress uses the six symmetric components in the order xx, yy, zz, xy, yz, zx.
inline constexpr std::array<const char*, 9> tensor_names{"xx", "xy", "xz", "yx", "yy",
                                                         "yz", "zx", "zy", "zz"};
inline constexpr std::array<const char*, 6> stress_names{"xx", "yy", "zz", "xy", "yz", "zx"};
inline constexpr std::array<std::array<int, 2>, 6> stress_index{
    {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}}};

struct Leg {
  std::string label;
  double duration = 0.0;  ///< [s]
  int steps = 0;          ///< number of steps (resolved from max_strain_increment when given)
  double growth = 1.0;    ///< ratio of successive step sizes (1: uniform; >1: log-spaced steps)
  std::array<std::optional<double>, 9> velocity_gradient;     ///< L_ij [1/s]
  std::array<std::optional<double>, 9> deformation_gradient;  ///< F_ij at the leg's end [-]
  std::array<std::optional<double>, 6> stress;                ///< sigma at the leg's end [Pa]
  std::array<std::optional<double>, 6> stress_ratio;  ///< sigma_c = ratio * sigma_{ratio_of}
  int ratio_of = 0;                                   ///< stress component index of the ratios
  Thermal thermal = Thermal::isothermal;
  double end_temperature = 0.0;             ///< prescribed: temperature at the leg's end [K]
  std::optional<double> start_temperature;  ///< a jump at the leg's start [K]
  Vec3 rotation_axis = Vec3::UnitZ();       ///< superposed rigid rotation over the leg
  double rotation_angle = 0.0;              ///< [rad]
};

struct SolverSettings {
  double stress_tolerance = 1e-3;            ///< on each stress-controlled component [Pa], plus:
  double relative_stress_tolerance = 1e-10;  ///< times the largest stress component [-]: the
                                             ///< material's own return tolerance bounds accuracy
  double strain_tolerance = 1e-12;  ///< on each deformation-gradient-controlled component [-]
  int max_iterations = 25;          ///< Newton iterations per attempt
  int max_cutbacks = 8;             ///< halvings of a step that does not converge
  enum class Jacobian { central_difference, elastic } jacobian = Jacobian::central_difference;
};

struct Path {
  std::string file;      ///< where it was read from (for messages and the replay file)
  Json material_source;  ///< the "material" entry as written (file + overrides)
  Material material;
  double temperature = 294.0;             ///< initial temperature [K]
  PointState initial_state;               ///< stress, F, history (optional "initial_state" block)
  Mat3 initial_frame = Mat3::Identity();  ///< superposed rotation Q at the start
  FailurePolicy failure_policy = FailurePolicy::stop;
  SolverSettings solver;
  std::vector<Leg> legs;
  Json resolved;  ///< the path with named legs expanded (written beside the output)
  std::vector<ColumnCheck> checks;  ///< regression checks on the run's CSV (checks.hpp)
  /// Admissible but suspicious values, "file: /key/path: why" (e.g. a temperature that looks
  /// like degC); its material's warnings are included. The command line prints them.
  std::vector<std::string> warnings;
};

/// Reads and validates a path document; named legs are expanded first (named_paths.hpp). Every
/// problem is reported at once as an InputError naming `file` and the JSON key path. Relative
/// material paths are resolved against the current directory, then the path file's directory.
Path read_path(const Json& document, const std::string& file);

/// Loads a path file; `patches` are RFC 7396 merge patches applied before validation.
Path load_path(const std::string& file, const std::vector<Json>& patches = {});

}  // namespace impact::pointdriver
