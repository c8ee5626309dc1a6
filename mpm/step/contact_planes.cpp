// The separating planes of `contact.normal = "logistic_regression"` (contact/separating_plane.hpp,
// Nairn, Hammerquist & Smith 2020): after particles to grid, at every node where exactly two
// bodies have mass, a plane is fitted by logistic regression to the two bodies' particles near it,
// and its unit normal is stored for contact (Grid::contact_plane); with `contact.detection =
// "separation"` the bodies' gap along it too (Grid::contact_gap; at a node of three or more bodies,
// which gets no plane, pair by pair: 3b below). The cloud is wider than the
// node's own support: the particles that weigh on the node or on any neighbouring two-body node
// (S_Ip > 0, the step's stencils), weighted by a tent of kPlaneReach cells about the node. The
// node's own support alone (1 + l_p cells) sees a few particle layers of a surface that is not
// grid-aligned, whose seeded staircase tilted the planes node by node by up to 20 degrees; a
// pressed interface whose nodes hold different normals holds every direction, and a block on a
// 20-degree ramp of another body did not slide at all (0.008 m/s against 1.71 m/s in 50 us; 1.35
// m/s with the wider cloud, 1.705 on the same ramp turned grid-aligned;
// tests/mpm/verification/contact_friction_test.cpp). Each cloud is sorted by particle (its seed
// id), so the fit is the same bits on any thread count. On several ranks a node near a box
// boundary has particles of the neighbouring ranks in its cloud: before the fit every rank sends
// the others its particles within kPlaneGhostCells cells of their boxes (position, seed id, object
// and field: the ghosts), and fits every node its own particles weigh on, the cells [c0, c1) of its
// box widened by one node layer, from its particles and the ghosts. A node two ranks both fit has
// the same cloud, in the same order, on both: the same plane, the same contact, as on one rank.
#include <omp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <utility>

#include "mpm/contact/separating_plane.hpp"
#include "mpm/grid/mirror_view.hpp"
#include "mpm/parallel/box_decomposition.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/parallel/slab_decomposition.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

// Another rank's particle, as a cloud needs it (named: a member of the fit's lambdas).
struct PlaneGhost {
  Vec3 x;
  /// Its uGIMP half-widths on a graded grid [m] (Particles::half_width, fixed at seeding): the
  /// owner's stencil, not that of the cell the ghost is in now (zero on a uniform grid).
  Vec3 half_width;
  std::uint64_t id;
  std::uint16_t object;
  std::uint16_t field;
};

// The ghosts and, for the bodies' gap (`detection: separation`), their deformation gradients
// (sent only then: 72 more bytes a ghost).
struct Ghosts {
  std::vector<PlaneGhost> ghost;
  std::vector<Mat3> F;  ///< empty without gaps
};

