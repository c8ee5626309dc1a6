#include "mpm/particles/particle_order.hpp"

#include <numeric>
#include <random>
#include <utility>

#include "mpm/particles/particles.hpp"

namespace impact::mpm {

namespace {

// A uniform draw in [0, bound] by rejection: the largest multiple of bound + 1 that fits below
// 2^64 keeps every residue equally likely.
std::uint64_t uniform_at_most(std::mt19937_64& random, std::uint64_t bound) {
  if (bound == ~std::uint64_t(0)) return random();
  const std::uint64_t range = bound + 1;
  const std::uint64_t limit = ~std::uint64_t(0) - (~std::uint64_t(0) % range + 1) % range;
  for (;;) {
    const std::uint64_t r = random();
    if (r <= limit) return r % range;
  }
}

}  // namespace

std::vector<std::size_t> shuffled_order(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::mt19937_64 random(seed);
  for (std::size_t i = n; i > 1; --i)
    std::swap(order[i - 1], order[std::size_t(uniform_at_most(random, i - 1))]);
  return order;
}

void store_in_order(Particles& P, const std::vector<std::size_t>& order) {
  if (P.id.empty()) {
    P.id.resize(P.size());
    std::iota(P.id.begin(), P.id.end(), std::uint64_t(0));
  }
  P.permute(order);
}

}  // namespace impact::mpm
