// Storage orders of the particles (Particles::permute applies one). The seeded order is a cell
// sort already (docs/performance.md); a shuffled order exists to measure how much a scene's
// results depend on the order of the sums over particles (solver.shuffle_particles,
// campaigns/benchmark/result_bounds.py --ensemble, issue 57).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace impact::mpm {

struct Particles;

/// A pseudo-random permutation of 0 .. n - 1 drawn with `seed`, the same on every machine and
/// library: a Fisher-Yates shuffle driven by std::mt19937_64, whose output sequence the C++
/// standard fixes, with draws bounded by rejection (std::shuffle and the standard distributions
/// are implementation-defined).
std::vector<std::size_t> shuffled_order(std::size_t n, std::uint64_t seed);

/// Stores P in `order` (Particles::permute), keeping each particle's seed index in P.id (filled
/// with the array index first where it is not kept yet): the outputs name particles by it.
void store_in_order(Particles& P, const std::vector<std::size_t>& order);

}  // namespace impact::mpm
