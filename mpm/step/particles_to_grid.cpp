// Stencils once per step, and particles to grid, Sulsky, Chen & Schreyer (1994) eqs. 20-22 (mass,
// momentum, internal force). Each thread scatters into its own grid buffer; Grid::reduce sums
// them in thread order (deterministic for a given thread count).
#include "mpm/step/parallel.hpp"

namespace impact::mpm {

template <class Shape>
void compute_stencils(const Particles& P, const Shape& shape, Stencils<Shape>& S, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  if (S.size() != P.size()) S.resize(P.size());  // once (the particle count is fixed)
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t p = 0; p < n; ++p) S[p] = shape.at(P.x[p], P.object[p]);
}

template <class Shape>
void particles_to_grid(const Particles& P, Grid& G, const Stencils<Shape>& S) {
  constexpr int N = Shape::N;
  G.clear();
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
#pragma omp parallel num_threads(G.threads())
  {
    NodeData* buf = G.buffer(omp_get_thread_num());
#pragma omp for schedule(static)
    for (std::ptrdiff_t p = 0; p < n; ++p) {
      const Stencil<N>& s = S[p];
      const Mat3 vs = -P.volume[p] * P.state[p].stress;  // -V_p sigma_p
      const double m = P.mass[p];
      const Vec3 mv = m * P.v[p];
      for (int i = 0; i < N; ++i) {
        for (int j = 0; j < N; ++j) {
          NodeData* row = buf + G.index(s.base[0] + i, s.base[1] + j, s.base[2]);
          const double wij = s.w[0][i] * s.w[1][j];
          const double dxw = s.dw[0][i] * s.w[1][j];
          const double wdy = s.w[0][i] * s.dw[1][j];
          // vs * grad = a * w_z + b * dw_z with a, b per (i, j)
          const Vec3 a = vs.col(0) * dxw + vs.col(1) * wdy;
          const Vec3 b = vs.col(2) * wij;
          for (int k = 0; k < N; ++k) {
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
    }
  }
  G.reduce();
}

template void compute_stencils<LinearShape>(const Particles&, const LinearShape&,
                                            Stencils<LinearShape>&, int);
template void compute_stencils<GimpShape>(const Particles&, const GimpShape&, Stencils<GimpShape>&,
                                          int);
template void particles_to_grid<LinearShape>(const Particles&, Grid&, const Stencils<LinearShape>&);
template void particles_to_grid<GimpShape>(const Particles&, Grid&, const Stencils<GimpShape>&);

}  // namespace impact::mpm
