#include "mpm/step/scatter_order.hpp"

#include <omp.h>

namespace impact::mpm {

template <int N>
void order_for_scatter(const std::vector<Stencil<N>>& S, const Grid& G, ScatterOrder& order) {
  constexpr int T = ScatterOrder::kBand;
  // Storage coordinates along x run from 0 (the first stored plane: the ghost layer, node -1,
  // on one rank) to the last stored plane.
  const int bands = (G.storage_x(G.stored().last[0]) + 1 + T - 1) / T;
  const int n = static_cast<int>(S.size());
  // Each thread's row of band counts, then of fill positions, a whole number of cache lines apart.
  const int row = (bands + 15) / 16 * 16;
  const int nt = G.threads();
  order.band_of.resize(n);
  order.start.assign(bands + 1, 0);
  order.particles.resize(n);
  order.next.assign(static_cast<std::size_t>(row) * nt, 0);
#pragma omp parallel num_threads(nt)
  {
    // Contiguous ranges in thread order: thread t's particles precede thread t + 1's in every
    // band, so filling the bands range by range keeps each band in ascending index order.
    const int t = omp_get_thread_num(), team = omp_get_num_threads();
    const int lo = static_cast<int>(static_cast<long>(n) * t / team);
    const int hi = static_cast<int>(static_cast<long>(n) * (t + 1) / team);
    int* const mine = order.next.data() + static_cast<std::size_t>(row) * t;
    for (int p = lo; p < hi; ++p) {
      const int s = G.storage_x(S[p].base[0]) / T;
      order.band_of[p] = s;
      ++mine[s];
    }
#pragma omp barrier
#pragma omp single
    {  // counts -> the bands' starts and each thread's first position in each band
      int at = 0;
      for (int s = 0; s < bands; ++s) {
        order.start[s] = at;
        for (int u = 0; u < team; ++u) {
          int& slot = order.next[static_cast<std::size_t>(row) * u + s];
          const int count = slot;
          slot = at;
          at += count;
        }
      }
      order.start[bands] = at;
    }  // the single's barrier: every position is set
    for (int p = lo; p < hi; ++p) order.particles[mine[order.band_of[p]]++] = p;
  }
  for (std::vector<int>& c : order.colours) c.clear();
  for (int s = 0; s < bands; ++s)
    if (order.start[s + 1] > order.start[s]) order.colours[s % 2].push_back(s);
}

template void order_for_scatter<2>(const std::vector<Stencil<2>>&, const Grid&, ScatterOrder&);
template void order_for_scatter<3>(const std::vector<Stencil<3>>&, const Grid&, ScatterOrder&);

}  // namespace impact::mpm
