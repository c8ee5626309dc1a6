// seed_box (mpm/particles/seeding.cpp) holds no more than its own box's particles at any time.
// This executable replaces the global operator new and delete with counting ones (bytes live and
// their peak), so the heap seed_box takes while it runs is measured, not estimated. On the
// recommended sphere-cylinder, a box of the middle third of y (the whole x and z ranges, as a
// rank of a 1 x 3 x 1 split gets) must peak at no more than its result's storage plus 1 %: seeding
// the whole x range and trimming it afterwards peaked at about three times that. The box's
// particles are also checked against seed_particles() (the same doubles, by seed index), so that
// the bound cannot be met by seeding too few.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <new>
#include <string>
#include <type_traits>

#include "../verification_helpers.hpp"
#include "mpm/particles/particles.hpp"

namespace {

// Heap bytes live and their peak since the last reset (the test runs on one thread).
std::size_t g_live = 0;
std::size_t g_peak = 0;
constexpr std::size_t kHeader = alignof(std::max_align_t);  // keeps the block's alignment

}  // namespace

// Not inlined: GCC would otherwise pair the inner free() with the caller's new expression
// (-Wmismatched-new-delete).
[[gnu::noinline]] void* operator new(std::size_t n) {
  void* block = std::malloc(n + kHeader);
  if (!block) throw std::bad_alloc();
  *static_cast<std::size_t*>(block) = n;
  g_live += n;
  g_peak = std::max(g_peak, g_live);
  return static_cast<char*>(block) + kHeader;
}

[[gnu::noinline]] void operator delete(void* p) noexcept {
  if (!p) return;
  void* block = static_cast<char*>(p) - kHeader;
  g_live -= *static_cast<std::size_t*>(block);
  std::free(block);
}

void operator delete(void* p, std::size_t) noexcept {
  operator delete(p);
}

using namespace impact::mpm;

namespace {

std::size_t storage_bytes(const Particles& p) {
  std::size_t bytes = 0;
  p.for_each_array([&](const auto& a) {
    bytes += a.capacity() * sizeof(typename std::decay_t<decltype(a)>::value_type);
  });
  return bytes;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_seed_box_memory)

BOOST_AUTO_TEST_CASE(a_box_never_holds_more_than_its_own_particles) {
  const Scene scene = test::shipped_scene("sphere_cylinder/recommended.json");
  const Particles all = seed_particles(scene);
  const SeedCounts counts = seed_counts_per_column(scene);
  const auto& cells = scene.grid.cells;
  const std::array<int, 3> first{0, cells[1] / 3, 0}, end{cells[0], 2 * cells[1] / 3, cells[2]};

  const std::size_t before = g_live;
  g_peak = g_live;
  const Particles box = seed_box(scene, first, end, counts);
  const std::size_t peak = g_peak - before;
  const std::size_t kept = storage_bytes(box);

  BOOST_TEST_MESSAGE("box of " << box.size() << " of " << all.size() << " particles: " << kept / 1e6
                               << " MB stored, heap peak while seeding " << peak / 1e6 << " MB");
  BOOST_TEST_REQUIRE(box.size() > 0u);
  BOOST_TEST_REQUIRE(box.size() < all.size() / 2);  // a box, not the x range
  BOOST_TEST(peak <= kept + kept / 100);
  BOOST_TEST(box.x.capacity() == box.size());  // exactly reserved, as seed_particles()
  BOOST_TEST_REQUIRE(box.id.size() == box.size());
  std::size_t expected = 0;
  for (std::size_t q = 0; q < all.size(); ++q) {
    const auto c = scene.grid.cell_of(all.x[q]);
    expected += c[1] >= first[1] && c[1] < end[1] ? 1 : 0;
  }
  BOOST_TEST(box.size() == expected);
  for (std::size_t p = 0; p < box.size(); ++p) {
    BOOST_REQUIRE(box.id[p] < all.size());
    BOOST_TEST_REQUIRE((box.x[p] == all.x[box.id[p]]));
  }
}

BOOST_AUTO_TEST_SUITE_END()
