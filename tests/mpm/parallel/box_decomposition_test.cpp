// BoxDecomposition (mpm/parallel/box_decomposition.hpp): the ranks per axis against cut areas
// counted by hand, the refusal of a grid no split fits, rank <-> box coordinates, the owner of
// every cell (inside and outside the grid) against the boxes' cell ranges, and per-axis balance.
#include "mpm/parallel/box_decomposition.hpp"

#include <boost/test/unit_test.hpp>
#include <stdexcept>

using namespace impact::mpm;

BOOST_AUTO_TEST_SUITE(mpm_box_decomposition)

// Cut node faces sum_d (p_d - 1) N_e N_f, N = cells + 1 per axis:
//   112 x 45 x 45 on 4: 4x1x1 cuts 3 * 46 * 46 = 6348, 2x2x1 46 * 46 + 113 * 46 = 7314: slabs.
//   12 x 12 x 12 on 4: 4x1x1 cuts 3 * 13 * 13 = 507; 2x2x1, 2x1x2 and 1x2x2 all cut
//     2 * 13 * 13 = 338: the tie goes to x, then y.
//   8 x 20 x 12 on 4: 1x2x2 cuts 9 * 13 + 9 * 21 = 306, 1x4x1 351, 2x2x1 390, 2x1x2 462, 1x1x4
//     567; 4x1x1 leaves 2-cell slabs.
//   13 x 7 x 7 on 4 (the Taylor rod): 2x2x1 cuts 8 * 8 + 14 * 8 = 176, 4x1x1 192.
//   48 x 2 x 2 on 2: the narrow axes are not split, so they need no width.
BOOST_AUTO_TEST_CASE(the_ranks_per_axis_cut_the_fewest_node_faces) {
  using P = std::array<int, 3>;
  BOOST_TEST((BoxDecomposition::ranks_per_axis({112, 45, 45}, 2) == P{2, 1, 1}));
  BOOST_TEST((BoxDecomposition::ranks_per_axis({112, 45, 45}, 4) == P{4, 1, 1}));
  BOOST_TEST((BoxDecomposition::ranks_per_axis({12, 12, 12}, 4) == P{2, 2, 1}));
  BOOST_TEST((BoxDecomposition::ranks_per_axis({8, 20, 12}, 4) == P{1, 2, 2}));
  BOOST_TEST((BoxDecomposition::ranks_per_axis({13, 7, 7}, 4) == P{2, 2, 1}));
  BOOST_TEST((BoxDecomposition::ranks_per_axis({48, 2, 2}, 2) == P{2, 1, 1}));
  BOOST_TEST((BoxDecomposition::ranks_per_axis({40, 40, 40}, 8) == P{2, 2, 2}));
  BOOST_TEST((BoxDecomposition::ranks_per_axis({5, 5, 5}, 1) == P{1, 1, 1}));
}

BOOST_AUTO_TEST_CASE(a_grid_no_split_fits_is_refused_with_its_size) {
  try {
    BoxDecomposition::ranks_per_axis({5, 5, 5}, 4);  // 2 boxes of 5 cells would be 2 and 3 wide
    BOOST_FAIL("expected std::invalid_argument");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(std::string(e.what()).find("5 x 5 x 5 cells cannot be split into 4 boxes") !=
               std::string::npos);
  }
  BOOST_CHECK_THROW(BoxDecomposition::ranks_per_axis({100, 100, 100}, 0), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(every_cell_belongs_to_the_box_whose_cell_range_holds_it) {
  // 2 x 3 x 2 boxes of a 10 x 15 x 8 grid, boundaries set by hand.
  const BoxDecomposition b({SlabDecomposition({0, 4, 10}), SlabDecomposition({0, 5, 9, 15}),
                            SlabDecomposition({0, 4, 8})});
  BOOST_TEST(b.ranks() == 12);
  BOOST_TEST(b.describe() == "x [0, 4) [4, 10); y [0, 5) [5, 9) [9, 15); z [0, 4) [4, 8)");
  for (int r = 0; r < b.ranks(); ++r) BOOST_TEST(b.rank_at(b.coordinates(r)) == r);
  BOOST_TEST((b.coordinates(7) == std::array<int, 3>{1, 0, 1}));  // (1 * 3 + 0) * 2 + 1
  for (int i = -1; i <= 10; ++i)
    for (int j = -1; j <= 15; ++j)
      for (int k = -1; k <= 8; ++k) {
        const int owner = b.owner_of_cell({i, j, k});
        const std::array<int, 3> lo = b.first_cell(owner), hi = b.end_cell(owner);
        const int c[3] = {i, j, k}, n[3] = {10, 15, 8};
        for (int d = 0; d < 3; ++d) {
          // Outside the grid: the box at that face.
          const int inside = std::min(std::max(c[d], 0), n[d] - 1);
          BOOST_TEST_REQUIRE((inside >= lo[std::size_t(d)] && inside < hi[std::size_t(d)]));
        }
      }
}

BOOST_AUTO_TEST_CASE(each_axis_is_balanced_by_its_own_counts) {
  // 16 cells per axis; x: all particles in cells 0-7, y uniform, z in cells 8-15.
  AxisCounts counts;
  for (int c = 0; c < 16; ++c) {
    counts[0].push_back(c < 8 ? 10 : 0);
    counts[1].push_back(5);
    counts[2].push_back(c >= 8 ? 10 : 0);
  }
  const BoxDecomposition b = BoxDecomposition::balanced(counts, {2, 2, 2});
  BOOST_TEST(b.axis(0).first_cells() == (std::vector<int>{0, 4, 16}));
  BOOST_TEST(b.axis(1).first_cells() == (std::vector<int>{0, 8, 16}));
  BOOST_TEST(b.axis(2).first_cells() == (std::vector<int>{0, 12, 16}));
  BOOST_TEST((b.ranks_per_axis() == std::array<int, 3>{2, 2, 2}));
}

BOOST_AUTO_TEST_SUITE_END()
