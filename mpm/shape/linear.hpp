// 8-node trilinear shape functions (Sulsky, Chen & Schreyer 1994): S_I(x) = prod_d N(xi_d) with
// N(r) = 1 - |r| for |r| < 1, r the distance to node I in cells. Tensor product of 1-D weights, so
// a stencil stores 2 weights and 2 derivatives per axis; the 3-D gradient is formed on the fly.
#pragma once

#include <array>
#include <cmath>

#include "models/core/tensor.hpp"

namespace impact::mpm {

/// Per-particle 1-D weights on N consecutive nodes per axis starting at node `base` (grid node
/// index, -1 is the ghost layer below the lower face). dw is dS/dx in 1/m.
template <int N>
struct Stencil {
  std::array<int, 3> base;
  double w[3][N];
  double dw[3][N];

  double weight(int i, int j, int k) const { return w[0][i] * w[1][j] * w[2][k]; }
  Vec3 gradient(int i, int j, int k) const {
    return {dw[0][i] * w[1][j] * w[2][k], w[0][i] * dw[1][j] * w[2][k],
            w[0][i] * w[1][j] * dw[2][k]};
  }
};

/// Trilinear stencil at position xi (in cells from the grid's lower corner; 0 <= xi_d <= cells_d).
inline Stencil<2> linear_stencil(const Vec3& xi, const Vec3& inv_dx, const std::array<int, 3>& n) {
  Stencil<2> s;
  for (int d = 0; d < 3; ++d) {
    // The upper face belongs to the last cell, so a particle exactly on it still has two nodes.
    const int i = std::min(static_cast<int>(std::floor(xi(d))), n[d] - 1);
    const double f = xi(d) - i;
    s.base[d] = i;
    s.w[d][0] = 1.0 - f;
    s.w[d][1] = f;
    s.dw[d][0] = -inv_dx(d);
    s.dw[d][1] = inv_dx(d);
  }
  return s;
}

}  // namespace impact::mpm
