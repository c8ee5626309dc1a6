// Grid to particles (Sulsky et al. 1994 eqs. 23, 25-26): FLIP velocity update, position from the
// updated grid velocity, velocity gradient; and MUSL's re-map (Sulsky et al. 1995, Nairn 2003).
// The weights are the cached start-of-step stencils throughout.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "models/thermal/adiabatic_heating.hpp"

#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/step/step.hpp"
#include "mpm/threads/chunk_sums.hpp"
#include "mpm/threads/threads.hpp"

namespace impact::mpm {

namespace {

// Position check after a move: a particle outside the grid has no complete stencil.
bool outside(const Grid& G, const Vec3& x) {
  const Vec3& upper = G.spec().upper;
  return !((x.array() >= G.lower().array()).all() && (x.array() <= upper.array()).all());
}

// A particle that creeps onto a face whose node the face holds (its grid velocity tends to zero
// there) crosses it by round-off: x = -7.3e-23 m on the x- wall of a block crushed under 1e11
// m/s^2, after 12138 steps, stopped a valid run as "left the grid". Within 1e-12 of a cell of
// a face it is put back on the face; further out it has left.
void onto_face_within_round_off(const Grid& G, Vec3& x) {
  const Vec3& lower = G.lower();
  const Vec3& upper = G.spec().upper;
  const Vec3& band = G.spacing();  // times 1e-12 below
  for (int d = 0; d < 3; ++d) {
    if (x(d) < lower(d) && x(d) >= lower(d) - 1e-12 * band(d)) x(d) = lower(d);
    if (x(d) > upper(d) && x(d) <= upper(d) + 1e-12 * band(d)) x(d) = upper(d);
  }
}

// The start-of-step radius of a particle, sum_I S_Ip y_I (the shapes reproduce linear fields):
// what the weights were evaluated at, also after MUSL has moved the particle.
template <int N>
double stencil_radius(const Grid& G, const Stencil<N>& s) {
  double r = 0.0;
  for (int j = 0; j < N; ++j) r += s.w[1][j] * G.node_coordinate(1, s.base[1] + j);
  return r;
}

// L_p = sum_I (v_I - v_ref) (x) grad S_Ip over nodes with mass (see step.hpp; with uGIMP a
// massless node of the particle's own stencil has zero weight and zero gradient, so it adds exact
// zeros and is not tested: Shape::kSlopeVanishesWithWeight, the same bits); with the hoop
// terms (axisymmetric), L_tt = sum_I S_Ip v_I,r / r_p = (v_ref,r + sum_I S_Ip (v_I - v_ref)_r) /
// r_p, in the same sense (Sulsky & Schreyer 1996 eq. 14), r_p at the start of the step.
template <class Shape>
Mat3 gradient(const Grid& G, const Stencil<Shape::N>& s, const std::vector<Vec3>& v,
              const Vec3& v_ref, std::size_t offset) {
  constexpr int N = Shape::N, NZ = Shape::NZ;
  Mat3 L = Mat3::Zero();
  const std::size_t base = offset + G.index(s.base[0], s.base[1], s.base[2]);
  const std::size_t sx = G.stride_x(), sy = G.stride_y();
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      const std::size_t row = base + i * sx + j * sy;
      const double wij = s.w[0][i] * s.w[1][j];
      const double dxw = s.dw[0][i] * s.w[1][j];
      const double wdy = s.w[0][i] * s.dw[1][j];
      Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // sum_k dv w_z, sum_k dv dw_z
      for (int k = 0; k < NZ; ++k) {
        if constexpr (!Shape::kSlopeVanishesWithWeight)
          if (!(G.mass[row + k] > 0.0)) continue;
        const Vec3 dv = v[row + k] - v_ref;
        a += dv * s.w[2][k];
        b += dv * s.dw[2][k];
      }
      L.col(0) += dxw * a;
      L.col(1) += wdy * a;
      L.col(2) += wij * b;
      if constexpr (Shape::kHoop) L(2, 2) += wij * a(1);
    }
  if constexpr (Shape::kHoop) {
    // On the axis itself v_r / r is its limit dv_r / dr (a particle seeded off the axis reaches
    // it only if parked there by outflow, with no mass).
    const double r = stencil_radius(G, s);
    L(2, 2) = r > 0.0 ? (L(2, 2) + v_ref(1)) / r : L(1, 1);
  }
  return L;
}

// sum_I S_Ip (u_I - w_I) over the particle's stencil in its field (`offset`).
template <class Shape>
Vec3 interpolated_difference(const Grid& G, const Stencil<Shape::N>& s, const std::vector<Vec3>& u,
                             const std::vector<Vec3>& w, std::size_t offset) {
  constexpr int N = Shape::N, NZ = Shape::NZ;
  const std::size_t base = offset + G.index(s.base[0], s.base[1], s.base[2]);
  const std::size_t sx = G.stride_x(), sy = G.stride_y();
  Vec3 d = Vec3::Zero();
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int k = 0; k < NZ; ++k) {
        const std::size_t e = base + i * sx + j * sy + k;
        d += (s.w[0][i] * s.w[1][j] * s.w[2][k]) * (u[e] - w[e]);
      }
  return d;
}

