// The two interpolations behind one small interface, chosen once per run (no per-particle branch):
// every phase is a template on the shape and is instantiated for both.
#pragma once

#include <vector>

#include "mpm/shape/gimp.hpp"
#include "mpm/shape/linear.hpp"

namespace impact::mpm {

struct LinearShape {
  static constexpr int N = 2;  ///< nodes per axis: 8 in all
  Vec3 lower, inv_dx;
  std::array<int, 3> cells;
  Stencil<2> at(const Vec3& x, int /*object*/) const {
    return linear_stencil((x - lower).cwiseProduct(inv_dx), inv_dx, cells);
  }
};

struct GimpShape {
  static constexpr int N = 3;  ///< nodes per axis: 27 in all
  Vec3 lower, inv_dx;
  std::array<int, 3> cells;
  std::vector<Vec3> half_width;  ///< per object, in cells
  Stencil<3> at(const Vec3& x, int object) const {
    return gimp_stencil((x - lower).cwiseProduct(inv_dx), inv_dx, half_width[object], cells);
  }
};

}  // namespace impact::mpm
