#include "mpm/scene/graded_axis.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
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

namespace {

// A span widened to the base grid's nodes: its cells are then exactly h0 / F for a whole F, and no
// side is left shorter than a cell (a sliver there set the time step: an axisymmetric Taylor
// rod's box ending 0.06 mm short of the grid's 8.86 mm took 5 times the steps).
struct Widened {
  double a = 0.0, b = 0.0;
  long ia = 0, ib = 0;  ///< the base nodes a and b are (spans merge by these, not by a and b)
  double factor = 1.0, growth = 1.2;
};

std::optional<Widened> widened(double lower, double upper, int base_cells,
                               const RefinedSpan& span) {
  const double h0 = (upper - lower) / base_cells;
  // A grid or a box the reader refused (a missing bound is NaN) has no span: the reader's
  // problems name it, and NaN must not reach the index conversions below (undefined behaviour;
  // a fuzzed scene without its base file's grid hit it).
  if (!(std::isfinite(h0) && h0 > 0.0 && std::isfinite(span.lower) && std::isfinite(span.upper)))
    return std::nullopt;
  // The node's coordinate and its index.
  const auto base_node = [&](double x, bool up) -> std::pair<double, long> {
    const double c = (x - lower) / h0;
    if (std::abs(c - std::round(c)) <= 1e-9) {  // on a node already: as given, or the face
      const long i = std::lround(c);            // (1e-12 off the face: no 1e-12 m cell)
      if (i <= 0) return {lower, 0};
      if (i >= base_cells) return {upper, base_cells};
      return {x, i};
    }
    const long i = std::clamp(static_cast<long>(up ? std::ceil(c) : std::floor(c)), 0L,
                              static_cast<long>(base_cells));
    return {std::clamp(lower + static_cast<double>(i) * h0, lower, upper), i};
  };
  const auto [a, ia] = base_node(std::clamp(span.lower, lower, upper), false);
  const auto [b, ib] = base_node(std::clamp(span.upper, lower, upper), true);
  if (!(span.factor > 1.0) || !(b > a)) return std::nullopt;
  return Widened{a, b, ia, ib, span.factor, span.growth};
}

GradedAxis uniform_axis(double lower, double upper, int base_cells) {
  const double h0 = (upper - lower) / base_cells;
  std::vector<double> x;  // the solver's own nodes lower + i h
  for (int i = 0; i <= base_cells; ++i) x.push_back(lower + i * h0);
  return GradedAxis(std::move(x));
}

// The refined cells of a span: round((b - a) / (h0 / F)) equal cells, at least one.
int refined_cells(const Widened& w, double h0) {
  return std::max(1, static_cast<int>(std::lround((w.b - w.a) / (h0 / w.factor))));
}

// The m smallest of the sizes two sides offer, each growing from its span's cell (hl, hr) by its
// growth and capped at c, nearest first on each side: the smaller next cell is taken first, so
// the two cells that meet differ by at most a growth (each side's next cell is no smaller than
// the other's last). `last_left`: the last cell taken, the largest, is the left side's.
struct GapCells {
  std::vector<double> left, right;
  bool last_left = true;
};
GapCells smallest_cells(int m, double hl, double gl, double hr, double gr, double c) {
  GapCells f;
  double xl = hl, xr = hr;
  for (int k = 0; k < m; ++k) {
    const double nl = std::min(xl * gl, c), nr = std::min(xr * gr, c);
    f.last_left = nl <= nr;
    if (f.last_left) {
      f.left.push_back(xl = nl);
    } else {
      f.right.push_back(xr = nr);
    }
  }
  return f;
}

// The cells of a gap of length L between two refined spans (cells hl below, hr above): the fewest
// m that reach L growing from both ends, at most h0 each (smallest_cells with c = h0); then the
// cap c lowered, by bisection, until those m cells fill L exactly (their sum grows with c). The
// ratios stay within the growths everywhere, where the sides meet too, and no cell is smaller
// than the two spans' cells. A gap too short to grade at all (m cells capped at the larger span
// cell already overfill it) gets m equal cells.
GapCells gap_cells(double L, double hl, double gl, double hr, double gr, double h0) {
  int m = 0;
  for (double xl = hl, xr = hr, t = 0.0; t < L; ++m) {
    const double nl = std::min(xl * gl, h0), nr = std::min(xr * gr, h0);
    t += nl <= nr ? (xl = nl) : (xr = nr);
  }
  const auto total = [](const GapCells& f) {
    double t = 0.0;
    for (const double x : f.left) t += x;
    for (const double x : f.right) t += x;
    return t;
  };
  double lo = std::max(hl, hr), hi = h0;
  if (total(smallest_cells(m, hl, gl, hr, gr, lo)) >= L) {
    GapCells f = smallest_cells(m, hl, gl, hr, gr, lo);
    const double each = L / m;
    for (double& x : f.left) x = each;
    for (double& x : f.right) x = each;
    return f;
  }
  for (int it = 0; it < 100; ++it) {
    const double c = 0.5 * (lo + hi);
    (total(smallest_cells(m, hl, gl, hr, gr, c)) < L ? lo : hi) = c;
  }
  GapCells f = smallest_cells(m, hl, gl, hr, gr, hi);
  // The bisection's last bits onto the last cell taken, the largest.
  (f.last_left ? f.left.back() : f.right.back()) += L - total(f);
  return f;
}

}  // namespace

