// Stencils once per step, and particles to grid, Sulsky, Chen & Schreyer (1994) eqs. 20-22 (mass,
// momentum, internal force). The threads scatter into one grid buffer, one colour of bands at a
// time (step/scatter_order.hpp: the same bits on any thread count). With active blocks the
// scatter also marks the blocks the stencils touch; Grid::activate turns the marks into the
// step's node list.
#include <tuple>

#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/step/step.hpp"
#include "mpm/threads/threads.hpp"

namespace impact::mpm {

template <class Shape>
long compute_stencils(const Particles& P, const Shape& shape, Stencils<Shape>& S, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  if (S.size() != P.size()) S.resize(P.size());  // once (the particle count is fixed)
  // A graded grid's particles carry their own uGIMP half-width (Particles::half_width).
  const Vec3* const own = P.half_width.empty() ? nullptr : P.half_width.data();
  if (!own) {
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::ptrdiff_t p = 0; p < n; ++p) S[p] = shape.at(P.x[p], P.object[p]);
    return 0;
  }
  long narrowed = 0;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(+ : narrowed)
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    bool n = false;
    S[p] = shape.at(P.x[p], P.object[p], own + p, &n);
    narrowed += n;
  }
  return narrowed;
}

template <class Shape>
void particles_to_grid(const Particles& P, Grid& G, const Stencils<Shape>& S,
                       const ScatterOrder& order, double dt, const HaloExchange* halo,
                       const Vec3* body_force, const Vec3* rigid_force) {
  constexpr int N = Shape::N, NZ = Shape::NZ;  // NZ = 1 on a 2D grid
  G.clear();                                   // where the last step put mass: now zero everywhere
  const std::size_t nn = static_cast<std::size_t>(G.node_count());
  const bool viscosity = !P.q.empty();
  NodeData* const buf = G.node_buffer();
  char* const marks = G.dense() ? nullptr : G.block_marks();
  const int sx = G.stride_x(), sy = G.stride_y();
  // Wall faces: which walls each particle's domain reaches this step (grid/wall.cpp).
  std::uint8_t* const touch = G.wall_touch.empty() ? nullptr : G.wall_touch.data();
  // A graded grid's particles reach a wall by their own half-width (Particles::half_width).
  const Vec3* const own = P.half_width.empty() ? nullptr : P.half_width.data();
  const bool graded = G.settings().node_mean_mass;
  scatter_by_colour(
      order, G.threads(),
      [&](int p) {
        if (rigid_force && G.is_rigid_field(P.field[p])) return;  // met at the particles instead
        const Stencil<N>& s = S[p];
        if (marks) G.mark_stencil(marks, s.base, N, NZ);
        const int base_index = G.index(s.base[0], s.base[1], s.base[2]);
        const std::size_t offset = P.field[p] * nn;  // the particle's velocity field
        NodeData* const field = buf + offset;
        Mat3 sigma = P.state[p].stress;
        if (viscosity) sigma.diagonal().array() -= P.q[p];  // sigma - q I (report eq. 12)
        const Mat3 vs = -P.volume[p] * sigma;               // -V_p (sigma_p - q_p I)
        // Axisymmetric: the hoop stress pulls each ring towards the axis, -V_p sigma_tt S_Ip / r_p
        // on the radial component (Sulsky & Schreyer 1996 eq. 20; V_p is the revolved ring's).
        // Held as a vector (0, hoop, 0) added to a below: a scalar a(1) += ... made the compiler
        // store a to the stack and reload it whole, a stalled store forward per node (perf).
        Vec3 hoop = Vec3::Zero();
        if constexpr (Shape::kHoop) hoop(1) = P.x[p](1) > 0.0 ? vs(2, 2) / P.x[p](1) : 0.0;
        const double m = P.mass[p];
        const Vec3 mv = m * P.v[p];
        // A body force adds m_p b_p S_Ip, a term of a with w_z (step/body_force.hpp).
        // The rigid objects' contact force f_p joins it (contact/rigid_particle_contact.hpp).
        Vec3 mb = body_force ? Vec3(m * body_force[p]) : Vec3::Zero();
        if (rigid_force) mb += rigid_force[p];
        const bool external = body_force || rigid_force;
        for (int i = 0; i < N; ++i) {
          for (int j = 0; j < N; ++j) {
            const int row_index = base_index + i * sx + j * sy;
            NodeData* row = field + row_index;
            const double wij = s.w[0][i] * s.w[1][j];
            const double dxw = s.dw[0][i] * s.w[1][j];
            const double wdy = s.w[0][i] * s.dw[1][j];
            // vs * grad = a * w_z + b * dw_z with a, b per (i, j)
            Vec3 a = vs.col(0) * dxw + vs.col(1) * wdy;
            if constexpr (Shape::kHoop) a = a + hoop * wij;  // w_z = 1, dw_z = 0 on a 2D grid
            if (external) a += mb * wij;
            const Vec3 b = vs.col(2) * wij;
            for (int k = 0; k < NZ; ++k) {
              NodeData& node = row[k];
              const double w = wij * s.w[2][k];
              const Vec3 f = a * s.w[2][k] + b * s.dw[2][k];
              node.mass += w * m;
              for (int d = 0; d < 3; ++d) {
                node.momentum[d] += w * mv(d);
                node.force[d] += f(d);
              }
            }
          }
        }
        if (graded) {  // the light-node rule's mean particle mass (NodeData::mass_moment)
          const double mm = m * m;
          for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j)
              for (int k = 0; k < NZ; ++k)
                field[base_index + i * sx + j * sy + k].mass_moment +=
                    s.w[0][i] * s.w[1][j] * s.w[2][k] * mm;
        }
        if (touch && m > 0.0) {  // the nodes this particle weighs, where it reaches a wall
          const std::uint8_t bits = G.touched_walls(
              P.x[p], P.v[p], own ? own[p] : G.settings().particle_half_width[P.object[p]], dt);
          if (bits == 0) return;
          for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j)
              for (int k = 0; k < NZ; ++k)
                if (s.w[0][i] * s.w[1][j] * s.w[2][k] > 0.0)
                  touch[offset + base_index + i * sx + j * sy + k] |= bits;
        }
      },
      [&](int q) {  // its stress (state records are 280 B apart) and its stencil (160 B)
        __builtin_prefetch(&P.state[q].stress);
        prefetch_stencil(S[q]);
      });
  if (halo) halo->sum_node_data(G, /*contact=*/G.fields() > 1);
  G.activate();
  G.collect_mass();
}

// Both phases for every shape of the catalogue (mpm/shape/shape.hpp): taking their addresses
// instantiates them here, for advance() to call.
namespace {
template <class... Shapes>
struct ScatterPhases {
  static constexpr auto functions =
      std::make_tuple(&compute_stencils<Shapes>..., &particles_to_grid<Shapes>...);
};
[[gnu::used]] const auto kScatterPhasesForEveryShape = WithEveryShape<ScatterPhases>::functions;
}  // namespace

}  // namespace impact::mpm
