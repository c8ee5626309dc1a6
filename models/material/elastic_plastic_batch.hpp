// The vector kernels of UpdateBatch (update_batch.hpp) around the radial return: the trial
// deviator (step 2) and the heating, default_hypo pressure and rotation back (steps 3, 4 and 7)
// of kLaneWidth points at once, elastic_plastic_lanes.hpp on lane::Vec. Compiled per instruction
// set and chosen when the program loads, like johnson_cook_return_batch.
#pragma once

#include "models/kinematics/corotation_lanes.hpp"
#include "models/material/elastic_plastic_lanes.hpp"
#include "models/plasticity/radial_return.hpp"

namespace impact {

struct alignas(lane::kLaneBytes) UpdateLanes {
  // Inputs, per lane.
  MaterialLanes<lane::Vec> material;
  lane::Vec J_n{};      ///< det F_n
  lane::Vec J_1{};      ///< det F_{n+1}
  lane::Vec dt{};       ///< [s]
  lane::Vec T_n{};      ///< start-of-step temperature [K]
  lane::Vec e_n{};      ///< start-of-step specific internal energy [J/kg]
  lane::Vec plastic{};  ///< 1 where the return was plastic, else 0
  lane::Vec d_ep{};     ///< the return's plastic strain increment [-]
  lane::Vec flow{};     ///< the return's flow stress [Pa]
  // Outputs.
  TrialLanes<lane::Vec> trial;
  HeatingLanes<lane::Vec> heating;
  PressureLanes<lane::Vec> pressure;
  LaneMat3<lane::Vec> stress;  ///< working frame after finish_lanes, lab frame after rotate_back
  lane::Vec wave_speed{};      ///< with default_hypo's K_eff [m/s]
};

/// Step 2 from the un-rotated stress and rate of deformation: u.trial.
void trial_kernel(const CorotatedLanes<lane::Vec>& c, UpdateLanes& u);

/// Steps 3 and 4 after the return (u.plastic, u.d_ep, u.flow): the returned deviator, heating and
/// the default_hypo pressure; u.stress = s_{n+1} - p_{n+1} I in the working frame.
void finish_kernel(const CorotatedLanes<lane::Vec>& c, UpdateLanes& u);

/// Step 7: u.stress rotated back with R_{n+1}, and the wave speed at rho_{n+1}.
void rotate_back_kernel(const LaneMat3<lane::Vec>& R_new, UpdateLanes& u);

}  // namespace impact
