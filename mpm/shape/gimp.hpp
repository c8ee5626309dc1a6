// 27-node uGIMP shape functions (Bardenhagen & Kober 2004, CMES 5:477; docs/report_code.md
// sec. 15): the linear hat convolved with a particle box of half-width l (cells, l = 1/(2 ppc),
// fixed at creation as in the report's code). With r the distance from the node in cells:
//   S(r) = 1 - (r^2 + l^2)/(2l)          |r| <= l
//        = 1 - |r|                      l < |r| <= 1 - l
//        = (1 + l - |r|)^2 / (4l)       1 - l < |r| < 1 + l
// and dS/dr = -r/l, -sign r, -sign r (1 + l - |r|)/(2l). For l <= 1/2 the support 1 + l <= 3/2, so
// three nodes per axis suffice: the host cell's two plus the neighbour on the particle's side.
#pragma once

#include "mpm/shape/linear.hpp"

namespace impact::mpm {

/// 1-D uGIMP weight and its derivative d/dr (r and l in cells).
inline void gimp_weight(double r, double l, double& w, double& dw) {
  const double a = std::abs(r);
  const double sgn = r < 0.0 ? -1.0 : 1.0;
  if (a <= l) {
    w = 1.0 - (r * r + l * l) / (2.0 * l);
    dw = -r / l;
  } else if (a <= 1.0 - l) {
    w = 1.0 - a;
    dw = -sgn;
  } else if (a < 1.0 + l) {
    const double b = 1.0 + l - a;
    w = b * b / (4.0 * l);
    dw = -sgn * b / (2.0 * l);
  } else {
    w = 0.0;
    dw = 0.0;
  }
}

/// uGIMP stencil at position xi (cells from the lower corner) with half-widths l (cells, <= 1/2).
/// Nodes may lie in the ghost layer (index -1 or cells+1) next to a face. Only the first `axes`
/// axes are computed: a 2D grid's caller sets z itself (shape.hpp, flatten_z), and its particles
/// then cost two axes of weights instead of three.
inline Stencil<3> gimp_stencil(const Vec3& xi, const Vec3& inv_dx, const Vec3& l,
                               const std::array<int, 3>& n, int axes = 3) {
  Stencil<3> s;
  for (int d = 0; d < axes; ++d) {
    const int i = std::min(static_cast<int>(std::floor(xi(d))), n[d] - 1);
    const int base = xi(d) - i < 0.5 ? i - 1 : i;
    s.base[d] = base;
    for (int a = 0; a < 3; ++a) {
      double w, dw;
      gimp_weight(xi(d) - (base + a), l(d), w, dw);
      s.w[d][a] = w;
      s.dw[d][a] = dw * inv_dx(d);
    }
  }
  return s;
}

}  // namespace impact::mpm
