// The least loaded boxes (mpm/parallel/split_search.hpp), on one process:
// - one split axis: refine_boundaries finds the optimum, the smallest busiest slab over every
//   placement of the cuts that leaves each slab at least 3 cells wide, enumerated here, on 200
//   pseudo-random count profiles and on a spike that defeats a greedy fill (slabs that take all
//   they can push the next slab's first 3 cells onto the spike);
// - the recommended sphere-cylinder on 8 ranks, every split: the refined boxes' busiest box,
//   counted here particle by particle (BoxDecomposition::owner_of_cell), is the reported one,
//   never above the boxes balanced per axis, below them for some split, and every box is at least
//   3 cells wide along a split axis; least_loaded_split is the least of them (fewer cut node
//   faces on a tie).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cstdint>
#include <limits>

#include "../verification_helpers.hpp"
#include "mpm/parallel/split_search.hpp"

using namespace impact::mpm;

namespace {

std::vector<double> on_one_process(const std::vector<double>& table) {
  return table;
}

// The smallest busiest slab of `counts` cut into 3 slabs at least 3 cells wide.
double best_of_every_cut(const std::vector<std::size_t>& counts) {
  const int n = int(counts.size());
  const auto sum = [&](int a, int b) {
    double s = 0.0;
    for (int i = a; i < b; ++i) s += double(counts[std::size_t(i)]);
    return s;
  };
  double best = std::numeric_limits<double>::infinity();
  for (int c1 = 3; c1 <= n - 6; ++c1)
    for (int c2 = c1 + 3; c2 <= n - 3; ++c2)
      best = std::min(best, std::max({sum(0, c1), sum(c1, c2), sum(c2, n)}));
  return best;
}

double refined_along_x(const std::vector<std::size_t>& counts) {
  const int n = int(counts.size());
  std::vector<CellCount> counted;
  for (int i = 0; i < n; ++i)
    if (counts[std::size_t(i)] > 0) counted.push_back({{i, 0, 0}, double(counts[std::size_t(i)])});
  const AxisCounts axes{counts, {1}, {1}};
  double busiest = 0.0;
  const BoxDecomposition boxes = refine_boundaries(BoxDecomposition::balanced(axes, {3, 1, 1}),
                                                   counted, on_one_process, &busiest);
  for (int r = 0; r < 3; ++r)
    BOOST_TEST(boxes.axis(0).first_cell(r + 1) - boxes.axis(0).first_cell(r) >= 3);
  return busiest;
}

// The particles of each box, counted one by one.
std::vector<double> held(const BoxDecomposition& boxes, const Particles& P, const GridSpec& g) {
  std::vector<double> n(std::size_t(boxes.ranks()), 0.0);
  for (const impact::Vec3& x : P.x) n[std::size_t(boxes.owner_of_cell(g.cell_of(x)))] += 1.0;
  return n;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_split_search)

BOOST_AUTO_TEST_CASE(one_axis_is_cut_at_the_optimum) {
  std::uint64_t state = 12345;
  const auto next = [&] {  // a linear congruential generator: the same profiles every run
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return std::size_t(state >> 33);
  };
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::size_t> counts(std::size_t(9 + trial % 8));
    for (std::size_t& c : counts) c = next() % (trial % 3 == 0 ? 1000 : 10);
    BOOST_TEST_REQUIRE(refined_along_x(counts) == best_of_every_cut(counts));
  }
  const std::vector<std::size_t> spike = {1, 1, 1, 1, 1, 1, 100, 0, 0, 0};
  BOOST_TEST(best_of_every_cut(spike) == 100.0);
  BOOST_TEST(refined_along_x(spike) == 100.0);
}

BOOST_AUTO_TEST_CASE(refined_boxes_are_never_busier_and_the_least_loaded_is_the_least) {
  const Scene scene = test::shipped_scene("sphere_cylinder/recommended.json");
  const GridSpec& g = scene.grid;
  const Particles all = seed_particles(scene);
  AxisCounts counts;
  std::vector<CellCount> counted;
  for (std::size_t d = 0; d < 3; ++d) counts[d].assign(std::size_t(g.cells[d]), 0);
  for (const impact::Vec3& x : all.x) {
    const std::array<int, 3> c = g.cell_of(x);
    for (std::size_t d = 0; d < 3; ++d) ++counts[d][std::size_t(c[d])];
    count_cell(counted, c);
  }
  const int ranks = 8;
  double least = std::numeric_limits<double>::infinity(), least_cut = least;
  std::array<int, 3> least_split{};
  int improved = 0;
  for (const std::array<int, 3>& p : BoxDecomposition::splits(g.cells, ranks)) {
    const BoxDecomposition balanced = BoxDecomposition::balanced(counts, p);
    double busiest = 0.0;
    const BoxDecomposition refined = refine_boundaries(balanced, counted, on_one_process, &busiest);
    const std::vector<double> before = held(balanced, all, g), after = held(refined, all, g);
    const double was = *std::max_element(before.begin(), before.end());
    const double is = *std::max_element(after.begin(), after.end());
    BOOST_TEST_MESSAGE(p[0] << " x " << p[1] << " x " << p[2] << ": busiest box " << was
                            << " balanced per axis, " << is << " refined");
    BOOST_TEST(is == busiest);
    BOOST_TEST(is <= was);
    improved += is < was ? 1 : 0;
    BOOST_TEST((refined.ranks_per_axis() == p));
    for (int d = 0; d < 3; ++d)
      for (int r = 0; r < p[std::size_t(d)] && p[std::size_t(d)] > 1; ++r)
        BOOST_TEST(refined.axis(d).first_cell(r + 1) - refined.axis(d).first_cell(r) >= 3);
    const double cut = BoxDecomposition::cut_faces(g.cells, p);
    if (is < least || (is == least && cut < least_cut)) {
      least = is;
      least_cut = cut;
      least_split = p;
    }
  }
  BOOST_TEST(improved > 0);
  const SplitChoice choice = least_loaded_split(g.cells, counts, ranks, counted, on_one_process);
  BOOST_TEST(choice.busiest == least);
  BOOST_TEST((choice.boxes.ranks_per_axis() == least_split));
  BOOST_TEST(choice.splits_searched == BoxDecomposition::splits(g.cells, ranks).size());
}

BOOST_AUTO_TEST_SUITE_END()
