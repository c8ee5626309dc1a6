#include "mpm/step/scatter_order.hpp"

namespace impact::mpm {

template <int N>
void order_for_scatter(const std::vector<Stencil<N>>& S, const Grid& G, ScatterOrder& order) {
  constexpr int T = ScatterOrder::kBand;
  // Storage coordinates along x run from 0 (the first stored plane: the ghost layer, node -1,
  // on one rank) to the last stored plane.
  const int bands = (G.storage_x(G.stored().last[0]) + 1 + T - 1) / T;
  const int n = static_cast<int>(S.size());
  order.band_of.resize(n);
  order.start.assign(bands + 1, 0);
  for (int p = 0; p < n; ++p) {
    const int s = G.storage_x(S[p].base[0]) / T;
    order.band_of[p] = s;
    ++order.start[s + 1];
  }
  for (int s = 0; s < bands; ++s) order.start[s + 1] += order.start[s];
  order.particles.resize(n);
  order.next.assign(order.start.begin(), order.start.end() - 1);
  for (int p = 0; p < n; ++p) order.particles[order.next[order.band_of[p]]++] = p;
  for (std::vector<int>& c : order.colours) c.clear();
  for (int s = 0; s < bands; ++s)
    if (order.start[s + 1] > order.start[s]) order.colours[s % 2].push_back(s);
}

template void order_for_scatter<2>(const std::vector<Stencil<2>>&, const Grid&, ScatterOrder&);
template void order_for_scatter<3>(const std::vector<Stencil<3>>&, const Grid&, ScatterOrder&);

}  // namespace impact::mpm
