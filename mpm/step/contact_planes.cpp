// The separating planes of `contact.normal = "logistic_regression"` (contact/separating_plane.hpp,
// Nairn, Hammerquist & Smith 2020): after particles to grid, at every node where exactly two
// bodies have mass, a plane is fitted by logistic regression to the two bodies' particles near it,
// and its unit normal is stored for contact (Grid::contact_plane). The cloud is wider than the
// node's own support: the particles that weigh on the node or on any neighbouring two-body node
// (S_Ip > 0, the step's stencils), weighted by a tent of kPlaneReach cells about the node. The
// node's own support alone (1 + l_p cells) sees a few particle layers of a surface that is not
// grid-aligned, whose seeded staircase tilted the planes node by node by up to 20 degrees; a
// pressed interface whose nodes hold different normals holds every direction, and a block on a
// 20-degree ramp of another body did not slide at all (0.008 m/s against 1.71 m/s in 50 us; 1.35
// m/s with the wider cloud, 1.705 on the same ramp turned grid-aligned;
// tests/mpm/verification/contact_friction_test.cpp). A node shared with another rank's particles
// (within two node layers of a box boundary: their uGIMP stencils reach it) has only part of its
// cloud here, and the ranks would fit different planes: there no plane is fitted and contact uses
// the mass gradients, which the node sums make identical on every rank (docs/mpi.md). Each cloud
// is sorted by particle index, so the fit is the same bits on any thread count.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "mpm/contact/separating_plane.hpp"
#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/parallel/slab_decomposition.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

namespace {

// The half-width of the tent that weighs a node's cloud [cells]: a neighbour's uGIMP support ends
// 1 + l_p (<= 1.5) cells beyond it, so the cloud reaches about 2.25 cells.
constexpr double kPlaneReach = 2.25;

// Whether every particle that can weigh on node n is on this rank: n at least two node layers
// inside the cells [c0, c1) of the rank's box on each side that has a neighbour (a neighbour's
// uGIMP particles reach its node c0 + 1 at most). A side without one stores the whole grid up to
// its ghost layer, -1 or cells + 1; a side with one stores from c0 - kHaloPlanes >= 0, as every
// box has at least SlabDecomposition::kMinCells >= kHaloPlanes cells.
static_assert(SlabDecomposition::kMinCells >= kHaloPlanes);
bool cloud_is_local(const Grid& G, const std::array<int, 3>& n) {
  const NodeBox stored = G.stored();
  const int axes = G.spec().planar() ? 2 : 3;
  for (int d = 0; d < axes; ++d) {
    if (stored.first[d] > -1 && n[d] < stored.first[d] + kHaloPlanes + 2) return false;
    if (stored.last[d] < G.cells()[d] + 1 && n[d] > stored.last[d] - kHaloPlanes - 2) return false;
  }
  return true;
}

}  // namespace

