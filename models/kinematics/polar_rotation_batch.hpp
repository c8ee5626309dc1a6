// The warm-started polar rotation of kLaneWidth points at once (polar_rotation_lanes.hpp on
// lane::Vec), compiled for AVX-512, AVX2 and SSE2 and chosen when the program loads, like the
// batched radial return (models/plasticity/johnson_cook_return_batch.hpp). A lane that did not
// converge from its warm start (converged = 0) is the caller's to finish with polar_rotation, which
// then falls back to the cold decomposition exactly as for a single point.
#pragma once

#include "models/kinematics/polar_rotation_lanes.hpp"

namespace impact {

struct alignas(lane::kLaneBytes) PolarRotationBatch {
  LaneMat3<lane::Vec> F;      ///< F_{n+1} of each lane
  LaneMat3<lane::Vec> guess;  ///< R_n of each lane
  PolarLanes<lane::Vec> out;
};

void polar_rotation_batch(PolarRotationBatch& batch);

}  // namespace impact