namespace {

// The half-width of the tent that weighs a node's cloud [cells]: a neighbour's uGIMP support ends
// 1 + l_p (<= 1.5) cells beyond it, so the cloud reaches about 2.25 cells.
constexpr double kPlaneReach = 2.25;

// The ghosts a rank receives: the other ranks' particles in the cells [c0 - kPlaneGhostCells, c1 +
// kPlaneGhostCells) of its box. A node it fits lies within one node layer of its cells, and the
// cloud's tent reaches kPlaneReach = 2.25 cells beyond that node: 3.25 cells beyond the box, in
// its fourth cell.
constexpr int kPlaneGhostCells = 4;
static_assert(kPlaneGhostCells > kPlaneReach + 1.0);
// The neighbours of a fitted node (one layer further) must be stored: their two-body status comes
// from the node sums and the contact layer copied beyond them (halo_exchange.hpp).
static_assert(kHaloPlanes >= 2);

Ghosts exchange_ghosts(const Particles& P, const Grid& G, const HaloExchange& halo, bool gaps) {
  const Communicator& comm = halo.comm();
  const BoxDecomposition& boxes = halo.boxes();
  const GridSpec& grid = G.spec();
  std::vector<std::vector<char>> to(static_cast<std::size_t>(comm.size()));
  const std::size_t record = sizeof(PlaneGhost) + (gaps ? sizeof(Mat3) : 0);
  // Per particle, the boxes whose cells widened by kPlaneGhostCells hold its cell: along each
  // axis the slabs within reach (one or two, a few where slabs are thin), then their product.
  std::array<std::vector<int>, 3> slabs;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (!(P.mass[p] > 0.0)) continue;
    const std::array<int, 3> c = grid.cell_of(P.x[p]);
    for (int d = 0; d < 3; ++d) {
      const SlabDecomposition& axis = boxes.axis(d);
      slabs[d].clear();
      for (int a = 0; a < axis.ranks(); ++a)
        if (c[d] >= axis.first_cell(a) - kPlaneGhostCells &&
            c[d] < axis.first_cell(a + 1) + kPlaneGhostCells)
          slabs[d].push_back(a);
    }
    PlaneGhost g;
    std::memset(static_cast<void*>(&g), 0, sizeof g);  // no stray padding bytes on the wire
    g.x = P.x[p];
    g.half_width = P.half_width.empty() ? Vec3::Zero() : P.half_width[p];
    g.id = seed_index(P, std::size_t(p));
    g.object = P.object[p];
    g.field = P.field[p];
    for (const int a : slabs[0])
      for (const int b : slabs[1])
        for (const int k : slabs[2]) {
          const int r = boxes.rank_at({a, b, k});
          if (r == comm.rank()) continue;
          std::vector<char>& bytes = to[static_cast<std::size_t>(r)];
          const std::size_t at = bytes.size();
          bytes.resize(at + record);
          std::memcpy(bytes.data() + at, &g, sizeof(PlaneGhost));
          if (gaps)
            std::memcpy(bytes.data() + at + sizeof(PlaneGhost), &P.state[p].F, sizeof(Mat3));
        }
  }
  Ghosts ghosts;
  for (const std::vector<char>& bytes : comm.all_to_all(to)) {
    const std::size_t n = bytes.size() / record;
    const std::size_t at = ghosts.ghost.size();
    ghosts.ghost.resize(at + n);
    if (gaps) ghosts.F.resize(at + n);
    for (std::size_t i = 0; i < n; ++i) {
      std::memcpy(static_cast<void*>(&ghosts.ghost[at + i]), bytes.data() + i * record,
                  sizeof(PlaneGhost));
      if (gaps)
        std::memcpy(static_cast<void*>(&ghosts.F[at + i]),
                    bytes.data() + i * record + sizeof(PlaneGhost), sizeof(Mat3));
    }
  }
  return ghosts;
}

}  // namespace

