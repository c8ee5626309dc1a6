#include "mpm/parallel/split_search.hpp"

#include <algorithm>
#include <limits>

namespace impact::mpm {

SplitLoads::SplitLoads(const std::array<int, 3>& cells, const AxisCounts& counts, int ranks)
    : cells_(cells),
      ranks_(ranks),
      splits_(BoxDecomposition::splits(cells, ranks)),
      x_end_(std::size_t(cells[0])),
      y_end_(x_end_ + std::size_t(cells[1])),
      cells_total_(y_end_ + std::size_t(cells[2])) {
  if (splits_.empty()) BoxDecomposition::ranks_per_axis(cells, ranks);  // throws its message
  rank_part_.reserve(splits_.size() * cells_total_);
  for (const std::array<int, 3>& p : splits_) {
    const BoxDecomposition boxes = BoxDecomposition::balanced(counts, p);
    const int stride[3] = {p[1] * p[2], p[2], 1};
    for (int d = 0; d < 3; ++d)
      for (int c = 0; c < cells[std::size_t(d)]; ++c)
        rank_part_.push_back(boxes.axis(d).owner_of_cell(c) * stride[d]);
  }
  loads_.assign(splits_.size() * std::size_t(ranks), 0.0);
}

SplitLoads::Choice SplitLoads::least_loaded() const {
  Choice best{{0, 0, 0}, std::numeric_limits<double>::infinity()};
  double best_cut = best.busiest;
  for (std::size_t s = 0; s < splits_.size(); ++s) {
    const auto first = loads_.begin() + std::ptrdiff_t(s * std::size_t(ranks_));
    const double busiest = *std::max_element(first, first + ranks_);
    const double cut = BoxDecomposition::cut_faces(cells_, splits_[s]);
    if (busiest < best.busiest || (busiest == best.busiest && cut < best_cut)) {
      best = {splits_[s], busiest};
      best_cut = cut;
    }
  }
  return best;
}

}  // namespace impact::mpm
