// The grid split across ranks in boxes (docs/mpi.md): each axis d is cut into p_d slabs
// (SlabDecomposition, balanced by the particle counts per cell along that axis), and the box of
// rank r = (a p_1 + b) p_2 + c is slab a along x, slab b along y and slab c along z. The boxes
// form a rectilinear grid: two boxes that touch across a face share their extent along the other
// two axes, so the node sums can run one axis after another (halo_exchange.hpp) and a node near
// an edge or a corner still receives every rank's part. Slabs (p = ranks x 1 x 1) are the special
// case: the ranks per axis are chosen to cut the fewest node faces (ranks_per_axis).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mpm/parallel/slab_decomposition.hpp"

namespace impact::mpm {

/// Particles per cell along each axis (the projections of the particle count).
using AxisCounts = std::array<std::vector<std::size_t>, 3>;

class BoxDecomposition {
 public:
  /// One box of `cells`.
  explicit BoxDecomposition(const std::array<int, 3>& cells = {1, 1, 1})
      : axes_{SlabDecomposition(cells[0]), SlabDecomposition(cells[1]),
              SlabDecomposition(cells[2])} {}
  explicit BoxDecomposition(std::array<SlabDecomposition, 3> axes) : axes_(std::move(axes)) {}

  /// The ranks per axis (p_x, p_y, p_z), product `ranks`, that cut the fewest node faces of the
  /// whole grid, sum_d (p_d - 1) N_e N_f (N the nodes per axis), among those leaving every box at
  /// least SlabDecomposition::kMinCells wide along each axis it splits; ties go to more cuts
  /// along x, then y. Throws std::invalid_argument when no split fits.
  static std::array<int, 3> ranks_per_axis(const std::array<int, 3>& cells, int ranks);
  /// Every split of `ranks` into ranks per axis that leaves each split axis at least kMinCells
  /// cells per box, more cuts along x first, then along y.
  static std::vector<std::array<int, 3>> splits(const std::array<int, 3>& cells, int ranks);
  /// The node faces a split cuts across the whole grid, sum_d (p_d - 1) N_e N_f.
  static double cut_faces(const std::array<int, 3>& cells, const std::array<int, 3>& per_axis);
  /// Each axis d cut into per_axis[d] slabs balanced by counts[d]; throws std::invalid_argument
  /// when an axis has fewer than kMinCells cells per slab.
  static BoxDecomposition balanced(const AxisCounts& counts, const std::array<int, 3>& per_axis);

  int ranks() const { return axes_[0].ranks() * axes_[1].ranks() * axes_[2].ranks(); }
  /// The slabs along axis d.
  const SlabDecomposition& axis(int d) const { return axes_[std::size_t(d)]; }
  std::array<int, 3> ranks_per_axis() const {
    return {axes_[0].ranks(), axes_[1].ranks(), axes_[2].ranks()};
  }
  /// The box's slab index along each axis.
  std::array<int, 3> coordinates(int rank) const;
  int rank_at(const std::array<int, 3>& coordinates) const;
  /// Rank r's cells [first(r)_d, end(r)_d) per axis.
  std::array<int, 3> first_cell(int rank) const;
  std::array<int, 3> end_cell(int rank) const;
  /// The rank owning cell (i, j, k) (cells outside the grid belong to the boxes at its faces).
  int owner_of_cell(const std::array<int, 3>& cell) const;

  /// "x [0, 12) [12, 25); y [0, 30); z [0, 30)" for messages.
  std::string describe() const;

  bool operator==(const BoxDecomposition&) const = default;

 private:
  std::array<SlabDecomposition, 3> axes_;
};

}  // namespace impact::mpm
