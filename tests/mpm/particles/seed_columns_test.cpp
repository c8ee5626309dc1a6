// seed_columns (mpm/particles/seeding.cpp): a rank on several seeds only its slab's cell columns.
// Checked against seed_particles(), the whole scene seeded at once: every column range gives the
// same particles, in the same order, with the same doubles, each with its index in the whole
// seeding as its id; the ranges of a split together give every particle once. The recommended
// sphere-cylinder: two objects (the later one's points inside the earlier one are skipped) and a
// sphere that lies in some columns only. The counts per column add up to the whole seeding.
// Blocks of columns counted apart (the census of several ranks) add up to the whole count.
// seed_box: the boxes of a 2 x 3 x 2 split seed every particle once, with the same doubles and
// seed indices, and the counts per cell along each axis match the whole seeding's cells.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "../verification_helpers.hpp"
#include "mpm/particles/particles.hpp"

using namespace impact::mpm;
using impact::Vec3;

BOOST_AUTO_TEST_SUITE(mpm_seed_columns)

BOOST_AUTO_TEST_CASE(the_counts_per_column_add_up_to_the_whole_seeding) {
  const Scene scene = test::shipped_scene("sphere_cylinder/recommended.json");
  const Particles all = seed_particles(scene);
  const auto counts = seed_counts_per_column(scene);
  BOOST_REQUIRE(counts.size() == scene.objects.size());
  std::size_t total = 0;
  for (std::size_t o = 0; o < counts.size(); ++o) {
    std::size_t of_object = 0;
    for (const std::size_t n : counts[o]) of_object += n;
    std::size_t seeded = 0;
    for (std::size_t p = 0; p < all.size(); ++p) seeded += all.object[p] == o;
    BOOST_TEST(of_object == seeded);
    total += of_object;
  }
  BOOST_TEST(total == all.size());
}

// The census of several ranks: each counts a block of columns, the blocks' counts summed must be
// the whole count, and a block counts nothing outside its columns.
BOOST_AUTO_TEST_CASE(blocks_of_columns_count_their_columns_only_and_add_up) {
  const Scene scene = test::shipped_scene("sphere_cylinder/recommended.json");
  SeedAxisCounts whole_axes;
  const auto whole = seed_counts_per_column(scene, &whole_axes);
  const std::vector<int> cuts = {0, 3, 5, 6, 7, 13, 29, 29, scene.grid.cells[0]};
  SeedCounts summed(whole.size(), std::vector<std::size_t>(whole[0].size(), 0));
  SeedAxisCounts summed_axes;
  for (std::size_t d = 0; d < 3; ++d) summed_axes[d].assign(whole_axes[d].size(), 0);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    SeedAxisCounts axes;
    const auto block = seed_counts_per_column(scene, &axes, cuts[k], cuts[k + 1]);
    for (std::size_t o = 0; o < block.size(); ++o)
      for (std::size_t i = 0; i < block[o].size(); ++i) {
        const bool inside = int(i) >= cuts[k] && int(i) < cuts[k + 1];
        BOOST_TEST(block[o][i] == (inside ? whole[o][i] : 0u));
        summed[o][i] += block[o][i];
      }
    for (std::size_t d = 0; d < 3; ++d)
      for (std::size_t c = 0; c < axes[d].size(); ++c) summed_axes[d][c] += axes[d][c];
  }
  BOOST_TEST(summed == whole);
  for (std::size_t d = 0; d < 3; ++d) BOOST_TEST(summed_axes[d] == whole_axes[d]);
}

