// models/core/lane_math.hpp: exp, log, log1p, expm1 and pow against the C library (the
// independent reference) within the stated ulp, their special values, and the same bits on one
// double and on every lane of a vector (the property the batched return rests on).
#include "models/core/lane_math.hpp"

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace impact;

namespace {

// |a - b| in units of the last place of b.
double ulps(double a, double b) {
  if (a == b) return 0.0;
  const double ulp =
      std::nextafter(std::abs(b), std::numeric_limits<double>::infinity()) - std::abs(b);
  return std::abs(a - b) / ulp;
}

// f on the values x, kLaneWidth at a time as vectors.
template <class F>
std::vector<double> on_vectors(const std::vector<double>& x, F f) {
  std::vector<double> out(x.size());
  for (std::size_t i0 = 0; i0 < x.size(); i0 += lane::kLaneWidth) {
    lane::Vec v;
    for (int k = 0; k < lane::kLaneWidth; ++k) v[k] = x[std::min(x.size() - 1, i0 + k)];
    const lane::Vec r = f(v);
    for (int k = 0; k < lane::kLaneWidth && i0 + k < x.size(); ++k) out[i0 + k] = r[k];
  }
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(core_lane_math)

BOOST_AUTO_TEST_CASE(functions_match_the_c_library_within_their_stated_ulp) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst_exp = 0, worst_log = 0, worst_log1p = 0, worst_expm1 = 0, worst_pow = 0;
  for (int i = 0; i < 200000; ++i) {
    const double x = -745.0 + 1454.7 * u(gen);  // the finite, normal range of exp
    worst_exp = std::max(worst_exp, ulps(lane::exp(x), std::exp(x)));
    const double y = std::exp(-745.0 + 1454.0 * u(gen));  // subnormal to 1e308
    worst_log = std::max(worst_log, ulps(lane::log(y), std::log(y)));
    const double z = (2.0 * u(gen) - 1.0) * std::exp(-40.0 * u(gen));  // |z| from 4e-18 to 1
    worst_log1p = std::max(worst_log1p, ulps(lane::log1p(z), std::log1p(z)));
    const double w = (2.0 * u(gen) - 1.0) * std::exp(6.5 * u(gen) - 40.0 * u(gen));
    worst_expm1 = std::max(worst_expm1, ulps(lane::expm1(w), std::expm1(w)));
    // A plastic strain from 1e-12 to 10 to a hardening exponent from 0.01 to 1.5.
    const double ep = std::exp(-27.6 + 29.9 * u(gen)), n = 0.01 + 1.49 * u(gen);
    worst_pow = std::max(
        worst_pow, ulps(lane::pow(ep, n), std::pow(ep, n)) / (2.0 + std::abs(n * std::log(ep))));
  }
  BOOST_TEST_MESSAGE("worst ulp: exp " << worst_exp << ", log " << worst_log << ", log1p "
                                       << worst_log1p << ", expm1 " << worst_expm1
                                       << ", pow / (2 + |y ln x|) " << worst_pow);
  BOOST_TEST(worst_exp <= 2.0);
  BOOST_TEST(worst_log <= 2.0);
  BOOST_TEST(worst_log1p <= 4.0);
  BOOST_TEST(worst_expm1 <= 4.0);
  BOOST_TEST(worst_pow <= 1.0);
}

BOOST_AUTO_TEST_CASE(special_values) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  BOOST_TEST(lane::exp(-746.0) == 0.0);
  BOOST_TEST(lane::exp(710.0) == inf);
  BOOST_TEST(std::isnan(lane::exp(std::nan(""))));
  BOOST_TEST(lane::exp(0.0) == 1.0);
  BOOST_TEST(lane::log(1.0) == 0.0);
  BOOST_TEST(lane::log(0.0) == -inf);
  BOOST_TEST(lane::log(inf) == inf);
  BOOST_TEST(std::isnan(lane::log(-1.0)));
  BOOST_TEST(lane::log(4.9e-324) == std::log(4.9e-324));  // the smallest subnormal
  BOOST_TEST(lane::log1p(0.0) == 0.0);
  BOOST_TEST(lane::log1p(1e-300) == 1e-300);
  BOOST_TEST(lane::expm1(1e-300) == 1e-300);
  BOOST_TEST(lane::expm1(-800.0) == -1.0);
  BOOST_TEST(lane::pow(0.0, 0.42) == 0.0);
}

BOOST_AUTO_TEST_CASE(a_vector_gives_every_lane_the_bits_of_one_double) {
  const std::vector<double> x = {1e-300, 3e-12, 0.05, 0.5, 1.0, 2.7, 812.0, 1e300, 4.9e-324};
  const auto e = on_vectors(x, [](lane::Vec v) { return lane::exp(lane::Vec(-v * 1e-3)); });
  const auto l = on_vectors(x, [](lane::Vec v) { return lane::log(v); });
  const auto p = on_vectors(x, [](lane::Vec v) { return lane::pow(v, 0.42); });
  const auto m = on_vectors(x, [](lane::Vec v) { return lane::expm1(lane::Vec(v * -1e-3)); });
  for (std::size_t k = 0; k < x.size(); ++k) {
    BOOST_TEST(e[k] == lane::exp(-x[k] * 1e-3));
    BOOST_TEST(l[k] == lane::log(x[k]));
    BOOST_TEST(p[k] == lane::pow(x[k], 0.42));
    BOOST_TEST(m[k] == lane::expm1(x[k] * -1e-3));
  }
}

BOOST_AUTO_TEST_SUITE_END()
