// grid.face_velocity evaluated (docs/scenes.md#moving-faces): each moving `symmetric` face's
// velocity along its axis, V_f(t) [m/s], a number or an expression of t compiled once. The solver
// gives the grid V_f at each step's start and end (Grid::set_face_velocities); the scene reader
// warns when a face travels more than a quarter of a cell (face_travel), since the mirror plane
// stays at its grid position.
#pragma once

#include <array>
#include <optional>

#include "mpm/scene/expression.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

class FaceMotions {
 public:
  FaceMotions(const GridSpec& grid, const NamedConstants& constants);
  /// V_f(t) per face [m/s], kFaceNames order; 0 for a face that does not move.
  std::array<double, 6> at(double t);

 private:
  std::array<std::optional<VectorField>, 6> fields_;  ///< the faces given an expression
  std::array<double, 6> numbers_{};                   ///< the faces given a number
};

/// How each face moves over [0, t_end], from V_f at 1001 times (trapezoid; exact for a number).
struct FaceTravel {
  std::array<double, 6> largest{};  ///< max |integral of V dt| [m]
  std::array<double, 6> outward{};  ///< max travel out of the grid (-x on x-, +x on x+) [m]
  std::array<double, 6> initial{};  ///< V_f(0) [m/s]
  std::array<std::optional<double>, 6> non_finite_at{};  ///< the first time V_f is not finite [s]
};
FaceTravel face_travel(const GridSpec& grid, const NamedConstants& constants, double t_end);

}  // namespace impact::mpm
