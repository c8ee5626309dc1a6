// One axis of the grid split across ranks (docs/mpi.md; BoxDecomposition combines three): slab r
// holds the cells [first_cell(r), first_cell(r + 1)) along the axis. The particles of cells
// [c0, c1) reach the nodes [c0 - 1, c1 + 1] (uGIMP), so neighbouring slabs share the 3 node
// layers around their boundary b, [b - 1, b + 1]; a slab at least kMinCells = 3 wide keeps the
// layers it shares below apart from those it shares above, so every node is shared by at most
// two slabs of an axis, whose sums (a + b = b + a) are then the same bits on both. Slabs are
// balanced by particle count: the boundaries cut the cumulative count of particles per cell
// into equal parts.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace impact::mpm {

class SlabDecomposition {
 public:
  /// Narrowest slab [cells].
  static constexpr int kMinCells = 3;

  /// One slab of `cells` cells.
  explicit SlabDecomposition(int cells = 1) : first_{0, cells} {}
  /// Boundaries first_cell(0) = 0 < ... < first_cell(ranks) = cells.
  explicit SlabDecomposition(std::vector<int> first_cells) : first_(std::move(first_cells)) {}

  /// `ranks` slabs of `counts.size()` cells with about equal sums of counts (particles per cell
  /// column along x), each at least kMinCells wide; throws std::invalid_argument when the grid
  /// has fewer than kMinCells cells per rank.
  static SlabDecomposition balanced(const std::vector<std::size_t>& counts, int ranks);

  int ranks() const { return static_cast<int>(first_.size()) - 1; }
  const std::vector<int>& first_cells() const { return first_; }
  int cells() const { return first_.back(); }
  int first_cell(int rank) const { return first_[static_cast<std::size_t>(rank)]; }
  /// The rank owning cell column i (cells below 0 belong to rank 0, beyond the grid to the last).
  int owner_of_cell(int i) const;
  /// The rank owning node plane i (node i is the lower corner of cell i; the last plane and the
  /// ghost planes belong to the end slabs).
  int owner_of_node(int i) const { return owner_of_cell(i); }

  /// The largest slab's count over the mean (1 = perfect balance).
  double imbalance(const std::vector<std::size_t>& counts) const;
  /// "[0, 12) [12, 25) ..." for messages.
  std::string describe() const;

  bool operator==(const SlabDecomposition&) const = default;

 private:
  std::vector<int> first_;
};

}  // namespace impact::mpm
