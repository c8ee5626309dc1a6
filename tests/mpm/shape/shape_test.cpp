// Both interpolations at random points, including within half a cell of every domain face (where
// uGIMP reaches the ghost layer): partition of unity sum_I S_I = 1, linear reproduction
// sum_I S_I x_I = x, and gradient consistency sum_I grad S_I = 0, sum_I x_I (x) grad S_I = I.
// Tolerance 1e-12 (round-off on O(1) sums in cell units).
#include <boost/test/unit_test.hpp>
#include <random>
#include <type_traits>
#include <utility>
#include <variant>

#include "mpm/shape/shape.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

const std::array<int, 3> kCells = {5, 4, 3};
const Vec3 kLower(-0.1, 0.2, 0.0);
const Vec3 kSpacing(0.02, 0.05, 0.01);

struct Sums {
  double unity = 0.0;
  Vec3 position = Vec3::Zero();
  Vec3 gradient = Vec3::Zero();
  Mat3 gradient_moment = Mat3::Zero();
};

template <int N>
Sums sums(const Stencil<N>& s) {
  Sums out;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int k = 0; k < N; ++k) {
        const Vec3 node =
            kLower + kSpacing.cwiseProduct(Vec3(s.base[0] + i, s.base[1] + j, s.base[2] + k));
        const double w = s.weight(i, j, k);
        const Vec3 g = s.gradient(i, j, k);
        out.unity += w;
        out.position += w * node;
        out.gradient += g;
        out.gradient_moment += node * g.transpose();
      }
  return out;
}

// Random points: half uniform in the domain, half within half a cell of a random face.
std::vector<Vec3> sample_points(int n) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> pts;
  for (int p = 0; p < n; ++p) {
    Vec3 xi(u(rng) * kCells[0], u(rng) * kCells[1], u(rng) * kCells[2]);
    if (p % 2 == 1) {
      const int axis = p % 3;
      xi(axis) = (p % 4 == 1) ? 0.5 * u(rng) : kCells[axis] - 0.5 * u(rng);
    }
    pts.push_back(kLower + kSpacing.cwiseProduct(xi));
  }
  pts.push_back(kLower);  // exactly on the corners
  pts.push_back(kLower + kSpacing.cwiseProduct(Vec3(kCells[0], kCells[1], kCells[2])));
  return pts;
}

template <class Shape>
void check_consistency(const Shape& shape) {
  double worst = 0.0;
  for (const Vec3& x : sample_points(2000)) {
    const Sums s = sums(shape.at(x, 0));
    // Gradients are in 1/m; scale by the spacing to compare O(1) numbers.
    worst = std::max({worst, std::abs(s.unity - 1.0),
                      ((s.position - x).cwiseQuotient(kSpacing)).cwiseAbs().maxCoeff(),
                      s.gradient.cwiseProduct(kSpacing).cwiseAbs().maxCoeff(),
                      (s.gradient_moment - Mat3::Identity()).cwiseAbs().maxCoeff()});
  }
  BOOST_TEST_MESSAGE("worst consistency error " << worst);
  BOOST_TEST(worst < 1e-12);
}

// The catalogue puts every shape on every grid geometry, shape by shape, the default first: the
// alternatives' order is what a run's variant index and the phases' instantiations rely on.
template <std::size_t... I>
constexpr bool shape_major(std::index_sequence<I...>) {
  constexpr std::size_t n = sizeof...(I);
  return std::variant_size_v<AnyShape> == 2 * n &&
         (std::is_same_v<std::variant_alternative_t<I, AnyShape>, GimpShape<GridGeometry(I)>> &&
          ...) &&
         (std::is_same_v<std::variant_alternative_t<n + I, AnyShape>,
                         LinearShape<GridGeometry(I)>> &&
          ...);
}
static_assert(shape_major(std::make_index_sequence<kGeometryCount>{}));
static_assert(std::is_same_v<std::variant_alternative_t<0, AnyShape>, GimpShape<>>);
static_assert(GimpShape<>::NZ == 3 && GimpShape<kPlaneStrain>::NZ == 1 && LinearShape<>::NZ == 2 &&
              LinearShape<kAxisymmetric>::NZ == 1);
static_assert(GimpShape<kAxisymmetric>::kHoop && !GimpShape<>::kHoop &&
              !LinearShape<kPlaneStrain>::kHoop);

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_shape)

BOOST_AUTO_TEST_CASE(linear_weights_are_a_partition_of_unity_with_consistent_gradients) {
  check_consistency(LinearShape<>{{}, kLower, kSpacing.cwiseInverse(), kCells, nullptr});
}

BOOST_AUTO_TEST_CASE(gimp_weights_are_a_partition_of_unity_with_consistent_gradients) {
  for (double l : {0.25, 1.0 / 6.0, 0.5, 0.125}) {
    check_consistency(
        GimpShape<>{{}, kLower, kSpacing.cwiseInverse(), kCells, {Vec3::Constant(l)}, nullptr});
  }
}

BOOST_AUTO_TEST_CASE(gimp_weight_derivative_matches_central_differences) {
  const double l = 0.25, h = 1e-6;
  for (double r = -1.3; r <= 1.3; r += 0.0137) {
    double w, dw, wp, wm, d;
    gimp_weight(r, l, w, dw);
    gimp_weight(r + h, l, wp, d);
    gimp_weight(r - h, l, wm, d);
    BOOST_TEST(std::abs((wp - wm) / (2 * h) - dw) < 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(gimp_reduces_to_a_smoothed_hat_continuous_at_the_piece_joints) {
  const double l = 0.25;
  for (double r : {l, 1.0 - l, 1.0 + l}) {
    double a, b, d;
    gimp_weight(r - 1e-12, l, a, d);
    gimp_weight(r + 1e-12, l, b, d);
    BOOST_TEST(std::abs(a - b) < 1e-10);
  }
}

BOOST_AUTO_TEST_SUITE_END()
