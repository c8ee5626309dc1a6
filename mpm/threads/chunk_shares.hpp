// Chunks of a particle loop dealt as contiguous shares, one per thread, and balanced at the end by
// stealing. A thread takes its own share's chunks from the front, so it keeps the particles the
// static split of the other phases gave it (their data stay in its cache); once its share is done
// it takes the last chunk of the share with the most left. The stress update's cost is uneven
// (a plastic point's radial return costs several times an elastic one's, and an impact's plastic
// points are neighbours in the arrays), so a static split leaves one thread waiting; chunks dealt
// round the threads balanced it but moved the particles between the cores' caches
// (docs/performance.md, issue 57). Which thread takes a chunk varies from run to run: anything
// summed over the chunks is summed per chunk and then in chunk order.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace impact::mpm {

class ChunkShares {
 public:
  /// Chunks [0, count) in `threads` contiguous shares of (nearly) equal length.
  ChunkShares(std::ptrdiff_t count, int threads) : shares_(static_cast<std::size_t>(threads)) {
    for (int t = 0; t < threads; ++t)
      shares_[t].range.store(pack(count * t / threads, count * (t + 1) / threads),
                             std::memory_order_relaxed);
  }

  /// The next chunk for `thread` (its own share's front first, then another share's back), or -1
  /// when every share is empty. Each chunk is returned exactly once.
  std::ptrdiff_t next(int thread) {
    const std::ptrdiff_t own = take(shares_[thread], /*front=*/true);
    if (own >= 0) return own;
    for (;;) {  // steal from the share with the most left; none left: done
      Share* victim = nullptr;
      std::uint64_t most = 0;
      for (Share& s : shares_) {
        const std::uint64_t r = s.range.load(std::memory_order_relaxed);
        if (back(r) > front(r) && back(r) - front(r) > most) {
          most = back(r) - front(r);
          victim = &s;
        }
      }
      if (victim == nullptr) return -1;
      const std::ptrdiff_t stolen = take(*victim, /*front=*/false);
      if (stolen >= 0) return stolen;
    }
  }

 private:
  // One word per share, [front, back) packed as front | back << 32, so that its owner (at the
  // front) and a thief (at the back) claim chunks by one compare-and-swap and never both take the
  // last one.
  struct alignas(64) Share {
    std::atomic<std::uint64_t> range{0};
  };
  static std::uint64_t pack(std::ptrdiff_t f, std::ptrdiff_t b) {
    return static_cast<std::uint64_t>(f) | static_cast<std::uint64_t>(b) << 32;
  }
  static std::uint64_t front(std::uint64_t r) { return r & 0xffffffffu; }
  static std::uint64_t back(std::uint64_t r) { return r >> 32; }
  static std::ptrdiff_t take(Share& s, bool at_front) {
    std::uint64_t r = s.range.load(std::memory_order_relaxed);
    while (front(r) < back(r)) {
      const std::uint64_t claimed =
          at_front ? pack(front(r) + 1, back(r)) : pack(front(r), back(r) - 1);
      if (s.range.compare_exchange_weak(r, claimed, std::memory_order_relaxed))
        return static_cast<std::ptrdiff_t>(at_front ? front(r) : back(r) - 1);
    }
    return -1;
  }

  std::vector<Share> shares_;
};

}  // namespace impact::mpm
