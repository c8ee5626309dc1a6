// Shape functions on graded axes (mpm/shape/tartan.hpp, issue 56): on equal cells they are the
// uniform grid's (gimp.hpp, linear.hpp) to round-off; on every graded cell of an axis refined 4
// times with growth 1.2 (graded_axis_test's) they keep the partition of unity sum_I S_I = 1, the
// linear completeness sum_I x_I S_I = x, sum_I dS_I/dx = 0 and sum_I x_I dS_I/dx = 1 to
// round-off, their gradient is the derivative of their weight, and a box too large for the
// cells it reaches is told apart and narrowed to them (exact still).
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "mpm/shape/gimp.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/tartan.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

GradedAxis refined() {
  return graded_axis(0.0, 1.0, 10, RefinedSpan{0.4, 0.6, 4.0, 1.2});
}

// Points through every cell of the axis (17 per cell, off the nodes and the cell's middle).
template <class F>
void across(const GradedAxis& axis, F&& f) {
  for (int i = 0; i < axis.cells(); ++i)
    for (int k = 0; k < 17; ++k) f(i, axis.node(i) + axis.size(i) * (k + 0.31) / 17.3);
}

// The largest half-width the host cell and its neighbours allow, a quarter of the smallest.
double fitting_half_width(const GradedAxis& axis, int i) {
  return 0.25 * std::min({axis.size(i - 1), axis.size(i), axis.size(i + 1)});
}

}  // namespace

BOOST_AUTO_TEST_SUITE(tartan)

BOOST_AUTO_TEST_CASE(on_equal_cells_they_are_the_uniform_grids_shapes) {
  const double h = 0.005;
  const GradedAxis axis = graded_axis(0.0, 0.06, 12, RefinedSpan{});
  const Vec3 inv(1.0 / h, 1.0 / h, 1.0 / h);
  const std::array<int, 3> n{12, 12, 12};
  const double l = 0.25;  // cells: 2 particles per cell
  double worst = 0.0;
  across(axis, [&](int, double x) {
    const Stencil<3> g = gimp_stencil(Vec3::Constant(x / h), inv, Vec3::Constant(l), n);
    const AxisWeights<3> t = tartan_gimp(axis, x, l * h);
    BOOST_TEST(t.base == g.base[0]);
    for (int a = 0; a < 3; ++a) {
      worst = std::max(worst, std::abs(t.w[a] - g.w[0][a]));
      worst = std::max(worst, std::abs(t.dw[a] - g.dw[0][a]) * h);
    }
    const Stencil<2> lin = linear_stencil(Vec3::Constant(x / h), inv, n);
    const AxisWeights<2> tl = tartan_linear(axis, x);
    BOOST_TEST(tl.base == lin.base[0]);
    for (int a = 0; a < 2; ++a) {
      worst = std::max(worst, std::abs(tl.w[a] - lin.w[0][a]));
      worst = std::max(worst, std::abs(tl.dw[a] - lin.dw[0][a]) * h);
    }
  });
  BOOST_TEST(worst < 1e-13);
}

BOOST_AUTO_TEST_CASE(partition_of_unity_and_linear_completeness_on_every_graded_cell) {
  const GradedAxis axis = refined();
  double unity = 0.0, position = 0.0, slope_sum = 0.0, identity = 0.0;
  across(axis, [&](int i, double x) {
    const double L = fitting_half_width(axis, i);
    BOOST_TEST(tartan_box_fits(axis, x, L));
    const AxisWeights<3> s = tartan_gimp(axis, x, L);
    double w = 0.0, xw = 0.0, dw = 0.0, xdw = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double xI = axis.node(s.base + a);
      w += s.w[a];
      xw += xI * s.w[a];
      dw += s.dw[a];
      xdw += xI * s.dw[a];
    }
    unity = std::max(unity, std::abs(w - 1.0));
    position = std::max(position, std::abs(xw - x));
    slope_sum = std::max(slope_sum, std::abs(dw) * axis.size(i));
    identity = std::max(identity, std::abs(xdw - 1.0));
    const AxisWeights<2> l = tartan_linear(axis, x);
    unity = std::max(unity, std::abs(l.w[0] + l.w[1] - 1.0));
    position = std::max(position,
                        std::abs(axis.node(l.base) * l.w[0] + axis.node(l.base + 1) * l.w[1] - x));
    identity = std::max(
        identity, std::abs(axis.node(l.base) * l.dw[0] + axis.node(l.base + 1) * l.dw[1] - 1.0));
  });
  BOOST_TEST_MESSAGE("graded: |sum S - 1| " << unity << ", |sum x_I S - x| " << position
                                            << " m, |sum dS| h " << slope_sum
                                            << ", |sum x_I dS - 1| " << identity);
  BOOST_TEST(unity < 1e-14);
  BOOST_TEST(position < 1e-14);  // m, on an axis of 1 m: about 45 ulp
  BOOST_TEST(slope_sum < 1e-13);
  BOOST_TEST(identity < 1e-12);
}

