// Shared by the MPM verification tests: load a data/scenes/verification scene with a JSON merge
// patch on top (how a test varies interpolation or scheme), and small measurements.
#pragma once

#include <algorithm>
#include <string>

#include "mpm/input/scene_reader.hpp"
#include "mpm/run/run.hpp"
#include "mpm/simulation/simulation.hpp"

namespace impact::mpm::test {

/// A scene shipped under data/scenes/ (`path` relative to it), with `patch` merged on top.
inline Scene shipped_scene(const std::string& path, const Json& patch = Json::object()) {
  const std::string file = std::string(IMPACT_SOURCE_DIR) + "/data/scenes/" + path;
  Json doc = load_scene_document(file);
  doc.merge_patch(patch);
  return read_scene(doc, file);
}

inline Scene verification_scene(const std::string& name, const Json& patch = Json::object()) {
  return shipped_scene("verification/" + name, patch);
}

inline Json with_solver(const char* interpolation, const char* scheme) {
  return {{"solver", {{"interpolation", interpolation}, {"scheme", scheme}}}};
}

/// Longitudinal (uniaxial-strain) wave speed sqrt((K + 4 mu/3)/rho0) of the first material.
inline double longitudinal_wave_speed(const Scene& s) {
  const auto& p = s.materials.front().material.model.params();
  return std::sqrt((p.bulk_modulus + 4.0 * p.shear_modulus / 3.0) / p.density);
}

/// Young's modulus E = 9 K G / (3 K + G) [Pa] and Poisson's ratio nu = (3 K - 2 G) / (2 (3 K + G))
/// of the first material, from its bulk and shear moduli.
inline double youngs_modulus(const Scene& s) {
  const auto& p = s.materials.front().material.model.params();
  return 9.0 * p.bulk_modulus * p.shear_modulus / (3.0 * p.bulk_modulus + p.shear_modulus);
}
inline double poissons_ratio(const Scene& s) {
  const auto& p = s.materials.front().material.model.params();
  return (3.0 * p.bulk_modulus - 2.0 * p.shear_modulus) /
         (2.0 * (3.0 * p.bulk_modulus + p.shear_modulus));
}

/// The patch that puts the report's case01 (data/scenes/sphere_cylinder/case01.json) on an
/// axisymmetric grid: the 3D twin's spacing (2.38 x 3.3 mm) over the half-section y >= 0, the
/// sphere moved onto the axis (docs/scenes.md#2d-grids). Tests add their own time and output.
inline Json axisymmetric_case01_patch() {
  return {{"grid",
           {{"geometry", "axisymmetric"},
            {"lower", {0.0, 0.0}},
            {"upper", {119.0e-3, 33.0e-3}},
            {"cells", {50, 10}},
            {"boundary", {{"z-", nullptr}, {"z+", nullptr}}}}},
          {"objects",
           {{"sphere",
             {{"geometry", {{"center", {9.75e-3, 0.0, 0.0}}}}, {"particles_per_cell", {2, 2}}}},
            {"target", {{"particles_per_cell", {2, 2}}}}}}};
}

/// The ledger's sink column `name` [J] (e.g. "friction_heat"); 0 when the scene has no such
/// column (nothing of that kind can be booked in it).
inline double ledger_sink(const Ledger& ledger, const std::string& name) {
  const auto& names = ledger.sink_names();
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? 0.0 : ledger.row().sinks[std::size_t(it - names.begin())];
}

}  // namespace impact::mpm::test
