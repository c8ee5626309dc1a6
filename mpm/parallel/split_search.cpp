#include "mpm/parallel/split_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::mpm {

namespace {

// The counts per cell along axis d and per box column m = b p_f + c of the other two axes e < f.
struct AxisTable {
  int cells;
  int columns;
  std::vector<double> count;  // [i * columns + m]
  double at(int i, int m) const {
    return count[std::size_t(i) * std::size_t(columns) + std::size_t(m)];
  }
};

AxisTable axis_table(const BoxDecomposition& boxes, int d, const std::vector<CellCount>& counted,
                     const TableSum& sum) {
  const int e = d == 0 ? 1 : 0, f = d == 2 ? 1 : 2;
  const SlabDecomposition &along = boxes.axis(d), &ae = boxes.axis(e), &af = boxes.axis(f);
  AxisTable t{along.cells(), ae.ranks() * af.ranks(), {}};
  t.count.assign(std::size_t(t.cells) * std::size_t(t.columns), 0.0);
  for (const CellCount& c : counted) {
    const int m = ae.owner_of_cell(c.cell[std::size_t(e)]) * af.ranks() +
                  af.owner_of_cell(c.cell[std::size_t(f)]);
    t.count[std::size_t(c.cell[std::size_t(d)]) * std::size_t(t.columns) + std::size_t(m)] +=
        c.count;
  }
  t.count = sum(t.count);
  return t;
}

// The busiest box of the slabs `first` along the table's axis.
double busiest_of(const AxisTable& t, const std::vector<int>& first) {
  double busiest = 0.0;
  std::vector<double> load(std::size_t(t.columns));
  for (std::size_t a = 0; a + 1 < first.size(); ++a) {
    std::fill(load.begin(), load.end(), 0.0);
    for (int i = first[a]; i < first[a + 1]; ++i)
      for (int m = 0; m < t.columns; ++m) load[std::size_t(m)] += t.at(i, m);
    busiest = std::max(busiest, *std::max_element(load.begin(), load.end()));
  }
  return busiest;
}

// Cuts into `slabs` slabs, each at least kMinCells wide, no box above `bound`; false when none
// exists. Exact: end(i), the furthest a slab starting at cell i may reach within the bound, grows
// with i (two pointers); the boundaries the first a slabs can reach are then a union of
// intervals, built slab by slab, and the cuts are read back from the last boundary (the grid's
// end) down, each the largest reachable start that reaches the boundary above it.
bool cuts_within(const AxisTable& t, int slabs, double bound, std::vector<int>& first) {
  const int n = t.cells, k = SlabDecomposition::kMinCells;
  std::vector<int> end(std::size_t(n) + 1, n);
  std::vector<double> load(std::size_t(t.columns), 0.0);
  for (int i = 0, j = 0; i <= n; ++i) {
    if (j < i) j = i;  // (the load is then empty)
    for (; j < n; ++j) {
      bool fits = true;
      for (int m = 0; m < t.columns && fits; ++m) fits = load[std::size_t(m)] + t.at(j, m) <= bound;
      if (!fits) break;
      for (int m = 0; m < t.columns; ++m) load[std::size_t(m)] += t.at(j, m);
    }
    end[std::size_t(i)] = j;
    if (i < j)  // cell i leaves the window
      for (int m = 0; m < t.columns; ++m) load[std::size_t(m)] -= t.at(i, m);
    else
      std::fill(load.begin(), load.end(), 0.0);
  }
  // reach[a][b]: a boundary b is reachable by the first a slabs.
  std::vector<std::vector<char>> reach(std::size_t(slabs) + 1,
                                       std::vector<char>(std::size_t(n) + 1, 0));
  reach[0][0] = 1;
  for (int a = 0; a < slabs; ++a) {
    std::vector<int> opened(std::size_t(n) + 2, 0);
    for (int i = 0; i <= n; ++i)
      if (reach[std::size_t(a)][std::size_t(i)] && i + k <= end[std::size_t(i)]) {
        ++opened[std::size_t(i + k)];
        --opened[std::size_t(end[std::size_t(i)]) + 1];
      }
    for (int b = 0, open = 0; b <= n; ++b) {
      open += opened[std::size_t(b)];
      reach[std::size_t(a) + 1][std::size_t(b)] = open > 0;
    }
  }
  if (!reach[std::size_t(slabs)][std::size_t(n)]) return false;
  first.assign(std::size_t(slabs) + 1, 0);
  first.back() = n;
  for (int a = slabs - 1; a > 0; --a) {
    const int above = first[std::size_t(a) + 1];
    int i = above - k;
    while (!(reach[std::size_t(a)][std::size_t(i)] && end[std::size_t(i)] >= above)) --i;
    first[std::size_t(a)] = i;
  }
  return true;
}

}  // namespace

BoxDecomposition refine_boundaries(const BoxDecomposition& start,
                                   const std::vector<CellCount>& counted, const TableSum& sum,
                                   double* busiest) {
  std::array<SlabDecomposition, 3> axes{start.axis(0), start.axis(1), start.axis(2)};
  double current = std::numeric_limits<double>::infinity();
  constexpr int kMaxSweeps = 8;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool moved = false;
    for (int d = 0; d < 3; ++d) {
      const BoxDecomposition boxes(axes);
      const AxisTable t = axis_table(boxes, d, counted, sum);
      current = busiest_of(t, axes[std::size_t(d)].first_cells());
      const int slabs = axes[std::size_t(d)].ranks();
      if (slabs == 1) continue;
      // Counts are integers: bisect on the integer bound between 0 (infeasible unless empty)
      // and the current busiest box (feasible: the current cuts).
      double lo = 0.0, hi = current;
      std::vector<int> first;
      while (hi - lo > 0.5) {
        const double mid = std::floor(0.5 * (lo + hi));
        if (cuts_within(t, slabs, mid, first))
          hi = mid;
        else
          lo = mid + 1.0;
      }
      if (hi < current && cuts_within(t, slabs, hi, first)) {
        axes[std::size_t(d)] = SlabDecomposition(first);
        current = hi;
        moved = true;
      }
    }
    if (!moved) break;
  }
  if (busiest) *busiest = current;
  return BoxDecomposition(axes);
}

SplitChoice least_loaded_split(const std::array<int, 3>& cells, const AxisCounts& counts, int ranks,
                               const std::vector<CellCount>& counted, const TableSum& sum) {
  const std::vector<std::array<int, 3>> splits = BoxDecomposition::splits(cells, ranks);
  if (splits.empty()) BoxDecomposition::ranks_per_axis(cells, ranks);  // throws its message
  SplitChoice best{BoxDecomposition(cells), std::numeric_limits<double>::infinity(), splits.size()};
  double best_cut = best.busiest;
  for (const std::array<int, 3>& p : splits) {
    double busiest = 0.0;
    BoxDecomposition boxes =
        refine_boundaries(BoxDecomposition::balanced(counts, p), counted, sum, &busiest);
    const double cut = BoxDecomposition::cut_faces(cells, p);
    if (busiest < best.busiest || (busiest == best.busiest && cut < best_cut)) {
      best.boxes = std::move(boxes);
      best.busiest = busiest;
      best_cut = cut;
    }
  }
  return best;
}

}  // namespace impact::mpm