BOOST_AUTO_TEST_CASE(the_gradient_is_the_derivative_of_the_weight) {
  const GradedAxis axis = refined();
  double worst = 0.0;
  across(axis, [&](int i, double x) {
    const double L = fitting_half_width(axis, i), e = 1e-7 * axis.size(i);
    const AxisWeights<3> s = tartan_gimp(axis, x, L);
    const AxisWeights<3> up = tartan_gimp(axis, x + e, L), down = tartan_gimp(axis, x - e, L);
    if (up.base != s.base || down.base != s.base) return;  // the stencil moved on: not comparable
    for (int a = 0; a < 3; ++a)
      worst = std::max(worst, std::abs((up.w[a] - down.w[a]) / (2 * e) - s.dw[a]) * axis.size(i));
  });
  BOOST_TEST(worst < 1e-6);
}

BOOST_AUTO_TEST_CASE(a_box_from_a_coarse_cell_does_not_fit_a_fine_one) {
  // Seeded 2 per cell in a base cell (L = h0 / 4 = 0.025 m), a particle reaching the span's
  // cells of 0.025 m would need a box of 0.05 m over them: more than the stencil's two cells.
  const GradedAxis axis = refined();
  BOOST_TEST(tartan_box_fits(axis, 0.05, 0.025));    // in the coarse cells
  BOOST_TEST(!tartan_box_fits(axis, 0.51, 0.025));   // inside the span
  BOOST_TEST(tartan_box_fits(axis, 0.51, 0.00625));  // seeded there: a quarter of its cells
}

BOOST_AUTO_TEST_CASE(a_box_too_wide_is_narrowed_to_its_cells_and_stays_exact) {
  // Every point of the axis with the coarse cells' box (L = 0.025 m, four times what the span's
  // cells take): the fitted half-width is positive, fits, is L wherever L fits, and the stencil
  // keeps partition of unity and linear completeness (3D: the same per axis).
  const GradedAxis axis = refined();
  const double L = 0.025;
  double unity = 0.0, position = 0.0;
  int narrowed = 0;
  across(axis, [&](int, double x) {
    const double l = tartan_fitted_half_width(axis, x, L);
    BOOST_TEST(l > 0.0);
    BOOST_TEST(tartan_box_fits(axis, x, l));
    if (tartan_box_fits(axis, x, L)) BOOST_TEST(l == L);
    narrowed += l < L;
  });
  const std::array<GradedAxis, 3> axes{axis, axis, axis};
  across(axis, [&](int i, double x) {
    const Vec3 at(x, 1.0 - x, axis.node(i) + 0.5 * axis.size(i));
    const Stencil<3> s = tartan_gimp_stencil(axes, at, Vec3::Constant(L));
    for (int d = 0; d < 3; ++d) {
      double w = 0.0, xw = 0.0;
      for (int a = 0; a < 3; ++a) {
        w += s.w[d][a];
        xw += axis.node(s.base[d] + a) * s.w[d][a];
      }
      unity = std::max(unity, std::abs(w - 1.0));
      position = std::max(position, std::abs(xw - at(d)));
    }
  });
  BOOST_TEST_MESSAGE("narrowed at " << narrowed << " points; |sum S - 1| " << unity
                                    << ", |sum x_I S - x| " << position << " m");
  BOOST_TEST(narrowed > 0);
  BOOST_TEST(unity < 1e-14);
  BOOST_TEST(position < 1e-14);
}

BOOST_AUTO_TEST_SUITE_END()
