// What the seeding made of each body, checked once the particles exist: `mpm check` and `mpm run`
// warn of a body whose particles hold a volume far from the part of its geometry they should fill.
#pragma once

#include <string>
#include <vector>

#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// Beyond this relative difference between a body's particle volume and the volume they should
/// fill, the body is warned of. The shipped scenes seed within 3.3 % (a sphere of 4 cells per
/// radius: 1.032); a block whose faces cut a graded gap's coarse cells held 0.80.
inline constexpr double kSeedingVolumeTolerance = 0.05;

/// One warning per body whose particles hold a volume more than kSeedingVolumeTolerance off the
/// part of its geometry they should fill: inside the grid and not in an earlier object, in the
/// particles' own measure (revolved on rings about x, per metre of thickness in plane strain;
/// seeding_check.cpp fill_volume). The seeding's staircase: a particle at a sub-cell centre inside
/// the body takes the whole sub-cell, so faces that cut coarse cells gain or lose up to half a
/// sub-cell each. P: the particles this rank holds (the sums are over the ranks).
std::vector<std::string> seeding_warnings(const Scene& scene, const Particles& P,
                                          const Communicator& comm);

}  // namespace impact::mpm