// Whether the rigid contact pushed particle p this step (rigid_particle_contact.hpp).
bool pushed(const Vec3* rigid_force, std::size_t p) {
  return rigid_force != nullptr && rigid_force[p].squaredNorm() > 0.0;
}

}  // namespace

template <class Shape>
ParticleTotals grid_to_particles(Particles& P, const Grid& G, const Stencils<Shape>& S, double dt,
                                 bool usl_gradient, const std::vector<HeatCapacity>& heat_capacity,
                                 std::optional<Failure>& failure, const Vec3* body_force,
                                 const Vec3* rigid_force) {
  constexpr int N = Shape::N, NZ = Shape::NZ;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  const std::size_t nn = static_cast<std::size_t>(G.node_count());
  const std::size_t sx = G.stride_x(), sy = G.stride_y();
  const int nt = G.threads();
  const bool heat = !G.heat.empty();
  const bool outflow = !P.removed.empty();  // grid.outflow = remove
  const std::uint8_t* const rigid =
      G.has_rigid_fields() ? G.settings().rigid_field.data() : nullptr;
  // The sums per chunk of 512 particles, then in chunk order (mpm/threads/chunk_sums.hpp).
  ChunkSums<ParticleTotals> chunk_sums(n, 512);
  const std::ptrdiff_t chunks = chunk_sums.chunks();
  std::optional<Failure> failures[kMaxThreads];
#pragma omp parallel num_threads(nt)
  {
    std::optional<Failure> fail;
#pragma omp for schedule(static)
    for (std::ptrdiff_t chunk = 0; chunk < chunks; ++chunk) {
      ParticleTotals& sum = chunk_sums[chunk];
      const std::ptrdiff_t chunk_end = chunk_sums.end(chunk);
      for (std::ptrdiff_t p = chunk_sums.begin(chunk); p < chunk_end; ++p) {
        if (outflow && P.removed[p]) continue;
        if (in_rigid_field(rigid, P, std::size_t(p))) {  // x += V dt; not in the system's books
          const Vec3 x_old = P.x[p];
          P.x[p] += dt * P.v[p];
          onto_face_within_round_off(G, P.x[p]);
          if (P.x[p].allFinite() && !outside(G, P.x[p])) continue;
          if (outflow) {  // leaves with nothing to book: its motion was never the system's
            P.removed[p] = 1;
            P.x[p] = x_old;
          } else if (fails_first(P, std::size_t(p), fail)) {
            fail = Failure{std::size_t(p), "position",
                           "a rigid object's particle left the grid (grid.outflow = \"remove\" "
                           "lets it leave the simulation)"};
          }
          continue;
        }
        const Stencil<N>& s = S[p];
        const std::size_t offset = P.field[p] * nn;  // the particle's velocity field
        Vec3 dv = Vec3::Zero(), v_new = Vec3::Zero();
        double h = 0.0;  // sum_I S_Ip heat_I / m_I
        const std::size_t base = offset + G.index(s.base[0], s.base[1], s.base[2]);
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j) {
            const std::size_t row = base + i * sx + j * sy;
            const double wij = s.w[0][i] * s.w[1][j];
            for (int k = 0; k < NZ; ++k) {
              const double w = wij * s.w[2][k];
              const Vec3& inc = G.increment[row + k];
              dv += w * inc;
              v_new += w * G.velocity_new[row + k];
              if (heat && G.heat[row + k] != 0.0) h += w * G.heat[row + k] / G.mass[row + k];
            }
          }
        if (usl_gradient) P.L[p] = gradient<Shape>(G, s, G.velocity_L, P.v[p], offset);
        const double m = P.mass[p];
        if (body_force) {  // sum_I S_Ip (v_I + v*_I)/2 = v_new - dv/2 (step.hpp ParticleTotals)
          const Vec3 J = dt * m * body_force[p];
          sum.external_impulse += J;
          sum.external_work += J.dot(v_new - 0.5 * dv);
        }
        if (h != 0.0) {
          const HeatCapacity& c = heat_capacity[P.material[p]];
          retain_heat(P.state[p], h, c.retained, c.specific_heat);
          sum.friction_heat += m * h;
        }
        P.v[p] += dv;
        const Vec3 x_old = P.x[p];
        P.x[p] += dt * v_new;
        if (usl_gradient && pushed(rigid_force, std::size_t(p)))  // with v^L_I, as L (step.hpp)
          P.x[p] += dt * interpolated_difference<Shape>(G, s, G.velocity_L, G.velocity_new, offset);
        onto_face_within_round_off(G, P.x[p]);
        const Vec3& v = P.v[p];
        if (!v.allFinite() && fails_first(P, std::size_t(p), fail))
          fail = Failure{std::size_t(p), "velocity", "not finite"};
        if (!(P.x[p].allFinite() && !outside(G, P.x[p]))) {
          if (outflow && v.allFinite()) {
            // Leaves the simulation: its mass, momentum and kinetic energy go to the outflow
            // columns; it stays parked where it was. It keeps its mass and final velocity until
            // the stress update empties it, so that the MUSL re-map, which divides by the nodal
            // masses of this step, still sees its momentum (without it the nodes it shared slow
            // down and strain the rest of the body: 20 J on a rigid block; outflow_test).
            sum.outflow_mass += m;
            sum.outflow_momentum += m * v;
            sum.outflow_kinetic_energy += 0.5 * m * v.squaredNorm();
            ++sum.removed;
            P.removed[p] = 1;
            P.x[p] = x_old;
            continue;
          }
          if (fails_first(P, std::size_t(p), fail)) {
            fail = Failure{std::size_t(p), "position",
                           "left the grid (grid.outflow = \"remove\" lets it leave the simulation, "
                           "booked as outflow)"};
          }
        }
        sum.kinetic_energy += 0.5 * m * v.squaredNorm();  // report eq. 13, end-of-step velocity
        sum.momentum += m * v;
        sum.max_speed = std::max(sum.max_speed, v.norm());
      }
    }
    failures[omp_get_thread_num()] = fail;
  }
  ParticleTotals total;
  chunk_sums.add_in_order([&](const ParticleTotals& sum) { merge_into(total, sum); });
  for (int t = 0; t < nt; ++t)  // the lowest seed index: the same whichever thread saw it
    merge_failure(failure, failures[t],
                  [&](const Failure& a, const Failure& b) { return fails_first(P, a, b); });
  return total;
}

