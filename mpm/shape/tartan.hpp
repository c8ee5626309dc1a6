// Shape functions on a graded (tartan) axis, whose cells are not all equal (issue 56; Nairn's
// tartan grids in NairnMPM). The linear hat of node I spans its two neighbouring cells, of sizes
// h_{I-1} below and h_I above:
//   N_I(y) = (y - x_{I-1}) / h_{I-1} on [x_{I-1}, x_I],  (x_{I+1} - y) / h_I on [x_I, x_{I+1}].
// uGIMP on unequal cells is the hat averaged over the particle's box [x - L, x + L] (Bardenhagen
// & Kober 2004's definition, which needs no equal cells), L in metres, fixed at creation from the
// cell the particle was seeded in:
//   S_I(x) = (F_I(x + L) - F_I(x - L)) / (2 L),  dS_I/dx = (N_I(x + L) - N_I(x - L)) / (2 L),
// F_I the antiderivative of N_I from x_{I-1}. Because sum_I N_I = 1 and sum_I x_I N_I(y) = y on
// any nodes, sum_I S_I = 1, sum_I x_I S_I = x and sum_I x_I dS_I/dx = 1 hold on every graded
// cell, to round-off. On equal cells S_I is gimp.hpp's weight.
// The stencil keeps three nodes per axis, so the box must span at most two cells: 2 L no larger
// than the cells it reaches. tartan_box_fits() says whether it does; where it does not (a
// particle seeded in a coarse cell among finer ones) tartan_fitted_half_width() narrows the box
// to those two cells, still a box, and the solver counts it (summary.json
// narrowed_particle_steps, a warning from mpm run; docs/scenes.md#graded-grids).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "mpm/scene/graded_axis.hpp"
#include "mpm/shape/linear.hpp"

namespace impact::mpm {

/// One axis of a stencil: N weights and their derivatives d/dx [1/m] from node `base`.
template <int N>
struct AxisWeights {
  int base = 0;
  double w[N] = {};
  double dw[N] = {};
};

/// Linear weights at x on a graded axis: the host cell's two nodes.
inline AxisWeights<2> tartan_linear(const GradedAxis& axis, double x) {
  AxisWeights<2> s;
  const int i = axis.cell_of(x);
  const double lo = axis.node(i), h = axis.size(i);
  const double f = (x - lo) / h;
  s.base = i;
  s.w[0] = 1.0 - f;
  s.w[1] = f;
  s.dw[0] = -1.0 / h;
  s.dw[1] = 1.0 / h;
  return s;
}

namespace detail {

// The hat of node I at y (nodes I - 1, I, I + 1 at a, c, b).
inline double hat(double a, double c, double b, double y) {
  if (y <= a || y >= b) return 0.0;
  return y <= c ? (y - a) / (c - a) : (b - y) / (b - c);
}

// Its antiderivative from a: 0 below a, (c - a + b - c) / 2 = (b - a) / 2 above b.
inline double hat_integral(double a, double c, double b, double y) {
  if (y <= a) return 0.0;
  if (y <= c) return (y - a) * (y - a) / (2.0 * (c - a));
  if (y < b) return 0.5 * (b - a) - (b - y) * (b - y) / (2.0 * (b - c));
  return 0.5 * (b - a);
}

}  // namespace detail

/// Whether the box [x - L, x + L] spans at most two cells of the axis, the nodes of the uGIMP
/// stencil below (the ghost cells beyond the faces included).
inline bool tartan_box_fits(const GradedAxis& axis, double x, double L) {
  const int i = axis.cell_of(x);
  const bool lower_half = x - axis.node(i) < axis.node(i + 1) - x;
  const int base = lower_half ? i - 1 : i;
  return x - L >= axis.node(base) && x + L <= axis.node(base + 2);
}

/// uGIMP weights at x with half-width L [m] on a graded axis: the host cell's two nodes and the
/// neighbour on the particle's side (nodes -1 and cells + 1 are the ghost layer).
inline AxisWeights<3> tartan_gimp(const GradedAxis& axis, double x, double L) {
  AxisWeights<3> s;
  const int i = axis.cell_of(x);
  s.base = x - axis.node(i) < axis.node(i + 1) - x ? i - 1 : i;
  const double lo = x - L, hi = x + L, inv = 1.0 / (2.0 * L);
  for (int k = 0; k < 3; ++k) {
    const int I = s.base + k;
    // Beyond the ghost node the hat has no neighbour: its cell mirrors the edge cell.
    const double a = axis.node(I - 1), c = axis.node(I), b = axis.node(I + 1);
    s.w[k] = (detail::hat_integral(a, c, b, hi) - detail::hat_integral(a, c, b, lo)) * inv;
    s.dw[k] = (detail::hat(a, c, b, hi) - detail::hat(a, c, b, lo)) * inv;
  }
  return s;
}

/// The half-width that fits: L, narrowed where the box [x - L, x + L] would reach beyond the two
/// cells of the uGIMP stencil at x (a particle seeded in a coarse cell that has moved into finer
/// ones). The narrowed box is still a box: partition of unity and sum_I x_I S_I = x hold.
inline double tartan_fitted_half_width(const GradedAxis& axis, double x, double L) {
  const int i = axis.cell_of(x);
  const int base = x - axis.node(i) < axis.node(i + 1) - x ? i - 1 : i;
  return std::min({L, x - axis.node(base), axis.node(base + 2) - x});
}

/// The linear stencil at x on three graded axes.
inline Stencil<2> tartan_linear_stencil(const std::array<GradedAxis, 3>& axes, const Vec3& x) {
  Stencil<2> s;
  for (int d = 0; d < 3; ++d) {
    const AxisWeights<2> a = tartan_linear(axes[std::size_t(d)], x(d));
    s.base[d] = a.base;
    for (int k = 0; k < 2; ++k) {
      s.w[d][k] = a.w[k];
      s.dw[d][k] = a.dw[k];
    }
  }
  return s;
}

/// The uGIMP stencil at x with half-widths L [m] on three graded axes, each narrowed to fit
/// (tartan_fitted_half_width); `narrowed`, when given, is set if one was, along the first
/// `axes_checked` axes (the mesh's).
inline Stencil<3> tartan_gimp_stencil(const std::array<GradedAxis, 3>& axes, const Vec3& x,
                                      const Vec3& L, bool* narrowed = nullptr,
                                      int axes_checked = 3) {
  Stencil<3> s;
  for (int d = 0; d < 3; ++d) {
    const GradedAxis& axis = axes[std::size_t(d)];
    const double l = tartan_fitted_half_width(axis, x(d), L(d));
    if (narrowed && d < axes_checked && l < L(d)) *narrowed = true;
    const AxisWeights<3> a = tartan_gimp(axis, x(d), l);
    s.base[d] = a.base;
    for (int k = 0; k < 3; ++k) {
      s.w[d][k] = a.w[k];
      s.dw[d][k] = a.dw[k];
    }
  }
  return s;
}

}  // namespace impact::mpm
