// The node coordinates of one grid axis when its cells are not all equal: a graded (tartan) grid
// (NairnMPM's tartan grids; issue 56). Inside a region of interest the cells are the base size
// over a factor F; outside they grow geometrically by g per cell until they reach the base size.
// A uniform axis is the special case F = 1, and the solver keeps its own uniform path for it
// (bit-identical results; a graded grid is opt-in).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace impact::mpm {

/// A refined span of one axis: [lower, upper] in m, cells there `factor` times finer than the
/// base, and the growth ratio per cell outside it until the base size is reached.
struct RefinedSpan {
  double lower = 0.0, upper = 0.0;
  double factor = 1.0;  ///< >= 1
  double growth = 1.2;  ///< > 1
};

/// Node coordinates x_0 < x_1 < ... < x_cells of one axis [m], with one ghost node beyond each
/// end at the edge cell's size (the ghost layer the uGIMP stencil reaches next to a face).
class GradedAxis {
 public:
  GradedAxis() = default;
  /// From explicit node coordinates (strictly increasing, at least two).
  explicit GradedAxis(std::vector<double> nodes);

  int cells() const { return static_cast<int>(x_.size()) - 1; }
  /// Node i; beyond the ends (the ghost layer, i = -1 or cells() + 1, and one more for the
  /// hats there) the edge cells' sizes repeat.
  double node(int i) const {
    if (i < 0) return x_.front() + i * (x_[1] - x_[0]);
    if (i > cells()) return x_.back() + (i - cells()) * (x_.back() - x_[x_.size() - 2]);
    return x_[static_cast<std::size_t>(i)];
  }
  /// The size of cell i (between nodes i and i + 1) [m].
  double size(int i) const { return node(i + 1) - node(i); }
  /// The cell holding coordinate x, clamped to [0, cells() - 1] (the upper face belongs to the
  /// last cell, as on a uniform grid).
  int cell_of(double x) const;
  double smallest() const { return smallest_; }
  double largest() const { return largest_; }
  const std::vector<double>& nodes() const { return x_; }

 private:
  std::vector<double> x_;
  double smallest_ = 0.0, largest_ = 0.0;  ///< cell sizes, found once
};

/// The axis [lower, upper] of `base_cells` base cells (size h0 = (upper - lower) / base_cells),
/// refined inside `span` (clipped to the axis, then widened to the nearest base nodes outside
/// it): there round((upper - lower of the span) / (h0 / F)) equal cells, at least one; outside, on
/// each side, the fewest cells that grow from the refined size by at most `growth` per cell, stop
/// growing at h0 and fill the side exactly (their common ratio lowered to fit). A span with factor
/// 1 gives the uniform axis, lower + i h0.
GradedAxis graded_axis(double lower, double upper, int base_cells, const RefinedSpan& span);

/// The axis refined in several spans (grid.refine as a list of boxes). Each span is widened to
/// the base nodes as above; spans that then overlap or touch (by node index) merge into one, with
/// the finest factor and the slowest growth of them. One span left: the axis above, node for
/// node. Between two spans the cells grow from both, the smaller next cell first, so that no
/// neighbour ratio exceeds a growth and no cell exceeds h0; the fewest that reach across are then
/// capped together to fill the gap exactly.
GradedAxis graded_axis(double lower, double upper, int base_cells,
                       const std::vector<RefinedSpan>& spans);

/// What a span's refined cells come to on the axis above: the base cells it covers once widened
/// to the base nodes, and the equal cells it gets there, round(base x factor), at least one (a
/// factor that does not divide the base cells into whole cells is rounded: 2.5 on one base cell
/// gives 3 cells of h0 / 3). None when the span refines nothing.
struct SpanCells {
  long base = 0;
  int refined = 0;
};
std::optional<SpanCells> span_cells(double lower, double upper, int base_cells,
                                    const RefinedSpan& span);

}  // namespace impact::mpm
