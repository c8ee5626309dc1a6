// A graded (tartan) axis (mpm/scene/graded_axis.hpp, issue 56) against its construction rules,
// worked by hand for [0, 1] m with 10 base cells (h0 = 0.1 m) refined 4 times on [0.4, 0.6] with
// growth 1.2: 8 cells of 0.025 m inside; outside, cells of 0.03, 0.036, 0.0432, ... capped at
// 0.1: seven reach 0.3875 m, eight 0.4875 m, so each side of 0.4 m gets eight cells with a common
// ratio r < 1.2 for which 0.025 (r + r^2 + ... ) with the cap fills it.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mpm/scene/graded_axis.hpp"

using namespace impact::mpm;

BOOST_AUTO_TEST_SUITE(graded_axes)

BOOST_AUTO_TEST_CASE(a_span_without_refinement_gives_the_uniform_nodes_exactly) {
  const GradedAxis axis = graded_axis(0.0, 0.06, 12, RefinedSpan{0.01, 0.02, 1.0, 1.2});
  BOOST_TEST(axis.cells() == 12);
  for (int i = 0; i <= 12; ++i) BOOST_TEST(axis.node(i) == 0.0 + i * (0.06 / 12));
}

BOOST_AUTO_TEST_CASE(refined_cells_fill_the_span_and_grow_outside_it) {
  const double h0 = 0.1, F = 4.0, g = 1.2;
  const GradedAxis axis = graded_axis(0.0, 1.0, 10, RefinedSpan{0.4, 0.6, F, g});
  BOOST_TEST(axis.cells() == 8 + 8 + 8);
  BOOST_TEST(axis.node(0) == 0.0);
  BOOST_TEST(axis.node(axis.cells()) == 1.0);
  BOOST_TEST(axis.node(8) == 0.4);  // the span's edges are nodes, exactly
  BOOST_TEST(axis.node(16) == 0.6);
  for (int i = 8; i < 16; ++i) BOOST_TEST(std::abs(axis.size(i) - h0 / F) < 1e-15);
  const double r = axis.size(16) / (h0 / F);  // the first cell above the span
  BOOST_TEST(r > 1.0);
  BOOST_TEST(r < g);
  double filled = 0.0, h = h0 / F;  // the side above: the cells the ratio r makes
  for (int k = 0; k < 8; ++k) filled += (h = std::min(h * r, h0));
  BOOST_TEST(std::abs(filled - 0.4) < 1e-12);
  BOOST_TEST(std::abs(axis.size(7) - axis.size(16)) < 1e-15);  // the side below mirrors it
  for (int i = 1; i < axis.cells(); ++i) {  // neighbours differ by the growth ratio at most
    const double ratio = axis.size(i) / axis.size(i - 1);
    BOOST_TEST(ratio <= g * (1.0 + 1e-12));
    BOOST_TEST(ratio >= 1.0 / g / (1.0 + 1e-12));
  }
  BOOST_TEST(axis.largest() <= h0);
  BOOST_TEST(std::abs(axis.smallest() - h0 / F) < 1e-15);
}

BOOST_AUTO_TEST_CASE(the_cell_of_a_coordinate_and_the_ghost_nodes) {
  const GradedAxis axis = graded_axis(0.0, 1.0, 10, RefinedSpan{0.4, 0.6, 4.0, 1.2});
  BOOST_TEST(axis.cell_of(0.4) == 8);                 // a node belongs to the cell above it
  BOOST_TEST(axis.cell_of(0.4125) == 8);              // half-way through the first refined cell
  BOOST_TEST(axis.cell_of(1.0) == axis.cells() - 1);  // the upper face: the last cell
  BOOST_TEST(axis.cell_of(-0.01) == 0);               // clamped
  // The ghost cells repeat the edge cells' sizes.
  BOOST_TEST(std::abs(axis.size(-1) - axis.size(0)) < 1e-15);
  BOOST_TEST(std::abs(axis.size(axis.cells()) - axis.size(axis.cells() - 1)) < 1e-15);
}

// A list of boxes (grid.refine as a list) refines, along each axis, the spans of all of them.
// Worked by hand for [0, 1] m, 10 base cells (h0 = 0.1 m), spans [0.1, 0.2] refined 4 times
// (growth 1.2) and [0.7, 0.8] refined twice (growth 1.5): 4 cells of 0.025 m and 2 of 0.05 m.
// Below the first span 0.1 m: 0.03, 0.036, 0.0432 reach it, 3 cells. Above the second 0.2 m:
// 0.075, 0.1, 0.1 reach it, 3 cells. The gap of 0.5 m between them, the smaller next cell first:
// 0.03, 0.036, 0.0432, 0.05184, 0.062208, 0.0746496 from below (each under the 0.075 from above),
// then 0.075 from above, then 0.0896 and 0.1 from below: 9 cells reach 0.562 m (their cap then
// lowered to fill 0.5 m). So 21 cells, the spans' edges at nodes 3, 7, 16 and 18.
BOOST_AUTO_TEST_CASE(two_spans_are_refined_with_the_gap_graded_from_both_ends) {
  const double h0 = 0.1;
  const GradedAxis axis = graded_axis(
      0.0, 1.0, 10, std::vector<RefinedSpan>{{0.7, 0.8, 2.0, 1.5}, {0.1, 0.2, 4.0, 1.2}});
  BOOST_TEST(axis.cells() == 21);
  BOOST_TEST(axis.node(0) == 0.0);
  BOOST_TEST(axis.node(3) == 0.1);  // the spans' edges are nodes, exactly
  BOOST_TEST(axis.node(7) == 0.2);
  BOOST_TEST(axis.node(16) == 0.7);
  BOOST_TEST(axis.node(18) == 0.8);
  BOOST_TEST(axis.node(21) == 1.0);
  for (int i = 3; i < 7; ++i) BOOST_TEST(std::abs(axis.size(i) - 0.025) < 1e-15);
  for (int i = 16; i < 18; ++i) BOOST_TEST(std::abs(axis.size(i) - 0.05) < 1e-15);
  for (int i = 1; i < axis.cells(); ++i) {  // no neighbour ratio beyond the larger growth
    const double ratio = axis.size(i) / axis.size(i - 1);
    BOOST_TEST(ratio <= 1.5 * (1.0 + 1e-12));
    BOOST_TEST(ratio >= 1.0 / 1.5 / (1.0 + 1e-12));
  }
  for (int i = 8; i < 15; ++i)  // the gap's cells from the first span grow by its 1.2 at most
    BOOST_TEST(axis.size(i) / axis.size(i - 1) <= 1.2 * (1.0 + 1e-12));
  BOOST_TEST(axis.largest() <= h0 * (1.0 + 1e-12));
  BOOST_TEST(std::abs(axis.smallest() - 0.025) < 1e-15);
}

