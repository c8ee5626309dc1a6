#include "models/kinematics/corotation_batch.hpp"

namespace impact {

// One copy per instruction set (IMPACT_LANE_CLONES, lane_math.hpp).
IMPACT_LANE_CLONES void corotation_batch(CorotationBatch& batch) {
  batch.out = corotate_lanes(batch.R_old, batch.R_new, batch.stress, batch.D);
}

}  // namespace impact
