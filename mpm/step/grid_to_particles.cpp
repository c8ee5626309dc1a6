// Grid to particles (Sulsky et al. 1994 eqs. 23, 25-26): FLIP velocity update, position from the
// updated grid velocity, velocity gradient; and MUSL's re-map (Sulsky et al. 1995, Nairn 2003).
// The weights are the cached start-of-step stencils throughout.
#include <cmath>

#include "mpm/step/parallel.hpp"

namespace impact::mpm {

namespace {

// Position check after a move: a particle outside the grid has no complete stencil.
bool outside(const Grid& G, const Vec3& x) {
  const Vec3& upper = G.spec().upper;
  return !((x.array() >= G.lower().array()).all() && (x.array() <= upper.array()).all());
}

// L_p = sum_I (v_I - v_ref) (x) grad S_Ip over nodes with mass (see step.hpp).
template <int N>
Mat3 gradient(const Grid& G, const Stencil<N>& s, const std::vector<Vec3>& v, const Vec3& v_ref) {
  Mat3 L = Mat3::Zero();
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      const int row = G.index(s.base[0] + i, s.base[1] + j, s.base[2]);
      const double wij = s.w[0][i] * s.w[1][j];
      const double dxw = s.dw[0][i] * s.w[1][j];
      const double wdy = s.w[0][i] * s.dw[1][j];
      Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // sum_k dv w_z, sum_k dv dw_z
      for (int k = 0; k < N; ++k) {
        if (!(G.mass[row + k] > 0.0)) continue;
        const Vec3 dv = v[row + k] - v_ref;
        a += dv * s.w[2][k];
        b += dv * s.dw[2][k];
      }
      L.col(0) += dxw * a;
      L.col(1) += wdy * a;
      L.col(2) += wij * b;
    }
  return L;
}

}  // namespace

template <class Shape>
ParticleTotals grid_to_particles(Particles& P, const Grid& G, const Stencils<Shape>& S, double dt,
                                 bool usl_gradient, std::optional<Failure>& failure) {
  constexpr int N = Shape::N;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  const int nt = G.threads();
  ParticleTotals partial[kMaxThreads];
  std::optional<Failure> failures[kMaxThreads];
#pragma omp parallel num_threads(nt)
  {
    ParticleTotals sum;
    std::optional<Failure> fail;
#pragma omp for schedule(static)
    for (std::ptrdiff_t p = 0; p < n; ++p) {
      const Stencil<N>& s = S[p];
      Vec3 dv = Vec3::Zero(), v_new = Vec3::Zero();
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
          const int row = G.index(s.base[0] + i, s.base[1] + j, s.base[2]);
          const double wij = s.w[0][i] * s.w[1][j];
          for (int k = 0; k < N; ++k) {
            const double w = wij * s.w[2][k];
            dv += w * G.increment[row + k];
            v_new += w * G.velocity_new[row + k];
          }
        }
      if (usl_gradient) P.L[p] = gradient(G, s, G.velocity_L, P.v[p]);
      // The faces' velocity projection's share of dv, delta_p = sum_I S_Ip (P v_I - v_I), does
      // the work m_p delta_p . (v_p^n + v_p^{n+1}) / 2 on the particle (the split of its kinetic-
      // energy change m dv . v_mid). Zero for a wall that holds a pressure without motion.
      double removed = 0.0;
      if (G.touches_boundary(s.base, N)) {
        Vec3 share = Vec3::Zero();
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j) {
            const int row = G.index(s.base[0] + i, s.base[1] + j, s.base[2]);
            const double wij = s.w[0][i] * s.w[1][j];
            for (int k = 0; k < N; ++k) share += wij * s.w[2][k] * G.bc_increment[row + k];
          }
        removed = -P.mass[p] * share.dot(P.v[p] + 0.5 * dv);
      }
      P.v[p] += dv;
      P.x[p] += dt * v_new;
      if (!fail && !(P.x[p].allFinite() && !outside(G, P.x[p])))
        fail = Failure{std::size_t(p), "position", "left the grid"};
      const Vec3& v = P.v[p];
      if (!fail && !v.allFinite()) fail = Failure{std::size_t(p), "velocity", "not finite"};
      const double m = P.mass[p];
      sum.kinetic_energy += 0.5 * m * v.squaredNorm();  // report eq. 13, end-of-step velocity
      sum.momentum += m * v;
      sum.max_speed = std::max(sum.max_speed, v.norm());
      sum.boundary_dissipation += removed;
    }
    partial[omp_get_thread_num()] = sum;
    failures[omp_get_thread_num()] = fail;
  }
  ParticleTotals total;
  for (int t = 0; t < nt; ++t) {  // thread order: deterministic
    total.kinetic_energy += partial[t].kinetic_energy;
    total.momentum += partial[t].momentum;
    total.max_speed = std::max(total.max_speed, partial[t].max_speed);
    total.boundary_dissipation += partial[t].boundary_dissipation;
    merge_failure(failure, failures[t]);
  }
  return total;
}

template <class Shape>
void remap_and_gradient(Particles& P, Grid& G, const Stencils<Shape>& S) {
  constexpr int N = Shape::N;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  const int nt = G.threads();
  G.clear_momentum();
#pragma omp parallel num_threads(nt)
  {
    Vec3* buf = G.momentum_buffer(omp_get_thread_num());
#pragma omp for schedule(static)
    for (std::ptrdiff_t p = 0; p < n; ++p) {
      const Stencil<N>& s = S[p];
      const Vec3 mv = P.mass[p] * P.v[p];
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
          Vec3* row = buf + G.index(s.base[0] + i, s.base[1] + j, s.base[2]);
          const Vec3 mvij = (s.w[0][i] * s.w[1][j]) * mv;
          for (int k = 0; k < N; ++k) row[k] += s.w[2][k] * mvij;
        }
    }
  }
  G.reduce_momentum();
  const std::vector<Vec3>& momentum = G.remapped_momentum();
  const int nn = G.node_count();
#pragma omp parallel for schedule(static) num_threads(nt)
  for (int i = 0; i < nn; ++i) {
    G.velocity_L[i] = G.mass[i] > 0.0 ? Vec3(momentum[i] / G.mass[i]) : Vec3::Zero();
  }
  G.apply_mirror(G.velocity_L, /*project_face=*/true);  // a projection, not a load
#pragma omp parallel for schedule(static) num_threads(nt)
  for (std::ptrdiff_t p = 0; p < n; ++p) P.L[p] = gradient(G, S[p], G.velocity_L, P.v[p]);
}

template ParticleTotals grid_to_particles<LinearShape>(Particles&, const Grid&,
                                                       const Stencils<LinearShape>&, double, bool,
                                                       std::optional<Failure>&);
template ParticleTotals grid_to_particles<GimpShape>(Particles&, const Grid&,
                                                     const Stencils<GimpShape>&, double, bool,
                                                     std::optional<Failure>&);
template void remap_and_gradient<LinearShape>(Particles&, Grid&, const Stencils<LinearShape>&);
template void remap_and_gradient<GimpShape>(Particles&, Grid&, const Stencils<GimpShape>&);

}  // namespace impact::mpm
