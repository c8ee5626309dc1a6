#include "mpm/parallel/slab_decomposition.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace impact::mpm {

SlabDecomposition SlabDecomposition::balanced(const std::vector<std::size_t>& counts, int ranks) {
  const int cells = static_cast<int>(counts.size());
  if (ranks < 1) throw std::invalid_argument("SlabDecomposition: ranks must be >= 1");
  if (ranks > 1 && cells < kMinCells * ranks) {  // one slab: the whole axis, however narrow
    std::ostringstream m;
    m << cells << " grid cells along one axis cannot be split into " << ranks
      << " slabs of at least " << kMinCells << " cells (the decomposition needs at least "
      << kMinCells * ranks << " cells along it; use fewer ranks or a finer grid)";
    throw std::invalid_argument(m.str());
  }
  double total = 0.0;
  for (std::size_t c : counts) total += static_cast<double>(c);
  std::vector<int> first(static_cast<std::size_t>(ranks) + 1, 0);
  first.back() = cells;
  // Each boundary where the cumulative count reaches r / ranks of the total (before or after the
  // cell that crosses it, whichever lands nearer), then kept at least kMinCells from the previous
  // boundary and from the cells the later slabs need.
  double cumulative = 0.0;
  int cell = 0;
  for (int r = 1; r < ranks; ++r) {
    const double target = total * r / ranks;
    while (cell < cells && cumulative < target) {
      cumulative += static_cast<double>(counts[std::size_t(cell)]);
      ++cell;
    }
    const double before =
        cell > 0 ? cumulative - static_cast<double>(counts[std::size_t(cell - 1)]) : cumulative;
    const int nearest = cumulative - target > target - before ? cell - 1 : cell;
    const int lowest = first[std::size_t(r) - 1] + kMinCells;
    const int highest = cells - kMinCells * (ranks - r);
    first[std::size_t(r)] = std::clamp(nearest, lowest, highest);
    // Continue from the boundary as placed.
    cell = first[std::size_t(r)];
    cumulative = 0.0;
    for (int c = 0; c < cell; ++c) cumulative += static_cast<double>(counts[std::size_t(c)]);
  }
  return SlabDecomposition(std::move(first));
}

int SlabDecomposition::owner_of_cell(int i) const {
  // The last boundary not above i.
  const auto it = std::upper_bound(first_.begin() + 1, first_.end() - 1, i);
  return static_cast<int>(it - first_.begin()) - 1;
}

double SlabDecomposition::imbalance(const std::vector<std::size_t>& counts) const {
  double total = 0.0, largest = 0.0;
  for (int r = 0; r < ranks(); ++r) {
    double n = 0.0;
    for (int c = first_cell(r); c < first_cell(r + 1); ++c)
      n += static_cast<double>(counts[std::size_t(c)]);
    total += n;
    largest = std::max(largest, n);
  }
  return total > 0.0 ? largest / (total / ranks()) : 1.0;
}

std::string SlabDecomposition::describe() const {
  std::ostringstream m;
  for (int r = 0; r < ranks(); ++r)
    m << (r ? " " : "") << '[' << first_cell(r) << ", " << first_cell(r + 1) << ')';
  return m.str();
}

}  // namespace impact::mpm
