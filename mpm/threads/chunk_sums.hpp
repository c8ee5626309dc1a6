// Sums over a parallel loop that are the same bits on any thread count. The loop's items are cut
// into chunks of a fixed size; whichever thread runs a chunk sums it into that chunk's own slot,
// and the slots are added in chunk order afterwards. A per-thread partial sum depends on where the
// thread's share starts, and so on the thread count; a chunk's does not. The ledger's sums over
// particles (grid-to-particles, the stress update) and over nodes (contact) are taken so, and the
// history is identical on 1, 2 or 3 threads (tests/mpm/simulation/determinism_test.cpp;
// docs/reliability.md).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace impact::mpm {

template <class Sum>
class ChunkSums {
 public:
  /// Items [0, items) in chunks of `chunk_items` (the last one shorter), each with a zeroed Sum.
  ChunkSums(std::ptrdiff_t items, std::ptrdiff_t chunk_items)
      : items_(items),
        chunk_items_(chunk_items),
        sums_(static_cast<std::size_t>((items + chunk_items - 1) / chunk_items)) {}

  std::ptrdiff_t chunks() const { return static_cast<std::ptrdiff_t>(sums_.size()); }
  /// The chunk's items are [begin(chunk), end(chunk)).
  std::ptrdiff_t begin(std::ptrdiff_t chunk) const { return chunk * chunk_items_; }
  std::ptrdiff_t end(std::ptrdiff_t chunk) const {
    return std::min(items_, (chunk + 1) * chunk_items_);
  }
  /// The chunk's own sum: only the thread that runs the chunk writes it.
  Sum& operator[](std::ptrdiff_t chunk) { return sums_[static_cast<std::size_t>(chunk)]; }

  /// Hands every chunk's sum to `add`, in chunk order.
  template <class Add>
  void add_in_order(Add&& add) const {
    for (const Sum& s : sums_) add(s);
  }

 private:
  std::ptrdiff_t items_;
  std::ptrdiff_t chunk_items_;
  std::vector<Sum> sums_;
};

}  // namespace impact::mpm
