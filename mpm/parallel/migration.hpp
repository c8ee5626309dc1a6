// Particles moving between ranks (docs/mpi.md): after a step, a particle whose cell another rank
// owns (BoxDecomposition) goes to that rank whole, with every per-particle array
// (Particles::for_each_array: position, velocity, mass, volumes, velocity gradient, the whole
// PointState, wave speed, material, object, velocity field, viscosity, fault and removal flags,
// id). The leaving particles are cut out in order and the arriving ones appended in the order of
// their senders' ranks, so the arrays' order, and with it every sum over them, is the same in
// every run with the same rank count.
#pragma once

#include <cstddef>
#include <vector>

#include "mpm/parallel/box_decomposition.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

struct MigrationCounts {
  std::size_t sent = 0;
  std::size_t received = 0;
};

/// Particles per cell along each axis (what BoxDecomposition::balanced splits): of P alone, or
/// with `comm` summed over the ranks.
AxisCounts axis_counts(const Particles& P, const GridSpec& grid, const Communicator& comm);

/// Keeps on this rank the particles of its box; sends the others to their owners.
MigrationCounts migrate(Particles& P, const BoxDecomposition& boxes, const GridSpec& grid,
                        const Communicator& comm);

/// Every rank's particles on rank 0, in seed order (ascending id), as one rank would hold them
/// (the outputs of a run on several ranks: gauges, observables, snapshots, summary); empty on the
/// other ranks.
Particles gather_particles(const Particles& local, const Communicator& comm);

}  // namespace impact::mpm
