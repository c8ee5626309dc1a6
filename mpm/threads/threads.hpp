// The OpenMP threads of the particle loops: the per-thread partial sums' bound (the loops partition
// [0, n) statically, so their sums are deterministic for a given thread count) and the
// first-failure merge (sums that must not depend on the thread count: chunk_sums.hpp).
#pragma once

#include <omp.h>

#include <optional>

namespace impact::mpm {

/// Per-thread partial sums live in fixed arrays of this size (no allocation in a step); the
/// Simulation caps its thread count at it.
inline constexpr int kMaxThreads = 256;

/// Keeps the failure that comes first by `before` (the lower seed index: deterministic whichever
/// thread saw it and whatever the storage order).
template <class Failure, class Before>
inline void merge_failure(std::optional<Failure>& into, const std::optional<Failure>& f,
                          Before&& before) {
  if (f && (!into || before(*f, *into))) into = f;
}

}  // namespace impact::mpm