template <class Shape>
void remap_and_gradient(Particles& P, Grid& G, const Stencils<Shape>& S, const ScatterOrder& order,
                        const ContactSpec* contact, const HaloExchange* halo, double dt,
                        const Vec3* rigid_force) {
  constexpr int N = Shape::N, NZ = Shape::NZ;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  const int nt = G.threads();
  G.clear_momentum();
  Vec3* const buf = G.momentum_buffer();
  const int sx = G.stride_x(), sy = G.stride_y();
  scatter_by_colour(
      order, nt,
      [&](int p) {
        const Stencil<N>& s = S[p];
        Vec3* const base =
            buf + P.field[p] * G.node_count() + G.index(s.base[0], s.base[1], s.base[2]);
        const Vec3 mv = P.mass[p] * P.v[p];
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j) {
            Vec3* row = base + i * sx + j * sy;
            const Vec3 mvij = (s.w[0][i] * s.w[1][j]) * mv;
            for (int k = 0; k < NZ; ++k) row[k] += s.w[2][k] * mvij;
          }
      },
      [&](int q) { prefetch_stencil(S[q]); });
  if (halo) halo->sum_momentum(G);
  const std::vector<Vec3>& momentum = G.remapped_momentum();
  const std::size_t nn = static_cast<std::size_t>(G.node_count());
  G.for_active_entries([&](int i) {
    G.velocity_L[i] = G.mass[i] > 0.0 ? Vec3(momentum[i] / G.mass[i]) : Vec3::Zero();
  });
  // Projections, not loads: the particles' momentum is already final. Contact holds the nodes
  // the step held (contact.hpp, ContactPass::strain); a rigid object's field is at V exactly.
  G.hold_rigid_fields(G.velocity_L);
  if (contact != nullptr && G.fields() > 1)
    apply_contact(G, *contact, G.velocity_L, ContactPass::strain);
  G.apply_mirror(G.velocity_L);
  if (G.has_walls()) G.apply_walls(nullptr, G.velocity_L, WallPass::projection);
  G.hold_rigid_fields(G.velocity_L);
#pragma omp parallel for schedule(static) num_threads(nt)
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    P.L[p] = gradient<Shape>(G, S[p], G.velocity_L, P.v[p], P.field[p] * nn);
    // A particle the rigid contact pushed moves with v^{n+1}_I, as L (step.hpp): grid_to_particles
    // moved it with v*_I from the same x^n. Where that would leave the grid it keeps that move.
    if (pushed(rigid_force, std::size_t(p)) && !(P.removed.size() > 0 && P.removed[p])) {
      Vec3 x = P.x[p] + dt * interpolated_difference<Shape>(G, S[p], G.velocity_L, G.velocity_new,
                                                            P.field[p] * nn);
      onto_face_within_round_off(G, x);
      if (x.allFinite() && !outside(G, x)) P.x[p] = x;
    }
  }
}

// Both phases for every shape of the catalogue (mpm/shape/shape.hpp): taking their addresses
// instantiates them here, for advance() to call.
namespace {
template <class... Shapes>
struct GatherPhases {
  static constexpr auto functions =
      std::make_tuple(&grid_to_particles<Shapes>..., &remap_and_gradient<Shapes>...);
};
[[gnu::used]] const auto kGatherPhasesForEveryShape = WithEveryShape<GatherPhases>::functions;
}  // namespace

}  // namespace impact::mpm
