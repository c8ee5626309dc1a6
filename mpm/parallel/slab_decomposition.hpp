// The grid split across ranks (docs/mpi.md): rank r owns the cells [first_cell(r),
// first_cell(r + 1)) along x, the slab whose particles it keeps and whose nodes it books. A
// particle's stencil reaches from the node below its cell to two nodes above it (uGIMP), so the
// particles of neighbouring slabs share 4 node planes; a slab at least kMinCells wide keeps every
// node shared by at most two ranks, whose sums (a + b = b + a) are then the same bits on both.
// Slabs are balanced by particle count: the boundaries cut the cumulative count of particles per
// cell column into equal parts.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace impact::mpm {

class SlabDecomposition {
 public:
  /// Narrowest slab [cells].
  static constexpr int kMinCells = 4;

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
