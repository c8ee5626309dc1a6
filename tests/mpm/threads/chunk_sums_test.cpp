// Sums per fixed chunk, added in chunk order (mpm/threads/chunk_sums.hpp): the chunks cover the
// items once, and a sum whose value depends on the order of its terms comes out the same bits on
// 1 to 4 threads, where per-thread partial sums do not. The ledger's sums rely on it
// (tests/mpm/simulation/determinism_test.cpp).
#include <boost/test/unit_test.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mpm/threads/chunk_sums.hpp"

using impact::mpm::ChunkSums;

BOOST_AUTO_TEST_CASE(the_chunks_cover_the_items_once_the_last_one_shorter) {
  const ChunkSums<double> ten(10, 4);
  BOOST_TEST(ten.chunks() == 3);
  BOOST_TEST(ten.begin(0) == 0);
  BOOST_TEST(ten.end(0) == 4);
  BOOST_TEST(ten.begin(2) == 8);
  BOOST_TEST(ten.end(2) == 10);
  BOOST_TEST(ChunkSums<double>(8, 4).chunks() == 2);
  BOOST_TEST(ChunkSums<double>(0, 4).chunks() == 0);
}

namespace {

// Terms of very different sizes and both signs: their floating-point sum depends on the order.
std::vector<double> terms() {
  std::mt19937_64 random(57);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-8, 8);
  std::vector<double> x(1000);
  for (double& v : x) v = mantissa(random) * std::pow(10.0, exponent(random));
  return x;
}

double by_chunks(const std::vector<double>& x, int threads) {
  ChunkSums<double> sums(static_cast<std::ptrdiff_t>(x.size()), 7);
  const std::ptrdiff_t chunks = sums.chunks();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t c = 0; c < chunks; ++c)
    for (std::ptrdiff_t i = sums.begin(c); i < sums.end(c); ++i) sums[c] += x[std::size_t(i)];
  double total = 0.0;
  sums.add_in_order([&](double s) { total += s; });
  return total;
}

// What the loops did before: each thread sums its static share, then the shares in thread order.
double by_thread_shares(const std::vector<double>& x, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x.size());
  double total = 0.0;
  for (int t = 0; t < threads; ++t) {
    double share = 0.0;
    for (std::ptrdiff_t i = n * t / threads; i < n * (t + 1) / threads; ++i)
      share += x[std::size_t(i)];
    total += share;
  }
  return total;
}

}  // namespace

BOOST_AUTO_TEST_CASE(an_order_sensitive_sum_is_the_same_bits_on_any_thread_count) {
  const std::vector<double> x = terms();
  // The terms are order-sensitive: per-thread shares give other bits on 1 and 3 threads.
  BOOST_TEST(by_thread_shares(x, 1) != by_thread_shares(x, 3));
  // The chunks' sums, each left to right, then in chunk order: the reference, in one thread.
  double reference = 0.0;
  for (std::size_t c = 0; c < x.size(); c += 7) {
    double chunk = 0.0;
    for (std::size_t i = c; i < std::min(x.size(), c + 7); ++i) chunk += x[i];
    reference += chunk;
  }
  for (int threads = 1; threads <= 4; ++threads) BOOST_TEST(by_chunks(x, threads) == reference);
}
