#include "mpm/parallel/box_decomposition.hpp"

#include <limits>
#include <sstream>
#include <stdexcept>

namespace impact::mpm {

std::vector<std::array<int, 3>> BoxDecomposition::splits(const std::array<int, 3>& cells,
                                                         int ranks) {
  std::vector<std::array<int, 3>> out;
  for (int px = ranks; px >= 1; --px) {
    if (ranks % px != 0) continue;
    for (int py = ranks / px; py >= 1; --py) {
      if ((ranks / px) % py != 0) continue;
      const std::array<int, 3> p{px, py, ranks / px / py};
      bool fits = true;
      for (std::size_t d = 0; d < 3; ++d)
        fits = fits && (p[d] == 1 || cells[d] >= SlabDecomposition::kMinCells * p[d]);
      if (fits) out.push_back(p);
    }
  }
  return out;
}

double BoxDecomposition::cut_faces(const std::array<int, 3>& cells, const std::array<int, 3>& p) {
  const double n[3] = {cells[0] + 1.0, cells[1] + 1.0, cells[2] + 1.0};
  return (p[0] - 1) * n[1] * n[2] + (p[1] - 1) * n[0] * n[2] + (p[2] - 1) * n[0] * n[1];
}

std::array<int, 3> BoxDecomposition::ranks_per_axis(const std::array<int, 3>& cells, int ranks) {
  if (ranks < 1) throw std::invalid_argument("BoxDecomposition: ranks must be >= 1");
  std::array<int, 3> best{0, 0, 0};
  double fewest = std::numeric_limits<double>::infinity();
  for (const std::array<int, 3>& p : splits(cells, ranks)) {  // a tie keeps the first found
    const double cut = cut_faces(cells, p);
    if (cut < fewest) {
      fewest = cut;
      best = p;
    }
  }
  if (best[0] == 0) {
    std::ostringstream m;
    m << "a grid of " << cells[0] << " x " << cells[1] << " x " << cells[2]
      << " cells cannot be split into " << ranks << " boxes of at least "
      << SlabDecomposition::kMinCells
      << " cells per axis (use fewer ranks, a rank count with other factors, or a finer grid)";
    throw std::invalid_argument(m.str());
  }
  return best;
}

BoxDecomposition BoxDecomposition::balanced(const AxisCounts& counts,
                                            const std::array<int, 3>& per_axis) {
  for (int a = 0; a < 3; ++a) {  // the axis that is too thin, by name
    const int cells = static_cast<int>(counts[std::size_t(a)].size());
    if (per_axis[std::size_t(a)] > 1 &&
        cells < SlabDecomposition::kMinCells * per_axis[std::size_t(a)]) {
      std::ostringstream m;
      m << cells << " grid cells along "
        << "xyz"[a] << " cannot be split into " << per_axis[std::size_t(a)] << " slabs of at least "
        << SlabDecomposition::kMinCells << " cells (grid.cells[" << a
        << "] >= " << SlabDecomposition::kMinCells * per_axis[std::size_t(a)]
        << " is needed; use fewer ranks or a finer grid)";
      throw std::invalid_argument(m.str());
    }
  }
  return BoxDecomposition({SlabDecomposition::balanced(counts[0], per_axis[0]),
                           SlabDecomposition::balanced(counts[1], per_axis[1]),
                           SlabDecomposition::balanced(counts[2], per_axis[2])});
}

std::array<int, 3> BoxDecomposition::coordinates(int rank) const {
  const int py = axes_[1].ranks(), pz = axes_[2].ranks();
  return {rank / (py * pz), (rank / pz) % py, rank % pz};
}

int BoxDecomposition::rank_at(const std::array<int, 3>& c) const {
  return (c[0] * axes_[1].ranks() + c[1]) * axes_[2].ranks() + c[2];
}

std::array<int, 3> BoxDecomposition::first_cell(int rank) const {
  const std::array<int, 3> c = coordinates(rank);
  return {axes_[0].first_cell(c[0]), axes_[1].first_cell(c[1]), axes_[2].first_cell(c[2])};
}

std::array<int, 3> BoxDecomposition::end_cell(int rank) const {
  const std::array<int, 3> c = coordinates(rank);
  return {axes_[0].first_cell(c[0] + 1), axes_[1].first_cell(c[1] + 1),
          axes_[2].first_cell(c[2] + 1)};
}

int BoxDecomposition::owner_of_cell(const std::array<int, 3>& cell) const {
  return rank_at({axes_[0].owner_of_cell(cell[0]), axes_[1].owner_of_cell(cell[1]),
                  axes_[2].owner_of_cell(cell[2])});
}

std::string BoxDecomposition::describe() const {
  std::ostringstream m;
  const char* names[3] = {"x ", "; y ", "; z "};
  for (int d = 0; d < 3; ++d) m << names[d] << axes_[std::size_t(d)].describe();
  return m.str();
}

}  // namespace impact::mpm