BOOST_AUTO_TEST_CASE(column_ranges_seed_the_same_particles_with_their_seed_indices) {
  const Scene scene = test::shipped_scene("sphere_cylinder/recommended.json");
  const Particles all = seed_particles(scene);
  const auto counts = seed_counts_per_column(scene);
  const int cells = scene.grid.cells[0];
  // Splits at the sphere's columns, inside the plate and in the cylinder, and one empty range.
  const std::vector<int> cuts = {0, 3, 5, 6, 7, 13, 29, 29, cells};
  std::vector<int> seen(all.size(), 0);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const Particles slab = seed_columns(scene, cuts[k], cuts[k + 1], counts);
    BOOST_REQUIRE(slab.id.size() == slab.size());
    std::size_t expected = 0;
    for (const auto& object : counts)
      for (int i = cuts[k]; i < cuts[k + 1]; ++i) expected += object[std::size_t(i)];
    BOOST_TEST(slab.size() == expected);
    for (std::size_t p = 0; p < slab.size(); ++p) {
      const std::size_t q = slab.id[p];
      BOOST_REQUIRE(q < all.size());
      ++seen[q];
      BOOST_TEST((slab.x[p] == all.x[q]));  // the same doubles
      BOOST_TEST((slab.v[p] == all.v[q]));
      BOOST_TEST(slab.mass[p] == all.mass[q]);
      BOOST_TEST(slab.volume0[p] == all.volume0[q]);
      BOOST_TEST(slab.object[p] == all.object[q]);
      BOOST_TEST(slab.material[p] == all.material[q]);
      BOOST_TEST(slab.field[p] == all.field[q]);
      BOOST_TEST(slab.state[p].temperature == all.state[q].temperature);
      BOOST_TEST(slab.wave_speed[p] == all.wave_speed[q]);
      if (p > 0) BOOST_TEST(slab.id[p] > slab.id[p - 1]);  // seed order kept
      const int column =
          static_cast<int>((slab.x[p](0) - scene.grid.lower(0)) / scene.grid.spacing()(0));
      BOOST_TEST((column >= cuts[k] && column < cuts[k + 1]));
    }
  }
  for (std::size_t q = 0; q < all.size(); ++q) BOOST_TEST_REQUIRE(seen[q] == 1);
}

BOOST_AUTO_TEST_CASE(boxes_seed_every_particle_once_with_its_seed_index) {
  const Scene scene = test::shipped_scene("sphere_cylinder/recommended.json");
  const Particles all = seed_particles(scene);
  SeedAxisCounts per_axis;
  const auto counts = seed_counts_per_column(scene, &per_axis);
  const GridSpec& g = scene.grid;
  const auto cell = [&](const Vec3& x, int d) {
    return static_cast<int>(std::floor((x(d) - g.lower(d)) / g.spacing()(d)));
  };
  // The counts per cell along each axis, counted again from the whole seeding.
  for (int d = 0; d < 3; ++d) {
    std::vector<std::size_t> expected(std::size_t(g.cells[std::size_t(d)]), 0);
    for (const Vec3& x : all.x) ++expected[std::size_t(cell(x, d))];
    BOOST_TEST(per_axis[std::size_t(d)] == expected);
  }
  const std::vector<int> cx = {0, 7, g.cells[0]}, cy = {0, 4, 11, g.cells[1]},
                         cz = {0, 9, g.cells[2]};
  std::vector<int> seen(all.size(), 0);
  for (std::size_t a = 0; a + 1 < cx.size(); ++a)
    for (std::size_t b = 0; b + 1 < cy.size(); ++b)
      for (std::size_t c = 0; c + 1 < cz.size(); ++c) {
        const std::array<int, 3> lo{cx[a], cy[b], cz[c]}, hi{cx[a + 1], cy[b + 1], cz[c + 1]};
        const Particles box = seed_box(scene, lo, hi, counts);
        BOOST_REQUIRE(box.id.size() == box.size());
        for (std::size_t p = 0; p < box.size(); ++p) {
          const std::size_t q = box.id[p];
          BOOST_REQUIRE(q < all.size());
          ++seen[q];
          BOOST_TEST((box.x[p] == all.x[q]));
          BOOST_TEST(box.mass[p] == all.mass[q]);
          BOOST_TEST(box.object[p] == all.object[q]);
          if (p > 0) BOOST_TEST(box.id[p] > box.id[p - 1]);  // seed order kept
          for (int d = 0; d < 3; ++d)
            BOOST_TEST((cell(box.x[p], d) >= lo[std::size_t(d)] &&
                        cell(box.x[p], d) < hi[std::size_t(d)]));
        }
      }
  for (std::size_t q = 0; q < all.size(); ++q) BOOST_TEST_REQUIRE(seen[q] == 1);
}

BOOST_AUTO_TEST_SUITE_END()
