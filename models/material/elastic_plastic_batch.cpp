#include "models/material/elastic_plastic_batch.hpp"

namespace impact {

// One copy per instruction set (IMPACT_LANE_CLONES, lane_math.hpp).
IMPACT_LANE_CLONES void trial_kernel(const CorotatedLanes<lane::Vec>& c, UpdateLanes& u) {
  u.trial =
      trial_lanes(c.stress, c.D, u.J_n, u.J_1, u.material.density, u.material.shear_modulus, u.dt);
}

IMPACT_LANE_CLONES void finish_kernel(const CorotatedLanes<lane::Vec>& c, UpdateLanes& u) {
  const MaterialLanes<lane::Vec>& m = u.material;
  const lane::Vec three_mu = 3.0 * m.shear_modulus;
  const LaneMat3<lane::Vec> s =
      returned_deviator(u.trial.s_trial, u.trial.q_trial, three_mu, u.d_ep, u.plastic > 0.0);
  u.heating = heating_lanes(m, u.flow, u.d_ep, u.trial.rho1, u.T_n);
  u.pressure = hypo_pressure_lanes(m.hypo_bulk_modulus, u.trial.p_n, lane_algebra::trace(c.D), u.dt,
                                   u.e_n, u.trial.rho0_n, u.trial.rho1, u.heating.heat_per_mass);
  u.stress = with_pressure(s, u.pressure.pressure);
}

IMPACT_LANE_CLONES void rotate_back_kernel(const LaneMat3<lane::Vec>& R_new, UpdateLanes& u) {
  u.stress = lane_algebra::rotate_symmetric(u.stress, R_new);
  u.wave_speed =
      longitudinal_wave_speed(u.material.hypo_bulk_modulus, u.material.shear_modulus, u.trial.rho1);
}

}  // namespace impact