GradedAxis graded_axis(double lower, double upper, int base_cells, const RefinedSpan& span) {
  const double h0 = (upper - lower) / base_cells;
  const std::optional<Widened> w = widened(lower, upper, base_cells, span);
  if (!w) return uniform_axis(lower, upper, base_cells);
  const double a = w->a, b = w->b;
  const int inner = refined_cells(*w, h0);
  const double hf = (b - a) / inner;
  const std::vector<double> below = growing_cells(a - lower, hf, h0, span.growth);
  const std::vector<double> above = growing_cells(upper - b, hf, h0, span.growth);
  // Nodes from the lower end: the side below outermost cell first.
  std::vector<double> x;
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

GradedAxis graded_axis(double lower, double upper, int base_cells,
                       const std::vector<RefinedSpan>& spans) {
  std::vector<Widened> ws;
  for (const RefinedSpan& s : spans)
    if (const std::optional<Widened> w = widened(lower, upper, base_cells, s)) ws.push_back(*w);
  std::sort(ws.begin(), ws.end(), [](const Widened& p, const Widened& q) { return p.ia < q.ia; });
  // Overlapping or touching spans merge: the finest factor, the slowest growth.
  std::vector<Widened> merged;
  for (const Widened& w : ws) {
    if (!merged.empty() && w.ia <= merged.back().ib) {  // by node index: no ulp-wide gap
      Widened& m = merged.back();
      if (w.ib > m.ib) {
        m.b = w.b;
        m.ib = w.ib;
      }
      m.factor = std::max(m.factor, w.factor);
      m.growth = std::min(m.growth, w.growth);
      continue;
    }
    merged.push_back(w);
  }
  if (merged.empty()) return uniform_axis(lower, upper, base_cells);
  if (merged.size() == 1) {  // the one-span axis, node for node
    const Widened& m = merged.front();
    return graded_axis(lower, upper, base_cells, RefinedSpan{m.a, m.b, m.factor, m.growth});
  }
  const double h0 = (upper - lower) / base_cells;
  std::vector<double> x{lower};
  double at = lower;
  for (std::size_t k = 0; k < merged.size(); ++k) {
    const Widened& m = merged[k];
    const int inner = refined_cells(m, h0);
    const double hf = (m.b - m.a) / inner;
    if (k == 0) {  // the side below the first span, outermost cell first
      const std::vector<double> below = growing_cells(m.a - lower, hf, h0, m.growth);
      for (auto c = below.rbegin(); c != below.rend(); ++c) x.push_back(at += *c);
    }
    x.back() = m.a;  // the span's edge exactly, not a sum's round-off
    for (int i = 1; i <= inner; ++i) x.push_back(m.a + (m.b - m.a) * i / inner);
    at = m.b;
    if (k + 1 < merged.size()) {  // the gap to the next span, growing from both ends
      const Widened& n = merged[k + 1];
      const double hn = (n.b - n.a) / refined_cells(n, h0);
      const GapCells gap = gap_cells(n.a - m.b, hf, m.growth, hn, n.growth, h0);
      for (const double c : gap.left) x.push_back(at += c);
      for (auto c = gap.right.rbegin(); c != gap.right.rend(); ++c) x.push_back(at += *c);
    } else {
      for (const double c : growing_cells(upper - m.b, hf, h0, m.growth)) x.push_back(at += c);
      x.back() = upper;
    }
  }
  return GradedAxis(std::move(x));
}

std::optional<SpanCells> span_cells(double lower, double upper, int base_cells,
                                    const RefinedSpan& span) {
  const std::optional<Widened> w = widened(lower, upper, base_cells, span);
  if (!w) return std::nullopt;
  return SpanCells{w->ib - w->ia, refined_cells(*w, (upper - lower) / base_cells)};
}

}  // namespace impact::mpm
