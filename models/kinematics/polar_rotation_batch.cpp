#include "models/kinematics/polar_rotation_batch.hpp"

namespace impact {

// One copy per instruction set (IMPACT_LANE_CLONES, lane_math.hpp).
IMPACT_LANE_CLONES void polar_rotation_batch(PolarRotationBatch& batch) {
  batch.out = polar_rotation_lanes(batch.F, batch.guess);
}

}  // namespace impact
