// SlabDecomposition (mpm/parallel/slab_decomposition.hpp): balanced boundaries against hand-counted
// ones, the minimum width, the owner of every cell, node plane and out-of-grid position, the
// imbalance measure, and the refusal of a grid too small for the rank count.
#include "mpm/parallel/slab_decomposition.hpp"

#include <boost/test/unit_test.hpp>
#include <stdexcept>

using namespace impact::mpm;

BOOST_AUTO_TEST_SUITE(mpm_slab_decomposition)

BOOST_AUTO_TEST_CASE(uniform_counts_give_equal_slabs) {
  const std::vector<std::size_t> counts(40, 10);
  const SlabDecomposition s = SlabDecomposition::balanced(counts, 4);
  BOOST_TEST(s.describe() == "[0, 10) [10, 20) [20, 30) [30, 40)");
  BOOST_TEST(s.imbalance(counts) == 1.0);
}

BOOST_AUTO_TEST_CASE(boundaries_cut_the_cumulative_count_into_equal_parts) {
  // 100 particles in cells 4-7 (25 each), 100 in cell 20: halves at the end of cell 7.
  std::vector<std::size_t> counts(30, 0);
  for (int c = 4; c < 8; ++c) counts[std::size_t(c)] = 25;
  counts[20] = 100;
  const SlabDecomposition two = SlabDecomposition::balanced(counts, 2);
  BOOST_TEST(two.first_cell(1) == 8);
  BOOST_TEST(two.imbalance(counts) == 1.0);
  // Four ranks: quarters at 50, 100, 150 particles -> after cells 5 and 7, the second pushed to
  // 9 by the minimum width (3 cells); the third lies in cell 20 (which cannot be split), after it.
  const SlabDecomposition four = SlabDecomposition::balanced(counts, 4);
  BOOST_TEST(four.describe() == "[0, 6) [6, 9) [9, 21) [21, 30)");
  BOOST_TEST(four.imbalance(counts) == 2.0);  // 100 of 200 on one rank, mean 50
}

BOOST_AUTO_TEST_CASE(every_slab_is_at_least_the_minimum_width) {
  std::vector<std::size_t> counts(16, 0);
  counts[0] = 1000;  // everything in the first cell
  const SlabDecomposition s = SlabDecomposition::balanced(counts, 4);
  for (int r = 0; r < 4; ++r)
    BOOST_TEST(s.first_cell(r + 1) - s.first_cell(r) >= SlabDecomposition::kMinCells);
  BOOST_TEST(s.cells() == 16);
}

BOOST_AUTO_TEST_CASE(owners_of_cells_nodes_and_positions_outside) {
  const SlabDecomposition s({0, 5, 12, 20});
  BOOST_TEST(s.owner_of_cell(-1) == 0);
  BOOST_TEST(s.owner_of_cell(0) == 0);
  BOOST_TEST(s.owner_of_cell(4) == 0);
  BOOST_TEST(s.owner_of_cell(5) == 1);
  BOOST_TEST(s.owner_of_cell(11) == 1);
  BOOST_TEST(s.owner_of_cell(12) == 2);
  BOOST_TEST(s.owner_of_cell(19) == 2);
  BOOST_TEST(s.owner_of_node(20) == 2);  // the last node plane
  BOOST_TEST(s.owner_of_node(21) == 2);  // the ghost plane
  BOOST_TEST(s.ranks() == 3);
}

BOOST_AUTO_TEST_CASE(a_grid_too_small_for_the_ranks_is_refused) {
  const std::vector<std::size_t> counts(5, 1);
  BOOST_CHECK_THROW(SlabDecomposition::balanced(counts, 2), std::invalid_argument);
  BOOST_CHECK_NO_THROW(SlabDecomposition::balanced(std::vector<std::size_t>(6, 1), 2));
  // One slab is the whole axis, however narrow (an axis the boxes do not split).
  BOOST_TEST(SlabDecomposition::balanced(std::vector<std::size_t>(1, 5), 1).first_cells() ==
             (std::vector<int>{0, 1}));
}

BOOST_AUTO_TEST_SUITE_END()