// Long on purpose (about 190 lines): its stages 0-3 below share the pair nodes' lists, which
// each stage fills for the next in one pass per step.
template <class Shape>
void fit_contact_planes(const Particles& P, Grid& G, const Shape& shape, const Stencils<Shape>& S,
                        const HaloExchange* halo, bool gaps) {
  constexpr int N = Shape::N, NZ = Shape::NZ;
  const int nn = G.node_count();
  const int nf = G.fields();
  const int threads = G.threads();
  if (G.contact_plane.size() != static_cast<std::size_t>(nn)) {
    G.contact_plane.assign(nn, Vec3::Zero());
    G.contact_plane_slot.assign(nn, -1);
  }
  if (gaps && G.contact_gap.size() != static_cast<std::size_t>(nn)) G.contact_gap.assign(nn, 0.0);
  auto body_of = [&](int f) {
    return f < static_cast<int>(G.settings().field_body.size()) ? G.settings().field_body[f] : f;
  };
  // 0. The other ranks' particles near this rank's box, and the nodes this rank fits: those its
  //    particles weigh on (all on one rank).
  const Ghosts exchanged = halo ? exchange_ghosts(P, G, *halo, gaps) : Ghosts();
  const std::vector<PlaneGhost>& ghosts = exchanged.ghost;
  std::array<int, 3> fit_first{-1, -1, -1}, fit_last{1 << 30, 1 << 30, 1 << 30};
  if (halo) {
    fit_first = halo->boxes().first_cell(halo->comm().rank());
    fit_last = halo->boxes().end_cell(halo->comm().rank());
    for (int d = 0; d < 3; ++d) {
      fit_first[d] -= 1;
      fit_last[d] += 1;
    }
  }
  // Within `layers` node layers of the fitted nodes. The clouds read the lists of the fitted
  // nodes' neighbours too: those are listed, one layer further.
  const auto within = [&](const std::array<int, 3>& n, int layers) {
    const int axes = G.spec().planar() ? 2 : 3;
    for (int d = 0; d < axes; ++d)
      if (n[d] < fit_first[d] - layers || n[d] > fit_last[d] + layers) return false;
    return true;
  };
  // 1. The nodes of two bodies: their slot, and the two bodies (lower index first); with gaps
  //    also the nodes of three or more bodies (no plane: bodies {-1, -1}), whose gap is measured
  //    pair by pair (3b below). A node whose gap is not measured holds NaN (approach decides).
  const std::vector<int>& active = G.active_nodes();
  std::vector<int>& slot = G.contact_plane_slot;  // all -1 between steps
  std::vector<int> pair_node;
  std::vector<std::array<int, 2>> pair_bodies;
  std::vector<std::uint64_t> node_bodies;  // bit b: body b has mass at the node
  static_assert(kMaxContactFields <= 64);  // a body is a material, one bit each
  for (const int I : active) {
    G.contact_plane[I].setZero();
    if (gaps) G.contact_gap[I] = std::numeric_limits<double>::quiet_NaN();
    std::array<int, 2> bodies{-1, -1};
    std::uint64_t mask = 0;
    for (int f = 0; f < nf; ++f)
      if (G.mass[f * nn + I] > 0.0) mask |= std::uint64_t(1) << body_of(f);
    const int count = std::popcount(mask);
    if (count < 2 || (count > 2 && !gaps) || !within(G.ijk(I), 1)) continue;
    if (count == 2) {
      bodies[0] = std::countr_zero(mask);
      bodies[1] = 63 - std::countl_zero(mask);
    }
    slot[I] = static_cast<int>(pair_node.size());
    pair_node.push_back(I);
    pair_bodies.push_back(bodies);
    node_bodies.push_back(mask);
  }
  const int K = static_cast<int>(pair_node.size());
  if (K == 0) return;
  struct ResetSlots {  // on every way out
    std::vector<int>& slot;
    const std::vector<int>& nodes;
    ~ResetSlots() {
      for (const int I : nodes) slot[I] = -1;
    }
  } reset{slot, pair_node};
  // 2. Each pair node's particles, as lists (counted, then filled): index q < np a particle of
  //    this rank, q >= np the ghost q - np (its stencil computed here; only the nodes this rank
  //    stores are visited).
  const std::ptrdiff_t np = static_cast<std::ptrdiff_t>(P.size());
  const std::ptrdiff_t nq = np + static_cast<std::ptrdiff_t>(ghosts.size());
  Stencils<Shape> ghost_stencils(ghosts.size());
  for (std::size_t g = 0; g < ghosts.size(); ++g)
    ghost_stencils[g] = shape.at(ghosts[g].x, ghosts[g].object,
                                 G.spec().graded() ? &ghosts[g].half_width : nullptr);
  const auto field_of = [&](std::ptrdiff_t q) {
    return q < np ? int(P.field[q]) : int(ghosts[std::size_t(q - np)].field);
  };
  const auto position = [&](std::ptrdiff_t q) -> const Vec3& {
    return q < np ? P.x[q] : ghosts[std::size_t(q - np)].x;
  };
  // q's deformed radius (or its box's reach) along the unit vector n [m] (separating_plane.hpp):
  // its half-widths are its own on a graded grid (the owner's, for a ghost), else its object's.
  const auto domain_along = [&](auto measure, std::ptrdiff_t q, const Vec3& n) {
    const bool ghost = q >= np;
    const std::size_t g = ghost ? std::size_t(q - np) : 0;
    const Vec3& l = G.spec().graded()
                        ? (ghost ? ghosts[g].half_width : P.half_width[q])
                        : G.settings().particle_half_width[ghost ? ghosts[g].object : P.object[q]];
    return measure(ghost ? exchanged.F[g] : P.state[q].F, l, n, G.spec().dimensions());
  };
  const auto radius = [&](std::ptrdiff_t q, const Vec3& n) {
    return domain_along(deformed_radius, q, n);
  };
  const auto box_reach = [&](std::ptrdiff_t q, const Vec3& n) {
    return domain_along(deformed_reach, q, n);
  };
  const auto seed_id = [&](std::ptrdiff_t q) -> std::uint64_t {
    if (q >= np) return ghosts[std::size_t(q - np)].id;
    return seed_index(P, std::size_t(q));
  };
  const NodeBox stored = G.stored();
  const int sx = G.stride_x(), sy = G.stride_y();
  const auto for_each_pair_node = [&](std::ptrdiff_t q, auto&& visit) {
    const bool ghost = q >= np;
    if (!ghost && !(P.mass[q] > 0.0)) return;
    const Stencil<N>& s = ghost ? ghost_stencils[std::size_t(q - np)] : S[q];
    const int b = body_of(field_of(q));
    // Grid::index is linear in (i, j, k), also for a ghost's base outside the stored box: the
    // nodes are base + strides, computed only once they are found inside.
    const int base = G.index(s.base[0], s.base[1], s.base[2]);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        for (int k = 0; k < NZ; ++k) {
          if (!(s.w[0][i] * s.w[1][j] * s.w[2][k] > 0.0)) continue;
          const std::array<int, 3> m{s.base[0] + i, s.base[1] + j, s.base[2] + k};
          if (ghost) {  // a ghost's stencil may reach beyond the stored nodes
            bool inside = true;
            for (int d = 0; d < 3; ++d)
              inside = inside && m[d] >= stored.first[d] && m[d] <= stored.last[d];
            if (!inside) continue;
          }
          const int k_slot = slot[base + i * sx + j * sy + k];
          if (k_slot < 0 || !((node_bodies[k_slot] >> b) & 1)) continue;
          visit(k_slot);
        }
  };
  std::vector<int> start(K + 1, 0);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t q = 0; q < nq; ++q)
    for_each_pair_node(q, [&](int k) {
#pragma omp atomic
      ++start[k + 1];
    });
  for (int k = 0; k < K; ++k) start[k + 1] += start[k];
  std::vector<int> entries(start[K]);  // particles and ghosts (q)
  std::vector<int> next(start.begin(), start.end() - 1);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t q = 0; q < nq; ++q)
    for_each_pair_node(q, [&](int k) {
      int at;
#pragma omp atomic capture
      at = next[k]++;
      entries[at] = static_cast<int>(q);
    });
  // The particles and ghosts some list holds, numbered compactly for the stamps below (the
  // numbering does not enter the fit).
  std::vector<int> compact(static_cast<std::size_t>(nq), -1);
  int listed = 0;
  for (const int q : entries)
    if (compact[q] < 0) compact[q] = listed++;
  // 3. The fit per node: w in cells^-1, the normal w / h (w . (x - x_I) / h is the plane),
  //    pointing from the lower body into the higher.
  const GridSpec& spec = G.spec();
  const Vec3 base = G.spacing();
  const int dims = spec.dimensions();
  // 3b. The gap at a node of three or more bodies (`detection: separation`), which has no plane:
  //     for each pair of them, along the line between the centres of the boxes that bound their
  //     particles in the node's list (as the mirror leaves it: min and max, so the same bits in
  //     any list order, thread or rank), min over the second of (m . x_p - s_p) minus max over
  //     the first of (m . x_p + s_p), s_p the reach of the particle's deformed box along m
  //     (separating_plane.hpp); the smallest of the pairs. Two convex bodies' gap along any
  //     direction is at most their distance, and the boxes' reach bounds the particles' domains,
  //     so a positive gap means apart; along a poor direction it reads too small and approach
  //     decides. Without it approach alone decided there, and three blocks closing on one point
  //     across gaps of one and two cells squeezed each other at those nodes while the pair nodes
  //     around read gaps: 39 J of 60 J in strain energy by 12 us
  //     (tests/mpm/verification/contact_detection_test.cpp).
  const auto smallest_pair_gap = [&](int k, const Vec3& node, const MirrorView& mirror) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::array<Vec3, 64> low, high;
    const std::uint64_t mask = node_bodies[std::size_t(k)];
    for (std::uint64_t rest = mask; rest != 0; rest &= rest - 1) {
      low[std::size_t(std::countr_zero(rest))].setConstant(inf);
      high[std::size_t(std::countr_zero(rest))].setConstant(-inf);
    }
    const std::span<const int> list(entries.data() + start[k], entries.data() + start[k + 1]);
    for (const int q : list) {
      const std::size_t b = std::size_t(body_of(field_of(q)));
      low[b] = low[b].cwiseMin(position(q) - node);
      high[b] = high[b].cwiseMax(position(q) - node);
    }
    double smallest = inf;
    for (std::uint64_t ra = mask; ra != 0; ra &= ra - 1)
      for (std::uint64_t rb = ra & (ra - 1); rb != 0; rb &= rb - 1) {
        const std::size_t a = std::size_t(std::countr_zero(ra)),
                          b = std::size_t(std::countr_zero(rb));
        Vec3 line = mirror.applied_to(0.5 * (low[b] + high[b]) - 0.5 * (low[a] + high[a]));
        if (dims == 2) line(2) = 0.0;
        if (!(line.norm() > 0.0)) return -inf;  // no direction (or a body without particles)
        const Vec3 m = line.normalized();
        double top = -inf, bottom = inf;
        for (const int q : list) {
          const std::size_t body = std::size_t(body_of(field_of(q)));
          const double along = m.dot(position(q) - node);
          if (body == b) bottom = std::min(bottom, along - box_reach(q, m));
          if (body == a) top = std::max(top, along + box_reach(q, m));
        }
        smallest = std::min(smallest, bottom - top);
      }
    return smallest;
  };