// Spans that overlap (or touch) once widened to the base nodes merge into one with the finest
// factor and the slowest growth; one span given as a list is the one-span axis node for node.
BOOST_AUTO_TEST_CASE(overlapping_spans_merge_and_one_span_in_a_list_is_the_same_axis) {
  const GradedAxis merged = graded_axis(
      0.0, 1.0, 10, std::vector<RefinedSpan>{{0.4, 0.55, 2.0, 1.5}, {0.5, 0.6, 4.0, 1.2}});
  // (0.55 widens to the node 6 h0, as the one span's 0.55 does; 0.6 as given is a round-off away.)
  const GradedAxis one = graded_axis(0.0, 1.0, 10, RefinedSpan{0.4, 0.55, 4.0, 1.2});
  BOOST_TEST(merged.nodes() == one.nodes());
  const RefinedSpan off_node{0.43, 0.571, 3.0, 1.3};
  BOOST_TEST(graded_axis(0.0, 1.0, 10, std::vector<RefinedSpan>{off_node}).nodes() ==
             graded_axis(0.0, 1.0, 10, off_node).nodes());
  const GradedAxis touching = graded_axis(
      0.0, 1.0, 10, std::vector<RefinedSpan>{{0.2, 0.4, 2.0, 1.2}, {0.4, 0.6, 2.0, 1.2}});
  BOOST_TEST(touching.nodes() ==
             graded_axis(0.0, 1.0, 10, RefinedSpan{0.2, 0.6, 2.0, 1.2}).nodes());
}

// Two boxes whose edges meet within round-off of the same base node merge (by node index): the
// second box's 0.005 is the node 7 h0 as given, the first box's edge 0.005 widened is -0.03 + 7 h0,
// an ulp away; compared as coordinates they left a cell of 5e-18 m between them (the audit's).
BOOST_AUTO_TEST_CASE(boxes_meeting_at_a_node_within_round_off_merge_without_a_sliver) {
  const GradedAxis axis =
      graded_axis(-0.03, 0.03, 12,
                  std::vector<RefinedSpan>{{-0.01, 0.0049, 2.0, 1.2}, {0.005, 0.02, 2.0, 1.2}});
  BOOST_TEST(axis.smallest() > 0.0025 * (1.0 - 1e-9));
  const GradedAxis edges = graded_axis(
      -0.03, 0.03, 12, std::vector<RefinedSpan>{{-0.01, 0.005, 2.0, 1.2}, {0.006, 0.02, 2.0, 1.2}});
  BOOST_TEST(edges.smallest() > 0.0025 * (1.0 - 1e-9));
}

// Where the two sides of a gap meet, the cells differ by a growth at most, whatever the gap's
// length and the spans' factors (the sides are capped together, not scaled together: scaled by one
// common ratio, a side of many uncapped cells shrank much more than the other, and h0 met 0.79 h0
// at growth 1.2 on [0, 1] with 40 base cells and boxes [0.125, 0.2] and [0.5, 0.575] refined
// twice, the audit's). Scanned over factors 2 to 16 on either side and gaps of 4 to 12 base cells;
// no gap cell is smaller than the finer span's cell, none larger than h0.
BOOST_AUTO_TEST_CASE(the_cells_of_a_gap_grow_by_the_growth_at_most_where_its_sides_meet) {
  const double h0 = 1.0 / 40;
  for (const double fa : {2.0, 4.0, 8.0, 16.0})
    for (const double fb : {2.0, 4.0, 8.0, 16.0})
      for (int gap = 4; gap <= 12; ++gap)
        for (const double g : {1.2, 1.5}) {
          const double b0 = 0.125 + 3 * h0 + gap * h0;
          const GradedAxis axis =
              graded_axis(0.0, 1.0, 40,
                          std::vector<RefinedSpan>{{0.125, 0.2, fa, g}, {b0, b0 + 3 * h0, fb, g}});
          double worst = 0.0;
          for (int i = 1; i < axis.cells(); ++i)
            worst =
                std::max({worst, axis.size(i) / axis.size(i - 1), axis.size(i - 1) / axis.size(i)});
          BOOST_TEST(worst <= g * (1.0 + 1e-9), "factors " << fa << ", " << fb << ", gap " << gap
                                                           << " h0, growth " << g << ": ratio "
                                                           << worst);
          BOOST_TEST(axis.largest() <= h0 * (1.0 + 1e-9));
          BOOST_TEST(axis.smallest() >= h0 / std::max(fa, fb) * (1.0 - 1e-9));
        }
}

BOOST_AUTO_TEST_SUITE_END()
