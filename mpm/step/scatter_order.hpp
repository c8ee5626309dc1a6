// The order of the scatters (particles to grid, the MUSL re-map): the particles grouped by the
// band of kBand node planes in x that their stencil starts in, and the bands in two colours, even
// and odd. A stencil reaches at most into the next band, so the bands of one colour, a band apart,
// write disjoint nodes: the threads scatter one colour at a time into one grid buffer, with no
// per-thread copies of the grid and no reduction.
//
// Each node's sum is then taken in one fixed order whatever the thread count and schedule: the
// even band's particles, then the odd one's, each by particle index. The scatters give the same
// bits on 1 or N threads (docs/mpm.md#threads-and-determinism). The grouping is a counting sort of
// indices each step (the particle arrays are not moved, so a particle keeps its index in output,
// faults and restarts). Why bands in x: the seeded order is x-major (and the particles keep it),
// so a band's particles are long runs of the arrays and its nodes are swept plane by plane as in
// index order; smaller tiles (4 x 4 nodes in x and y) re-load their halo nodes in another colour's
// pass and cost 9 % of a GIMP step (docs/notes/performance_history.md).
#pragma once

#include <omp.h>

#include <algorithm>
#include <array>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/shape/shape.hpp"

namespace impact::mpm {

struct ScatterOrder {
  /// Node planes per band: more than the stencil's reach (2 nodes beyond its base), and whole
  /// blocks of the active-block marks, so that the bands of one colour mark disjoint blocks too.
  static constexpr int kBand = 8;
  static_assert(kBand >= 3 && kBand % Grid::kBlock == 0);

  std::vector<int> particles;               ///< indices grouped by band, ascending within one
  std::vector<int> start;                   ///< band s holds particles[start[s], start[s + 1])
  std::array<std::vector<int>, 2> colours;  ///< the non-empty even and odd bands, ascending
  std::vector<int> band_of;                 ///< scratch: each particle's band
  std::vector<int> next;  ///< scratch: per thread, where its next particle of each band goes
};

/// Groups the particles by the band of their stencil's base node (every step, after the stencils):
/// a counting sort, each thread counting and then placing a contiguous range of the particles, so
/// the order is the same as one thread's.
template <int N>
void order_for_scatter(const std::vector<Stencil<N>>& S, const Grid& G, ScatterOrder& order);

/// body(p) for every particle, one colour after the other, the bands of a colour dealt to the
/// threads in contiguous runs of about equal particle counts (called inside no parallel region).
/// Contiguous in x, each thread's bands hold about the particles and nodes its share of the
/// static particle and node loops holds, so the data stays in its core's cache: dealt one band at
/// a time on demand, the recommended scene ran 6-8 % slower on 2 threads
/// (docs/performance.md). Each band is still one thread's, in index order: the same bits.
/// ahead(q) is called with the particle kAhead places further on in the band before body(p), so
/// that the body finds that particle's data in cache: a band's particles are runs of the arrays
/// with gaps, which the hardware prefetcher does not follow (P2G's first load of a particle's
/// stress took 12 % of the phase's samples without it; docs/performance.md).
template <class Body, class Ahead>
void scatter_by_colour(const ScatterOrder& order, int threads, Body&& body, Ahead&& ahead) {
  constexpr int kAhead = 4;
#pragma omp parallel num_threads(threads)
  {
    const long t = omp_get_thread_num(), team = omp_get_num_threads();
    for (const std::vector<int>& bands : order.colours) {
      const int n = static_cast<int>(bands.size());
      long total = 0;
      for (const int s : bands) total += order.start[s + 1] - order.start[s];
      // Band i is thread t's where the midpoint of its particles falls in t's equal share of
      // the colour's particles: contiguous runs, one per thread.
      long before = 0;
      for (int i = 0; i < n; ++i) {
        const int s = bands[i];
        const long count = order.start[s + 1] - order.start[s];
        const long owner =
            total > 0 ? std::min(team - 1, (2 * before + count) * team / (2 * total)) : 0;
        before += count;
        if (owner != t) continue;
        const int end = order.start[s + 1];
        for (int k = order.start[s]; k < end; ++k) {
          if (k + kAhead < end) ahead(order.particles[k + kAhead]);
          body(order.particles[k]);
        }
      }
#pragma omp barrier
    }  // a colour is complete before the next starts
  }
}

/// Brings a stencil (160 B with uGIMP: three cache lines) towards the core, for an `ahead` hook.
template <int N>
inline void prefetch_stencil(const Stencil<N>& s) {
  const char* const bytes = reinterpret_cast<const char*>(&s);
  for (std::size_t at = 0; at < sizeof(Stencil<N>); at += 64) __builtin_prefetch(bytes + at);
}

template <class Body>
void scatter_by_colour(const ScatterOrder& order, int threads, Body&& body) {
  scatter_by_colour(order, threads, body, [](int) {});
}

}  // namespace impact::mpm