#pragma omp parallel num_threads(threads)
  {
    std::vector<PlanePoint> points;
    std::vector<int> cloud;
    // The last node (k + 1) whose cloud took each listed particle (compact number): each is taken
    // once, so that only the cloud itself is sorted, not the up to 27 lists' copies of it.
    std::vector<int> taken(static_cast<std::size_t>(listed), 0);
#pragma omp for schedule(dynamic, 16)
    for (int k = 0; k < K; ++k) {
      const int I = pair_node[k];
      const std::array<int, 3> n = G.ijk(I);
      if (!within(n, 0)) continue;  // listed only: no particle of this rank weighs on it
      // The node and the cell the tent counts in: on a graded grid the node's own coordinates
      // and its dual cell (the mean of the two cells beside it along each mesh axis), so that
      // the tent reaches 2.25 of the cells around it whatever their size (issue 56).
      Vec3 node = G.lower() + Vec3(n[0] * base(0), n[1] * base(1), n[2] * base(2));
      Vec3 h = base;
      if (spec.graded())
        for (int d = 0; d < dims; ++d) {
          node(d) = spec.node(d, n[d]);
          h(d) = spec.dual_size(d, n[d]);
        }
      if (pair_bodies[k][0] < 0) {  // three or more bodies: their gap pair by pair (3b)
        G.contact_gap[I] = smallest_pair_gap(k, node, mirror_view(G, n));
        continue;
      }
      // The cloud: the two bodies' particles in the lists of this node and of its neighbours
      // that are two-body nodes too, weighted by a tent of kPlaneReach cells about this node.
      cloud.clear();
      const int kz = dims == 3 ? 1 : 0;
      for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
          for (int c = -kz; c <= kz; ++c) {
            const std::array<int, 3> m{n[0] + a, n[1] + b, n[2] + c};
            bool stored_node = true;
            for (int d = 0; d < 3; ++d)
              stored_node = stored_node && m[d] >= stored.first[d] && m[d] <= stored.last[d];
            if (!stored_node) continue;
            const int kj = slot[G.index(m[0], m[1], m[2])];
            // Pair nodes only (a node of three bodies is listed only for its gap, 3b): the
            // planes are those of approach runs.
            if (kj < 0 || pair_bodies[std::size_t(kj)][0] < 0) continue;
            for (auto e = entries.begin() + start[kj]; e != entries.begin() + start[kj + 1]; ++e) {
              if (taken[compact[*e]] == k + 1) continue;
              const int body = body_of(field_of(*e));
              if (body != pair_bodies[k][0] && body != pair_bodies[k][1]) continue;
              taken[compact[*e]] = k + 1;
              cloud.push_back(*e);
            }
          }
      // By seed id: the same sums on any thread count, and on every rank that fits this node.
      std::sort(cloud.begin(), cloud.end(), [&](int a, int b) { return seed_id(a) < seed_id(b); });
      points.clear();
      for (const int p : cloud) {
        const Vec3 xi = (position(p) - node).cwiseQuotient(h);
        double weight = 1.0;
        for (int d = 0; d < dims; ++d) weight *= std::max(0.0, 1.0 - std::abs(xi(d)) / kPlaneReach);
        if (weight > 0.0) points.push_back({xi, weight, body_of(field_of(p)) == pair_bodies[k][1]});
      }
      const Vec3 normal = separating_plane(points, dims).cwiseQuotient(h);
      const double length = normal.norm();
      if (!(length > 0.0)) continue;
      const Vec3 unit = normal / length;
      G.contact_plane[I] = unit;
      if (!gaps) continue;
      // The gap between the lower body's furthest particle and the higher body's nearest along
      // the normal contact will use (the mirror's: a face node's lies in the face; contact.cpp),
      // over the particles that weigh on this node. A plane tilted by a few degrees at a body's
      // edge reads the gap short by the tilt times the particles' spread along the surface, which
      // the fit's wider cloud would double (contact_detection_test.cpp).
      const Vec3 along_face = mirror_view(G, n).applied_to(unit);
      if (!(along_face.norm() > 0.0)) continue;  // contact ignores this plane too
      const Vec3 m = along_face.normalized();
      double top = -std::numeric_limits<double>::infinity();
      double bottom = std::numeric_limits<double>::infinity();
      for (auto e = entries.begin() + start[k]; e != entries.begin() + start[k + 1]; ++e) {
        const double along = m.dot(position(*e) - node);
        if (body_of(field_of(*e)) == pair_bodies[k][1])
          bottom = std::min(bottom, along - radius(*e, m));
        else
          top = std::max(top, along + radius(*e, m));
      }
      if (std::isfinite(bottom - top)) G.contact_gap[I] = bottom - top;  // else NaN: approach
    }
  }
}

// For every shape of the catalogue (mpm/shape/shape.hpp), as particles_to_grid.cpp does.
namespace {
template <class... Shapes>
struct ContactPlanePhases {
  static constexpr auto functions = std::make_tuple(&fit_contact_planes<Shapes>...);
};
[[gnu::used]] const auto kContactPlanesForEveryShape =
    WithEveryShape<ContactPlanePhases>::functions;
}  // namespace

}  // namespace impact::mpm
