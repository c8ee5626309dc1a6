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

/// The largest |integral of V_f dt| over [0, t_end] of each face [m] (trapezoid over 1000
/// intervals; exact for a number).
std::array<double, 6> face_travel(const GridSpec& grid, const NamedConstants& constants,
                                  double t_end);

}  // namespace impact::mpm
