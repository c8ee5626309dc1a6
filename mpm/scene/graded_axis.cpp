#include "mpm/scene/graded_axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace impact::mpm {

GradedAxis::GradedAxis(std::vector<double> nodes) : x_(std::move(nodes)) {
  if (x_.size() < 2) throw std::invalid_argument("GradedAxis: at least two nodes");
  for (std::size_t i = 1; i < x_.size(); ++i)
    if (!(x_[i] > x_[i - 1])) throw std::invalid_argument("GradedAxis: nodes must increase");
  smallest_ = largest_ = x_[1] - x_[0];
  for (std::size_t i = 2; i < x_.size(); ++i) {
    smallest_ = std::min(smallest_, x_[i] - x_[i - 1]);
    largest_ = std::max(largest_, x_[i] - x_[i - 1]);
  }
}

int GradedAxis::cell_of(double x) const {
  // The last node not above x: upper_bound finds the first node above it.
  const auto above = std::upper_bound(x_.begin(), x_.end(), x);
  const int i = static_cast<int>(above - x_.begin()) - 1;
  return std::clamp(i, 0, cells() - 1);
}

namespace {

// The sizes of cells that fill a side of length L outward from a refined cell of size hf, nearest
// first: the fewest cells m that grow by `growth` per cell (and stop growing at h0) and reach L,
// their ratio then lowered to the r in [1, growth] that fills L exactly (the sum grows with r).
// So the first cell is hf r >= hf, no neighbour ratio exceeds the growth and no cell exceeds h0. A
// side shorter than m refined cells gets m equal cells.
std::vector<double> growing_cells(double L, double hf, double h0, double growth) {
  std::vector<double> s;
  if (!(L > 1e-12 * h0)) return s;
  const auto sizes = [&](double r, int m) {
    std::vector<double> c;
    double h = hf;
    for (int k = 0; k < m; ++k) c.push_back(h = std::min(h * r, h0));
    return c;
  };
  const auto sum = [](const std::vector<double>& c) {
    double t = 0.0;
    for (const double x : c) t += x;
    return t;
  };
  // The fewest cells at the full growth that reach L, summed as they are added (a long side
  // of a fine grid has 1e5 of them: no sum over all of them per candidate).
  int m = 0;
  for (double h = hf, t = 0.0; t < L; ++m) t += (h = std::min(h * growth, h0));
  if (m * hf >= L) return std::vector<double>(std::size_t(m), L / m);
  double lo = 1.0, hi = growth;
  for (int it = 0; it < 100; ++it) {
    const double r = 0.5 * (lo + hi);
    (sum(sizes(r, m)) < L ? lo : hi) = r;
  }
  s = sizes(hi, m);
  s.back() += L - sum(s);  // the bisection's last bits onto the outermost cell
  return s;
}

}  // namespace

GradedAxis graded_axis(double lower, double upper, int base_cells, const RefinedSpan& span) {
  const double h0 = (upper - lower) / base_cells;
  // The span widened to the base grid's nodes: its cells are then exactly h0 / F for a whole F,
  // and no side is left shorter than a cell (a sliver there set the time step: an axisymmetric
  // Taylor rod's box ending 0.06 mm short of the grid's 8.86 mm took 5 times the steps).
  const auto base_node = [&](double x, bool up) {
    const double c = (x - lower) / h0;
    if (std::abs(c - std::round(c)) <= 1e-9) {  // on a node already: as given, or the face
      if (std::round(c) <= 0.0) return lower;   // (1e-12 off the face: no 1e-12 m cell)
      if (std::round(c) >= base_cells) return upper;
      return x;
    }
    const double i = up ? std::ceil(c) : std::floor(c);
    return std::clamp(lower + i * h0, lower, upper);
  };
  const double a = base_node(std::clamp(span.lower, lower, upper), false);
  const double b = base_node(std::clamp(span.upper, lower, upper), true);
  std::vector<double> x;
  if (!(span.factor > 1.0) || !(b > a)) {  // uniform: the solver's own nodes lower + i h
    for (int i = 0; i <= base_cells; ++i) x.push_back(lower + i * h0);
    return GradedAxis(std::move(x));
  }
  const int inner = std::max(1, static_cast<int>(std::lround((b - a) / (h0 / span.factor))));
  const double hf = (b - a) / inner;
  const std::vector<double> below = growing_cells(a - lower, hf, h0, span.growth);
  const std::vector<double> above = growing_cells(upper - b, hf, h0, span.growth);
  // Nodes from the lower end: the side below outermost cell first.
  x.push_back(lower);
  double at = lower;
  for (auto c = below.rbegin(); c != below.rend(); ++c) x.push_back(at += *c);
  if (!below.empty()) x.back() = a;  // the span's edge exactly, not a sum's round-off
  for (int i = 1; i <= inner; ++i) x.push_back(a + (b - a) * i / inner);
  at = b;
  for (const double c : above) x.push_back(at += c);
  x.back() = upper;
  return GradedAxis(std::move(x));
}

}  // namespace impact::mpm
