// Fixed sets of particles named by seed index (a gauge's members, a crater's face layer), found
// among the particles a rank holds: on one rank in seed order the seed index is the array index;
// on several (and in a shuffled store, solver.shuffle_particles) each rank finds its members by
// Particles::id once per output row, with
// one binary search per particle it holds into the sets' union (small: a few layers of cells).
#pragma once

#include <cstdint>
#include <vector>

#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"

namespace impact::mpm {

class ParticleSets {
 public:
  /// A member found here: `p` in the rank's arrays, `i` its place in the set's (sorted) ids.
  struct Member {
    std::size_t p, i;
  };
  /// Adds a set: the seed indices `local` this rank selected from the particles it holds,
  /// gathered from every rank (collective) and sorted. Returns the set's index.
  std::size_t add(const std::vector<std::uint64_t>& local, const Communicator& comm);
  /// Adds a set whose seed indices are already every rank's (not collective).
  std::size_t add(std::vector<std::uint64_t> ids);
  /// The seed indices of set s, ascending.
  const std::vector<std::uint64_t>& ids(std::size_t s) const { return sets_[s]; }
  /// Per set, the members P holds, in P's order (in seed order: ascending seed index).
  std::vector<std::vector<Member>> find(const Particles& P) const;

 private:
  std::vector<std::vector<std::uint64_t>> sets_;
  // Every set's ids together, sorted, each with the sets it belongs to (CSR: owners_ from
  // first_owner_[k] to first_owner_[k + 1]).
  std::vector<std::uint64_t> union_;
  std::vector<std::size_t> first_owner_, owners_;
};

}  // namespace impact::mpm
