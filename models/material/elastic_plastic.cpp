#include "models/material/elastic_plastic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/kinematics/polar_decomposition.hpp"

namespace impact {

std::string_view to_string(UpdateStatus s) {
  switch (s) {
    case UpdateStatus::ok:
      return "ok";
    case UpdateStatus::negative_jacobian:
      return "negative Jacobian det F <= 0";
    case UpdateStatus::non_finite_deformation_gradient:
      return "deformation gradient F or det F not finite: it overflowed (L dt too large; take a "
             "smaller step)";
    case UpdateStatus::return_mapping_not_converged:
      return "radial return did not converge";
    case UpdateStatus::non_finite_stress:
      return "non-finite stress";
    case UpdateStatus::eos_out_of_range:
      return "compression beyond the Mie-Gruneisen limit";
    case UpdateStatus::non_finite_wave_speed:
      return "no wave speed: the equation of state's K_s + 4 mu/3 <= 0 (tension beyond its range), "
             "or a neo_hookean solid strained past strong ellipticity";
  }
  return "unknown";
}

std::string_view to_string(FailureCause c) {
  switch (c) {
    case FailureCause::none:
      return "none";
    case FailureCause::melting:
      return "melting";
    case FailureCause::tepla:
      return "tepla";
    case FailureCause::drucker:
      return "drucker";
    case FailureCause::becker:
      return "becker";
  }
  return "unknown";
}

PointState ElasticPlastic::initial_state(double temperature) const {
  PointState s;
  s.temperature = temperature;
  s.porosity = p_.tepla.initial_porosity;
  return s;
}

double ElasticPlastic::wave_speed(const PointState& s) const {
  if (hyperelastic()) return neo_hookean_wave_speed(s.F, neo_hookean_moduli(), p_.density);
  return wave_speed(p_.density / lane_algebra::determinant(to_lanes(s.F)), s.internal_energy,
                    shear_modulus_of(s));
}

double ElasticPlastic::melting_temperature_of(const PointState& s) const {
  if (p_.melting.curve == MeltingCurve::constant) return p_.melt_temperature;
  return melting_temperature(p_.melting, p_.melt_temperature,
                             1.0 / lane_algebra::determinant(to_lanes(s.F)));
}

bool ElasticPlastic::molten(const PointState& s) const {
  return p_.melting.do_melting && is_melted(s.temperature, melting_temperature_of(s));
}

double ElasticPlastic::shear_modulus_of(const PointState& s) const {
  if (is_constant(p_.shear_modulus_model)) return p_.shear_modulus;
  const double J = lane_algebra::determinant(to_lanes(s.F));
  const double melt = melting_temperature_of(s);
  // With melting off the point stays solid above T_m, so a form that vanishes at melting
  // (Nadal-Le Poac, SCG's floor) is held at its value at T_m: a solid whose modulus went to zero
  // under a standing deviatoric stress would turn that stress into an unbounded plastic strain
  // (the return's increment is the overstress over 3 mu) and heat without limit.
  const double T = p_.melting.do_melting ? s.temperature : std::min(s.temperature, melt);
  return shear_modulus(p_.shear_modulus_model, p_.shear_modulus,
                       {T, -s.stress.trace() / 3.0, 1.0 / J, p_.density / J, melt});
}

double ElasticPlastic::wave_speed(double rho, double internal_energy) const {
  return wave_speed(rho, internal_energy, p_.shear_modulus);
}

double ElasticPlastic::wave_speed(double rho, double internal_energy, double mu) const {
  // The neo-Hookean solid at rest, or any state's estimate before its first step:
  // sqrt((lambda + 2 mu) / rho) (the state's own bound is wave_speed(state)).
  if (hyperelastic()) return longitudinal_wave_speed(p_.bulk_modulus, mu, rho);
  const double bulk = eos_bulk_modulus(p_.equation_of_state, eos_material(), rho, internal_energy);
  if (!(bulk + 4.0 * mu / 3.0 > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return longitudinal_wave_speed(bulk, mu, rho);
}

bool ElasticPlastic::begin_update(const PointState& s0, const Mat3& L, const Mat3& F1, double dt,
                                  PointState& s1, UpdateTrial& t, StepReport& report,
                                  const Corotated* corotated) const {
  report = StepReport{};
  const double J1 = lane_algebra::determinant(to_lanes(F1));
  if (!F1.allFinite() || std::isinf(J1)) {  // NaN or Inf would read as a negative Jacobian
    report.status = UpdateStatus::non_finite_deformation_gradient;
    return false;
  }
  if (!(J1 > 0.0)) {
    report.status = UpdateStatus::negative_jacobian;
    return false;
  }
  s1 = s0;
  s1.F = F1;
  s1.melted = false;
  t.hyperelastic = false;  // a batch reuses its trials: a neo_hookean lane's flag must not stay
  if (hyperelastic()) {    // sigma(F1), and the stored energy per unit mass as e
    const NeoHookeanModuli m = neo_hookean_moduli();
    s1.stress = neo_hookean_stress(F1, m);
    s1.internal_energy = neo_hookean_energy(F1, m) / p_.density;
    t.hyperelastic = true;
    t.batched = false;
    t.rho1 = p_.density / J1;
    report.wave_speed = neo_hookean_wave_speed(F1, m, p_.density);
    if (!s1.stress.allFinite())
      report.status = UpdateStatus::non_finite_stress;
    else if (!std::isfinite(report.wave_speed))
      report.status = UpdateStatus::non_finite_wave_speed;
    return true;
  }

  // 1. Kinematics: work in the unrotated frame (Green-Naghdi) or in the lab frame after a
  //    Hughes-Winget rotation of the old stress (Jaumann).
  const Mat3 D = sym(L);
  Mat3 stress_n;  // old stress in the working frame
  if (p_.objective_rate == ObjectiveRate::green_naghdi) {
    const Corotated c =
        corotated ? *corotated : corotate(s0.R, polar_rotation(F1, s0.R), s0.stress, D);
    stress_n = c.stress;
    t.D_hat = c.D;
    t.R_out = c.R_new;
    s1.R = c.R_new;
  } else if (p_.objective_rate == ObjectiveRate::green_naghdi_incremental) {
    const Corotation c = incremental_corotation(s0.R, s0.F, F1, L, dt);
    stress_n = unrotate(s0.stress, c.R_old);
    t.D_hat = unrotate(D, c.R_mid);
    t.R_out = c.R_new;
    s1.R = c.R_new;
  } else {
    // Midpoint form: the increment C:D dt is added in the mid-step orientation, between two
    // half-step Hughes-Winget rotations, sigma_{n+1} = Q_h (Q_h sigma_n Q_h^T + C:D dt) Q_h^T.
    // Adding it after a full-step rotation drops the commutator [W, C:D] dt^2 / 2 per step and is
    // only first order (docs/theory.md).
    const Mat3 Qh = hughes_winget_rotation(skew(L), 0.5 * dt);
    stress_n = rotate(s0.stress, Qh);
    t.D_hat = D;
    t.R_out = Qh;
  }

  // 2. Deviatoric trial (eq. 4) at the start-of-step temperature; the radial return (eq. 5-6)
  //    follows, for one point (update) or a batch (UpdateBatch).
  //    The shear modulus at the start-of-step temperature, pressure and density.
  const double J_n = lane_algebra::determinant(to_lanes(s0.F));
  t.shear_modulus = shear_modulus_of(s0);
  const TrialLanes<double> trial = trial_lanes<double>(to_lanes(stress_n), to_lanes(t.D_hat), J_n,
                                                       J1, p_.density, t.shear_modulus, dt);
  t.s_trial = to_mat3(trial.s_trial);
  t.q_trial = trial.q_trial;
  t.p_n = trial.p_n;
  t.rho0_n = trial.rho0_n;
  t.rho1 = trial.rho1;
  // One melting temperature for the step: the melting check's and the flow stress's (PTW's T^).
  const double melt_temperature = melting_temperature_of(s0);
  t.molten = p_.melting.do_melting && is_melted(s0.temperature, melt_temperature);
  const auto* jc = std::get_if<JohnsonCookParams>(&p_.flow_stress);
  if (jc) t.thermal = johnson_cook_thermal(*jc, s0.temperature);
  t.conditions = {s0.temperature,   t.p_n,           t.rho1 / p_.density, t.rho1, s0.plastic_strain,
                  s0.flow_internal, melt_temperature};
  t.batched = jc && !t.molten && p_.return_algorithm == ReturnAlgorithm::newton;
  return true;
}

ReturnResult ElasticPlastic::unbatched_return(const PointState& s0, const UpdateTrial& t,
                                              double dt) const {
  ReturnResult r;
  if (t.hyperelastic) return r;
  if (t.molten) {  // no deviatoric strength once molten; the EOS still acts
    r.deviator = Mat3::Zero();
    return r;
  }
  const Mat3 eta = deviator(t.D_hat);
  const double eta_norm = std::sqrt(2.0 / 3.0 * ddot(eta, eta));
  if (const auto* jc = std::get_if<JohnsonCookParams>(&p_.flow_stress)) {
    // Newton's return here is return_values on one double: the arithmetic of a batch's lane.
    const JohnsonCookAtTemperature flow_at{*jc, t.thermal};
    return radial_return(t.s_trial, t.shear_modulus, s0.plastic_strain, dt, flow_at,
                         p_.return_algorithm, eta_norm, p_.return_tolerance,
                         s0.plastic_strain_rate * dt);
  }
  // Any other law at the step's conditions (no increment bound: Newton starts from the elastic
  // one).
  const auto flow_at = [&](double ep, double rate) {
    return flow_stress(p_.flow_stress, ep, rate, t.conditions);
  };
  return radial_return(t.s_trial, t.shear_modulus, s0.plastic_strain, dt, flow_at,
                       p_.return_algorithm, eta_norm, p_.return_tolerance,
                       s0.plastic_strain_rate * dt);
}

StepReport ElasticPlastic::update(const PointState& s0, const Mat3& L, const Mat3& F1, double dt,
                                  PointState& s1) const {
  StepReport report;
  UpdateTrial t;
  if (!begin_update(s0, L, F1, dt, s1, t, report)) return report;
  finish_update(s0, t, unbatched_return(s0, t, dt), dt, s1, report);
  return report;
}

void ElasticPlastic::finish_update(const PointState& s0, const UpdateTrial& t,
                                   const ReturnResult& r, double dt, PointState& s1,
                                   StepReport& report) const {
  if (t.hyperelastic) return;  // begin_update wrote the end state
  const double rho1 = t.rho1;
  const double T0 = s0.temperature;
  s1.melted = t.molten;
  report.return_iterations = r.iterations;
  if (!r.converged) report.status = UpdateStatus::return_mapping_not_converged;
  const double d_ep = r.delta_plastic_strain;
  report.plastic = r.plastic;
  s1.plastic_strain = s0.plastic_strain + d_ep;
  s1.plastic_strain_rate = d_ep / dt;
  // A law's internal variable follows the increment by the expression its flow stress used.
  if (d_ep > 0.0) {
    s1.flow_internal =
        flow_internal_after(p_.flow_stress, s0.flow_internal, d_ep, d_ep / dt, t.conditions);
  }

  // 3. Adiabatic heating (eq. 8): the Taylor-Quinney fraction of the plastic work, retained by the
  //    point only when heating is on (off: isothermal, the heat leaves; docs/theory.md sec. 5).
  const MaterialLanes<double> m = material_lanes<double>();
  const HeatingLanes<double> h = heating_lanes<double>(m, r.flow.value, d_ep, rho1, T0);
  report.plastic_work = h.plastic_work;
  report.temperature_rise = h.temperature_rise;
  s1.temperature = h.temperature;

  // 4. Pressure from the equation of state; the specific internal energy follows the work
  //    -p dv plus the retained heat, so e = e_v + c_p (T - T_0) at every step (e_v the EOS step's
  //    own work: the trapezoid of p for default_hypo, to (rho0 Gamma0 dv)^2 / 12 of it for
  //    Mie-Gruneisen).
  const EosStep eos = eos_step(p_.equation_of_state, eos_material(),
                               {t.p_n, t.rho0_n, s0.internal_energy, T0, rho1, s1.temperature,
                                lane_algebra::trace(to_lanes(t.D_hat)), dt, h.heat_per_mass});
  if (!eos.in_range) {
    report.status = UpdateStatus::eos_out_of_range;
    return;
  }
  const double p_new = eos.pressure;
  s1.internal_energy = eos.internal_energy;
  Mat3 stress_new = to_mat3(with_pressure(to_lanes(r.deviator), p_new));

  // 5-6. Damage, porosity, failure and erosion.
  stress_new =
      damage_and_failure(s0, t.D_hat, r, dt, rho1, t.shear_modulus, stress_new, s1, report);

  // 7. Back to the lab frame.
  s1.stress = to_mat3(lane_algebra::rotate_symmetric(to_lanes(stress_new), to_lanes(t.R_out)));
  check_end_state(s1, rho1, wave_speed(rho1, s1.internal_energy, t.shear_modulus), report);
}

Mat3 ElasticPlastic::damage_and_failure(const PointState& s0, const Mat3& D_hat,
                                        const ReturnResult& r, double dt, double rho1, double mu,
                                        Mat3 stress_new, PointState& s1, StepReport& report) const {
  const double d_ep = r.delta_plastic_strain;
  const FlowStress& flow = r.flow;
  const Mat3& s_new = r.deviator;
  const double T0 = s0.temperature;
  // 5. Johnson-Cook damage (eq. 7) and optional porosity growth.
  if (d_ep > 0.0)
    accumulate_damage(p_.damage, s1.damage, d_ep, stress_new, s1.plastic_strain_rate, T0);
  // On plastic steps only (report's code); with porosity_growth = "tension", only while the mean
  // stress is tensile (voids do not open under pressure).
  const bool voids_grow = p_.tepla.growth == PorosityGrowth::dilatation || mean(stress_new) > 0.0;
  if (p_.tepla.evolve_porosity && d_ep > 0.0 && voids_grow) {
    s1.porosity =
        porosity_update(p_.tepla, s0.porosity, D_hat.trace(), s0.plastic_strain, d_ep, dt);
  }

  // 6. Failure detection, only with an erosion algorithm (report sec. 3), then erosion.
  if (p_.erosion == Erosion::none) return stress_new;
  if (!s0.failed) {
    if (s1.melted) {
      report.failure = FailureCause::melting;
    } else if (report.plastic && p_.tepla.enabled &&
               tepla_indicator(s1.porosity, p_.tepla.critical_porosity, s1.damage) >= 1.0) {
      report.failure = FailureCause::tepla;
    } else if (report.plastic && d_ep > 0.0 && p_.stability.check != StabilityCheck::none) {
      const double H =
          effective_hardening(FlowSlopes{flow.d_plastic_strain, flow.d_rate, flow.d_temperature},
                              flow.value, dt, p_.stability.rate_slope, p_.heating.enabled,
                              p_.heating.taylor_quinney, rho1, p_.specific_heat);
      const Mat3 Dp = s1.plastic_strain_rate * 1.5 * s_new / flow.value;
      const StabilityResult st =
          check_stability(p_.stability, p_.bulk_modulus, mu, stress_new, H, D_hat, Dp);
      report.drucker_indicator = st.drucker.indicator;
      report.becker_indicator = st.becker.indicator;
      const FailureCause cause = st.drucker.unstable  ? FailureCause::drucker
                                 : st.becker.unstable ? FailureCause::becker
                                                      : FailureCause::none;
      if (p_.stability.outcome == StabilityOutcome::fail) {
        report.failure = cause;
      } else {  // "report": a loss of stability is a localisation warning, not a fracture
        if (st.drucker.unstable) s1.instability |= kDruckerFired;
        if (st.becker.unstable) s1.instability |= kBeckerFired;
      }
    }
    if (report.failure != FailureCause::none) {
      s1.failed = true;
      s1.failure_cause = report.failure;
      s1.failed_in_tension = mean(stress_new) > 0.0;
    }
  }
  if (!s1.failed) return stress_new;
  const Mat3 eroded = erode_stress(p_.erosion, stress_new);
  const auto w = [&](const Mat3& t) {  // complementary elastic energy density
    const Mat3 dev = deviator(t);
    const double pr = mean(t);
    return ddot(dev, dev) / (4.0 * mu) + pr * pr / (2.0 * p_.bulk_modulus);
  };
  // Booked on the step of failure only: later steps keep the stress constrained, which the strain
  // energy (with the eroded stress) already accounts for; a total-form EOS (Mie-Gruneisen) would
  // otherwise re-book the same tension p(rho)^2/2K every step.
  if (report.failure != FailureCause::none) report.eroded_energy = w(stress_new) - w(eroded);
  return eroded;
}

void ElasticPlastic::check_end_state(const PointState& s1, double rho1, double wave,
                                     StepReport& report) const {
  if (!s1.stress.allFinite()) report.status = UpdateStatus::non_finite_stress;
  report.wave_speed = wave;
  if (std::isfinite(wave)) return;
  // A failed point whose erosion drops the tension (AllowNoTension, ZeroStress) no longer follows
  // the EOS there: its signal speed is the reference one, the stiffest it has when it closes
  // again. Any other point is outside the EOS's range: a fault, not a silent NaN that std::max
  // would drop from the time step.
  const bool tension_eroded =
      s1.failed && (p_.erosion == Erosion::allow_no_tension || p_.erosion == Erosion::zero_stress);
  if (tension_eroded) {
    report.wave_speed = std::sqrt((p_.bulk_modulus + 4.0 * p_.shear_modulus / 3.0) / rho1);
  } else if (report.status == UpdateStatus::ok) {
    report.status = UpdateStatus::non_finite_wave_speed;
  }
}

}  // namespace impact