template <class Shape>
void fit_contact_planes(const Particles& P, Grid& G, const Stencils<Shape>& S) {
  constexpr int N = Shape::N, NZ = Shape::NZ;
  const int nn = G.node_count();
  const int nf = G.fields();
  const int threads = G.threads();
  if (G.contact_plane.size() != static_cast<std::size_t>(nn)) {
    G.contact_plane.assign(nn, Vec3::Zero());
    G.contact_plane_slot.assign(nn, -1);
  }
  auto body_of = [&](int f) {
    return f < static_cast<int>(G.field_body.size()) ? G.field_body[f] : f;
  };
  // 1. The nodes of two bodies: their slot, and the two bodies (lower index first).
  const std::vector<int>& active = G.active_nodes();
  std::vector<int>& slot = G.contact_plane_slot;  // all -1 between steps
  std::vector<int> pair_node;
  std::vector<std::array<int, 2>> pair_bodies;
  for (const int I : active) {
    G.contact_plane[I].setZero();
    std::array<int, 2> bodies{-1, -1};
    int count = 0;
    for (int f = 0; f < nf && count <= 2; ++f) {
      if (!(G.mass[f * nn + I] > 0.0)) continue;
      const int b = body_of(f);
      if (b == bodies[0] || b == bodies[1]) continue;
      if (count < 2) bodies[count] = b;
      ++count;
    }
    if (count != 2 || !cloud_is_local(G, G.ijk(I))) continue;
    if (bodies[0] > bodies[1]) std::swap(bodies[0], bodies[1]);
    slot[I] = static_cast<int>(pair_node.size());
    pair_node.push_back(I);
    pair_bodies.push_back(bodies);
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
  // 2. Each pair node's particles, as lists (counted, then filled).
  const std::ptrdiff_t np = static_cast<std::ptrdiff_t>(P.size());
  const int sx = G.stride_x(), sy = G.stride_y();
  const auto for_each_pair_node = [&](std::ptrdiff_t p, auto&& visit) {
    if (!(P.mass[p] > 0.0)) return;
    const Stencil<N>& s = S[p];
    const int b = body_of(P.field[p]);
    const int base = G.index(s.base[0], s.base[1], s.base[2]);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        for (int k = 0; k < NZ; ++k) {
          if (!(s.w[0][i] * s.w[1][j] * s.w[2][k] > 0.0)) continue;
          const int k_slot = slot[base + i * sx + j * sy + k];
          if (k_slot < 0 || (pair_bodies[k_slot][0] != b && pair_bodies[k_slot][1] != b)) continue;
          visit(k_slot);
        }
  };
  std::vector<int> start(K + 1, 0);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t p = 0; p < np; ++p)
    for_each_pair_node(p, [&](int k) {
#pragma omp atomic
      ++start[k + 1];
    });
  for (int k = 0; k < K; ++k) start[k + 1] += start[k];
  std::vector<int> entries(start[K]);  // particles
  std::vector<int> next(start.begin(), start.end() - 1);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t p = 0; p < np; ++p)
    for_each_pair_node(p, [&](int k) {
      int at;
#pragma omp atomic capture
      at = next[k]++;
      entries[at] = static_cast<int>(p);
    });
  // 3. The fit per node: w in cells^-1, the normal w / h (w . (x - x_I) / h is the plane),
  //    pointing from the lower body into the higher.
  const Vec3 h = G.spacing();
  const int dims = G.spec().dimensions();
  const NodeBox stored = G.stored();
#pragma omp parallel num_threads(threads)
  {
    std::vector<PlanePoint> points;
    std::vector<int> cloud;
    // The last node (k + 1) whose cloud took each particle: each is taken once, so that only the
    // cloud itself is sorted, not the up to 27 lists' copies of it.
    std::vector<int> taken(P.size(), 0);
#pragma omp for schedule(dynamic, 16)
    for (int k = 0; k < K; ++k) {
      const int I = pair_node[k];
      const std::array<int, 3> n = G.ijk(I);
      const Vec3 node = G.lower() + Vec3(n[0] * h(0), n[1] * h(1), n[2] * h(2));
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
            if (kj < 0) continue;
            for (auto e = entries.begin() + start[kj]; e != entries.begin() + start[kj + 1]; ++e) {
              if (taken[*e] == k + 1) continue;
              const int body = body_of(P.field[*e]);
              if (body != pair_bodies[k][0] && body != pair_bodies[k][1]) continue;
              taken[*e] = k + 1;
              cloud.push_back(*e);
            }
          }
      std::sort(cloud.begin(), cloud.end());  // by particle: the same sums on any thread count
      points.clear();
      for (const int p : cloud) {
        const Vec3 xi = (P.x[p] - node).cwiseQuotient(h);
        double weight = 1.0;
        for (int d = 0; d < dims; ++d) weight *= std::max(0.0, 1.0 - std::abs(xi(d)) / kPlaneReach);
        if (weight > 0.0) points.push_back({xi, weight, body_of(P.field[p]) == pair_bodies[k][1]});
      }
      const Vec3 normal = separating_plane(points, dims).cwiseQuotient(h);
      const double length = normal.norm();
      if (length > 0.0) G.contact_plane[I] = normal / length;
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
