// The arithmetic of an elastic_plastic step around its radial return (elastic_plastic.hpp, steps
// 2-4 and 7), for one point (V = double) or a vector of points (V = lane::Vec): one source, so
// that ElasticPlastic::update (the point driver's path) and UpdateBatch (the MPM's) give a point
// the same bits. Branch-free in the points' values: a heated and an unheated lane, an elastic and
// a plastic one, go through the same instructions with selects.
#pragma once

#include "models/core/lane_mat3.hpp"
#include "models/eos/default_hypo.hpp"  // hypo_pressure_lanes, step 4

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace impact {

/// Per-lane material constants (lanes of one batch may belong to different materials).
template <class V>
struct alignas(lane::kLaneBytes) MaterialLanes {
  V density{};            ///< rho0 [kg/m^3]
  V shear_modulus{};      ///< mu [Pa]
  V hypo_bulk_modulus{};  ///< K_eff of default_hypo (default_hypo_effective_bulk_modulus) [Pa]
  V heating{};            ///< 1 when adiabatic heating is on, else 0
  V taylor_quinney{};     ///< chi [-]
  V specific_heat{};      ///< cp [J/(kg K)]
};

/// The deviatoric trial of step 2 and the densities, from the old stress and the rate of
/// deformation in the working frame.
template <class V>
struct alignas(lane::kLaneBytes) TrialLanes {
  LaneMat3<V> s_trial;  ///< s_n + 2 mu dev(D) dt (report eq. 4) [Pa]
  V q_trial{};          ///< sqrt(3/2 s_tr:s_tr) [Pa]
  V p_n{};              ///< start-of-step pressure -tr(sigma_n)/3 [Pa]
  V rho0_n{};           ///< start-of-step density rho0 / J_n [kg/m^3]
  V rho1{};             ///< end-of-step density rho0 / J_{n+1} [kg/m^3]
};

template <class V>
[[gnu::always_inline]] inline TrialLanes<V> trial_lanes(const LaneMat3<V>& stress_n,
                                                        const LaneMat3<V>& D_hat, V J_n, V J_1,
                                                        V density, V shear_modulus, V dt) {
  using namespace lane_algebra;
  TrialLanes<V> t;
  t.rho0_n = density / J_n;
  t.rho1 = density / J_1;
  t.p_n = -(trace(stress_n) / 3.0);
  const LaneMat3<V> s = deviator(stress_n), e = deviator(D_hat);
  const V two_mu_dt = 2.0 * shear_modulus * dt;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.s_trial.a[i][j] = s.a[i][j] + two_mu_dt * e.a[i][j];
  t.q_trial = equivalent_of_deviator(t.s_trial);
  return t;
}

/// s_{n+1} = s_tr (1 - 3 mu d / q_tr) on a plastic lane with d > 0, else s_tr (radial_return.hpp,
/// finish_return: the same expression).
template <class V>
[[gnu::always_inline]] inline LaneMat3<V> returned_deviator(const LaneMat3<V>& s_trial, V q_trial,
                                                            V three_mu, V d_ep,
                                                            lane::MaskOf<V> plastic) {
  const auto scaled = plastic & (d_ep > 0.0);
  const V factor = lane::select<V>(scaled, V(1.0 - three_mu * d_ep / q_trial), 1.0);
  LaneMat3<V> s;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      s.a[i][j] = lane::select<V>(scaled, V(s_trial.a[i][j] * factor), s_trial.a[i][j]);
  return s;
}

/// Step 3, adiabatic heating (report eq. 8): the plastic work sigma_y d_ep per unit volume, and,
/// with heating on and d_ep > 0, the Taylor-Quinney share of it retained as heat.
template <class V>
struct alignas(lane::kLaneBytes) HeatingLanes {
  V plastic_work{};      ///< sigma_y d_ep [J/m^3]
  V heat_per_mass{};     ///< chi sigma_y d_ep / rho_{n+1} [J/kg]
  V temperature_rise{};  ///< chi sigma_y d_ep / (rho_{n+1} cp) [K]
  V temperature{};       ///< T_{n+1} [K]
};

template <class V>
[[gnu::always_inline]] inline HeatingLanes<V> heating_lanes(const MaterialLanes<V>& m, V flow,
                                                            V d_ep, V rho1, V T0) {
  HeatingLanes<V> h;
  h.plastic_work = flow * d_ep;
  const auto heated = (m.heating > 0.0) & (d_ep > 0.0);
  h.heat_per_mass = lane::select<V>(heated, V(m.taylor_quinney * h.plastic_work / rho1), 0.0);
  // adiabatic_temperature_rise (models/thermal/adiabatic_heating.hpp), written out for lanes.
  h.temperature_rise =
      lane::select<V>(heated, V(m.taylor_quinney * flow * d_ep / (rho1 * m.specific_heat)), 0.0);
  h.temperature = lane::select<V>(heated, V(T0 + h.temperature_rise), T0);
  return h;
}

/// s - p I.
template <class V>
[[gnu::always_inline]] inline LaneMat3<V> with_pressure(const LaneMat3<V>& s, V pressure) {
  LaneMat3<V> stress = s;
  for (int i = 0; i < 3; ++i) stress.a[i][i] = s.a[i][i] - pressure;
  return stress;
}

/// Longitudinal wave speed sqrt((K + 4 mu/3) / rho) [m/s].
template <class V>
[[gnu::always_inline]] inline V longitudinal_wave_speed(V bulk_modulus, V shear_modulus, V rho) {
  return lane::sqrt(V((bulk_modulus + 4.0 * shear_modulus / 3.0) / rho));
}

}  // namespace impact

#pragma GCC diagnostic pop
