// The scatter order (mpm/step/scatter_order.hpp): the particles grouped by the band of kBand node
// planes along x that their stencil starts in, ascending by index within a band, the bands in two
// colours. The counting sort runs on every thread, each counting and placing a contiguous range;
// the order must be the one thread's whatever the thread count (the scatters' sums, and so every
// particle's bits, follow it: docs/mpm.md#threads-and-determinism).
#include <omp.h>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <random>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/step/scatter_order.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// A dense grid of 40 x 4 x 4 unit cells: 41 node planes along x plus the ghost layers, six bands.
GridSpec long_grid() {
  GridSpec spec;
  spec.lower = Vec3::Zero();
  spec.upper = Vec3(40.0, 4.0, 4.0);
  spec.cells = {40, 4, 4};
  spec.faces.fill(FaceCondition::free);
  spec.active_blocks = false;
  return spec;
}

// n stencils whose base node along x is drawn from [-1, 38] (the ghost layer to the last cell),
// unevenly: a third of them in the first eight planes, as an impact crowds its particles.
std::vector<Stencil<3>> stencils(int n) {
  std::mt19937 draw(7);
  std::uniform_int_distribution<int> any(-1, 38), crowded(-1, 6);
  std::vector<Stencil<3>> S(n);
  for (int p = 0; p < n; ++p) S[p].base = {p % 3 == 0 ? crowded(draw) : any(draw), 0, 0};
  return S;
}

ScatterOrder order_on(int threads, const std::vector<Stencil<3>>& S) {
  GridSettings settings;
  settings.threads = threads;
  const Grid G(long_grid(), settings);
  ScatterOrder order;
  order_for_scatter(S, G, order);
  return order;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_order_is_grouped_by_band_ascending_within_each) {
  const std::vector<Stencil<3>> S = stencils(5003);
  const ScatterOrder order = order_on(1, S);
  GridSettings one;
  const Grid G(long_grid(), one);
  const int bands = static_cast<int>(order.start.size()) - 1;
  BOOST_TEST(order.start.front() == 0);
  BOOST_TEST(order.start.back() == 5003);
  std::vector<int> seen(S.size(), 0);
  for (int s = 0; s < bands; ++s)
    for (int k = order.start[s]; k < order.start[s + 1]; ++k) {
      const int p = order.particles[k];
      ++seen[p];
      BOOST_TEST(G.storage_x(S[p].base[0]) / ScatterOrder::kBand == s);
      if (k > order.start[s]) BOOST_TEST(order.particles[k - 1] < p);
    }
  BOOST_TEST(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
  for (int c = 0; c < 2; ++c)
    for (int s : order.colours[c]) BOOST_TEST(s % 2 == c);
}

BOOST_AUTO_TEST_CASE(every_thread_count_gives_the_one_thread_order) {
  for (int n : {1, 2, 17, 5003}) {
    const std::vector<Stencil<3>> S = stencils(n);
    const ScatterOrder one = order_on(1, S);
    for (int threads : {2, 3, 4}) {
      const ScatterOrder many = order_on(threads, S);
      BOOST_TEST(many.particles == one.particles, n << " particles on " << threads << " threads");
      BOOST_TEST(many.start == one.start);
      BOOST_TEST(many.colours[0] == one.colours[0]);
      BOOST_TEST(many.colours[1] == one.colours[1]);
    }
  }
}

// scatter_by_colour: each colour's bands are dealt in contiguous runs, one per thread in thread
// order, of about equal particle counts (each thread's share within one band of the equal share),
// every band wholly one thread's in its stored order, and a colour complete before the next
// starts. Dealt on demand, band by band, the runs interleave.
BOOST_AUTO_TEST_CASE(the_scatter_deals_contiguous_balanced_runs_of_bands) {
  GridSpec spec = long_grid();
  spec.upper = Vec3(200.0, 4.0, 4.0);
  spec.cells = {200, 4, 4};  // 26 bands, 13 of each colour
  std::mt19937 draw(11);
  std::uniform_int_distribution<int> any(-1, 198), crowded(60, 75);
  std::vector<Stencil<3>> S(20000);
  for (std::size_t p = 0; p < S.size(); ++p)
    S[p].base = {p % 3 == 0 ? crowded(draw) : any(draw), 0, 0};
  for (int threads : {2, 3, 4}) {
    GridSettings settings;
    settings.threads = threads;
    const Grid G(spec, settings);
    ScatterOrder order;
    order_for_scatter(S, G, order);
    std::vector<int> thread_of(S.size(), -1), seq_of(S.size(), -1);
    std::vector<int> visits(S.size(), 0);
    std::atomic<int> seq{0};
    scatter_by_colour(order, threads, [&](int p) {
      thread_of[p] = omp_get_thread_num();
      seq_of[p] = seq++;
      ++visits[p];  // one thread per band: no race if the deal is right
    });
    BOOST_TEST(std::all_of(visits.begin(), visits.end(), [](int v) { return v == 1; }));
    int last_of_colour0 = -1;
    for (int s : order.colours[0])
      for (int k = order.start[s]; k < order.start[s + 1]; ++k)
        last_of_colour0 = std::max(last_of_colour0, seq_of[order.particles[k]]);
    for (int s : order.colours[1])
      for (int k = order.start[s]; k < order.start[s + 1]; ++k)
        BOOST_TEST(seq_of[order.particles[k]] > last_of_colour0);
    for (const std::vector<int>& bands : order.colours) {
      int previous_owner = 0, largest = 0, total = 0;
      std::vector<int> share(threads, 0);
      for (int s : bands) {
        const int first = order.particles[order.start[s]];
        const int owner = thread_of[first];
        for (int k = order.start[s]; k < order.start[s + 1]; ++k) {
          const int p = order.particles[k];
          BOOST_TEST(thread_of[p] == owner, "band " << s << " on one thread");
          if (k > order.start[s]) BOOST_TEST(seq_of[p] > seq_of[order.particles[k - 1]]);
        }
        BOOST_TEST(owner >= previous_owner, "band " << s << " on " << threads << " threads");
        previous_owner = owner;
        const int count = order.start[s + 1] - order.start[s];
        share[owner] += count;
        largest = std::max(largest, count);
        total += count;
      }
      for (int t = 0; t < threads; ++t)
        BOOST_TEST(std::abs(share[t] - total / threads) <= largest + 1,
                   "thread " << t << " of " << threads << ": " << share[t] << " of " << total);
    }
  }
}
