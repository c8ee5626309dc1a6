// The Green-Naghdi un-rotations of kLaneWidth points at once (corotation_lanes.hpp on lane::Vec),
// compiled per instruction set like polar_rotation_batch. A `wide` lane (a step rotation beyond
// ~151 degrees) is the caller's to finish with corotate, which takes the polar factor of the mean
// rotation there exactly as for a single point.
#pragma once

#include "models/kinematics/corotation_lanes.hpp"

namespace impact {

struct alignas(lane::kLaneBytes) CorotationBatch {
  LaneMat3<lane::Vec> R_old;   ///< R_n of each lane
  LaneMat3<lane::Vec> R_new;   ///< R_{n+1}
  LaneMat3<lane::Vec> stress;  ///< sigma_n (symmetric)
  LaneMat3<lane::Vec> D;       ///< sym L (symmetric)
  CorotatedLanes<lane::Vec> out;
};

void corotation_batch(CorotationBatch& batch);

}  // namespace impact
