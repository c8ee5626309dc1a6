// The constitutive model of a material (constitutive_model.type). `elastic_plastic`, the composed
// model of the report's constitutive_model block (sec. 2-3), is described below; `neo_hookean` is
// the hyperelastic compressible neo-Hookean solid (models/elasticity/neo_hookean.hpp): its stress
// is a function of F1 alone, with no plastic flow, heating, damage or failure, so its step is
// begin_update alone (the rest returns at once) and it never takes the vector lanes.
//
// The composed `elastic_plastic` model (the report's constitutive_model block, sec. 2-3): a
// hypoelastic update in the unrotated (Green-Naghdi) frame with a chosen equation of state for the
// pressure, von Mises radial return on the Johnson-Cook flow stress for the deviator, and optional
// adiabatic heating, Johnson-Cook damage, TEPLA failure, melting, stability checks and erosion.
//
// One step, for a point with start-of-step state s0, velocity gradient L and new deformation
// gradient F1 (the caller integrates F):
//  1. kinematics: D = sym L; un-rotate sigma_n with R_n, rotate D with R_{n+1/2}   (kinematics/)
//  2. deviator:   s_tr = s_n + 2 mu dev(D) dt  (report eq. 4), radial return       (plasticity/)
//                 on sigma_y(ep, rate, T_n) (eq. 5-6); molten points keep no deviator (melting)
//  3. heating:    T += chi sigma_y d_ep / (rho cp)  (eq. 8)                         (thermal/)
//  4. pressure:   default_hypo (eq. 2, with K) or Mie-Gruneisen (eq. 3)            (eos/)
//  5. damage:     D += d_ep / eps_f(triaxiality, rate, T)  (eq. 7)                  (damage/)
//  6. failure:    only when an erosion algorithm is chosen (as in the report): melting, TEPLA
//                 (eq. 9), Drucker (eq. 10), Becker (eq. 11); failed points get the erosion
//                 operation every step                                               (failure/)
//  7. re-rotate with R_{n+1}.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "models/core/input.hpp"
#include "models/core/point_state.hpp"
#include "models/damage/damage_law.hpp"
#include "models/elasticity/neo_hookean.hpp"
#include "models/elasticity/shear_modulus.hpp"
#include "models/eos/equation_of_state.hpp"
#include "models/failure/erosion.hpp"
#include "models/failure/tepla.hpp"
#include "models/flow_stress/flow_stress_law.hpp"
#include "models/kinematics/corotation.hpp"
#include "models/material/elastic_plastic_lanes.hpp"
#include "models/plasticity/johnson_cook_return_batch.hpp"
#include "models/plasticity/radial_return.hpp"
#include "models/stability/stability_check.hpp"
#include "models/thermal/adiabatic_heating.hpp"
#include "models/thermal/melting.hpp"

namespace impact {

/// constitutive_model.type: the composed hypoelastic-plastic model, or the neo-Hookean solid.
enum class ConstitutiveType : std::uint8_t { elastic_plastic, neo_hookean };

struct ElasticPlasticParams {
  ConstitutiveType type = ConstitutiveType::elastic_plastic;
  double density = 0.0;                 ///< reference density rho0 [kg/m^3]
  double bulk_modulus = 0.0;            ///< K [Pa]
  double shear_modulus = 0.0;           ///< mu0 [Pa]
  ShearModulusLaw shear_modulus_model;  ///< mu(T, p, rho) from mu0 (constant by default)
  double specific_heat = 0.0;           ///< cp [J/(kg K)]
  double room_temperature = 294.0;      ///< [K]
  double melt_temperature = 925.0;      ///< [K]
  ObjectiveRate objective_rate = ObjectiveRate::green_naghdi;
  ReturnAlgorithm return_algorithm = ReturnAlgorithm::newton;
  ReturnTolerance return_tolerance;
  EquationOfState equation_of_state = DefaultHypoParams{};
  FlowStressLaw flow_stress;  ///< models/flow_stress/flow_stress_law.hpp
  DamageLaw damage;           ///< models/damage/damage_law.hpp (none by default)
  TeplaParams tepla;
  MeltingParams melting;
  AdiabaticHeatingParams heating;
  StabilityParams stability;
  Erosion erosion = Erosion::none;  ///< none also switches failure detection off (report sec. 3)
};

enum class UpdateStatus : std::uint8_t {
  ok,
  negative_jacobian,  ///< det F_{n+1} <= 0
  /// F_{n+1} or its determinant not finite: L dt overflowed (a huge step), not a collapse
  non_finite_deformation_gradient,
  return_mapping_not_converged,  ///< the radial return missed its tolerance
  non_finite_stress,             ///< NaN or Inf in the updated stress
  eos_out_of_range,              ///< compression beyond the Mie-Gruneisen limit 1 - S eta > 0
  /// K_s + 4 mu / 3 <= 0 (a Mie-Gruneisen fit extrapolated into tension beyond its spinodal) at
  /// a point whose stress follows the EOS: no wave speed, no stable time step.
  non_finite_wave_speed,
};

/// What one update did, beyond the new state: for the caller's time step, ledger and diagnostics.
struct StepReport {
  UpdateStatus status = UpdateStatus::ok;
  bool plastic = false;
  int return_iterations = 0;
  double wave_speed = 0.0;        ///< longitudinal sound speed sqrt((K_s + 4 mu/3)/rho) [m/s]
  double plastic_work = 0.0;      ///< sigma_y d_ep, per unit current volume [J/m^3]
  double temperature_rise = 0.0;  ///< adiabatic heating of this step [K]
  FailureCause failure = FailureCause::none;  ///< set on the step a point fails
  double drucker_indicator = 0.0;  ///< sigma_dot : D^p when the Drucker check ran [Pa/s^2]
  double becker_indicator = 1.0;   ///< min det A_ep / det A_e when the Becker check ran [-]
  /// Elastic energy density the erosion took out of the stress on the step the point failed,
  /// w(sigma) - w(eroded sigma) with w = s:s/(4 mu) + p^2/(2 K) [J/m^3] (0 for KeepStress, and on
  /// every later step).
  double eroded_energy = 0.0;
};

/// A step after its kinematics and before its radial return (begin_update), kept for the rest
/// (finish_update): what the return needs and what the pressure, damage, failure and rotation back
/// read.
struct UpdateTrial {
  Mat3 D_hat;                  ///< rate of deformation in the working frame [1/s]
  Mat3 R_out;                  ///< rotation back to the lab frame
  Mat3 s_trial;                ///< trial deviator [Pa]
  double q_trial = 0.0;        ///< its von Mises equivalent sqrt(3/2 s_tr:s_tr) [Pa]
  double p_n = 0.0;            ///< start-of-step pressure [Pa]
  double rho0_n = 0.0;         ///< start-of-step density [kg/m^3]
  double rho1 = 0.0;           ///< end-of-step density [kg/m^3]
  JohnsonCookThermal thermal;  ///< Johnson-Cook's temperature factor at the start-of-step T
  FlowConditions conditions;  ///< what any other law reads: T_n, p_n, rho1 / rho0, rho1, T_m(rho_n)
  double shear_modulus = 0.0;  ///< mu at the start-of-step T, p and rho (shear_modulus_model)
  bool molten = false;         ///< no return: the deviator is zero
  /// Newton's return of a Johnson-Cook point, which a batch can do (johnson_cook_return_batch);
  /// other laws take the one-point return with the same Newton iteration.
  bool batched = false;
  /// A neo_hookean step: begin_update wrote the whole end state; no return, nothing to finish.
  bool hyperelastic = false;
};

std::string_view to_string(UpdateStatus);
std::string_view to_string(FailureCause);

class ElasticPlastic {
 public:
  /// A placeholder with no properties, to be assigned a configured model before use.
  ElasticPlastic() = default;
  explicit ElasticPlastic(ElasticPlasticParams params) : p_(std::move(params)) {}

  const ElasticPlasticParams& params() const { return p_; }
  bool hyperelastic() const { return p_.type == ConstitutiveType::neo_hookean; }
  /// mu and lambda = K - 2 mu / 3 of the neo_hookean law.
  NeoHookeanModuli neo_hookean_moduli() const {
    return {p_.shear_modulus, p_.bulk_modulus - 2.0 / 3.0 * p_.shear_modulus};
  }
  /// The stored energy W(F) per unit reference volume [J/m^3] of a hyperelastic law (its strain
  /// energy is a function of F: the solver books its change, not the stress power's quadrature).
  double stored_energy(const Mat3& F) const { return neo_hookean_energy(F, neo_hookean_moduli()); }

  /// A point at rest in the reference configuration at temperature T.
  PointState initial_state(double temperature) const;

  /// Advances s0 over dt with velocity gradient L to the deformation gradient F1; writes s1.
  StepReport update(const PointState& s0, const Mat3& L, const Mat3& F1, double dt,
                    PointState& s1) const;

  /// update() in three parts, so that a caller can do the radial returns of many points at once
  /// (UpdateBatch): begin_update (false when det F1 <= 0, with report.status set), the return
  /// (unbatched_return for one point, or johnson_cook_return_batch on a batch's lanes filled by
  /// to_lane), finish_update. update() is exactly these three with the one-point return.
  /// `corotated`, when given, is the green_naghdi step already applied, corotate(s0.R, R_new,
  /// s0.stress, sym L) with R_new the polar rotation of F1 (a batch computes them together,
  /// polar_rotation_batch and corotation_batch); used with the green_naghdi rate only.
  bool begin_update(const PointState& s0, const Mat3& L, const Mat3& F1, double dt, PointState& s1,
                    UpdateTrial& t, StepReport& report, const Corotated* corotated = nullptr) const;
  ReturnResult unbatched_return(const PointState& s0, const UpdateTrial& t, double dt) const;
  /// Fills point (V = double) or lane k (V = lane::Vec) of a return's inputs.
  template <class V>
  void to_lane(const PointState& s0, const UpdateTrial& t, double dt, ReturnValues<V>& r,
               int k) const {
    lane::set(r.q_trial, k, t.q_trial);
    lane::set(r.three_mu, k, 3.0 * t.shear_modulus);
    lane::set(r.plastic_strain, k, s0.plastic_strain);
    lane::set(r.dt, k, dt);
    // The previous step's plastic rate is a close first guess under steady loading.
    lane::set(r.guess, k, s0.plastic_strain_rate * dt);
  }
  void finish_update(const PointState& s0, const UpdateTrial& t, const ReturnResult& r, double dt,
                     PointState& s1, StepReport& report) const;

  /// Longitudinal wave speed sqrt((K_s + 4 mu/3) / rho) of a state (for the time step); NaN when
  /// K_s + 4 mu/3 <= 0.
  double wave_speed(const PointState& s) const;
  /// The same at density rho [kg/m^3] and specific internal energy e [J/kg], with mu0 or with
  /// the shear modulus `mu` [Pa] of the step.
  double wave_speed(double rho, double internal_energy) const;
  double wave_speed(double rho, double internal_energy, double mu) const;
  /// mu [Pa] of a state (shear_modulus_model at its T, pressure and density).
  double shear_modulus_of(const PointState& s) const;
  /// T_m [K] of a state (the melting curve at its density rho0 / det F).
  double melting_temperature_of(const PointState& s) const;
  /// Whether a state is molten: melting on and T >= T_m of the state (a step starting there has
  /// no deviatoric strength).
  bool molten(const PointState& s) const;

  /// The constants the equation of state reads (models/eos/eos_step.hpp).
  EosMaterial eos_material() const {
    return {p_.density, p_.bulk_modulus, p_.shear_modulus, p_.specific_heat};
  }

  /// Steps 5-6 of finish_update: damage, porosity, failure detection and erosion of the end-of-step
  /// stress in the working frame (returned, eroded where the point has failed). A no-op, returning
  /// stress_new, unless the step was plastic, d_ep > 0, the point was molten or had failed: a batch
  /// skips it then.
  /// `mu`: the step's shear modulus.
  Mat3 damage_and_failure(const PointState& s0, const Mat3& D_hat, const ReturnResult& r, double dt,
                          double rho1, double mu, Mat3 stress_new, PointState& s1,
                          StepReport& report) const;
  /// Step 7's checks: a non-finite stress, and a wave speed (`wave`, at rho1) that is not finite.
  void check_end_state(const PointState& s1, double rho1, double wave, StepReport& report) const;

  /// This material's constants for elastic_plastic_lanes.hpp.
  template <class V>
  MaterialLanes<V> material_lanes() const {
    MaterialLanes<V> m;
    m.density = lane::splat<V>(p_.density);
    m.shear_modulus = lane::splat<V>(p_.shear_modulus);
    const auto* hypo = std::get_if<DefaultHypoParams>(&p_.equation_of_state);
    m.hypo_bulk_modulus = lane::splat<V>(
        hypo ? default_hypo_effective_bulk_modulus(p_.bulk_modulus, p_.shear_modulus, *hypo) : 0.0);
    m.heating = lane::splat<V>(p_.heating.enabled ? 1.0 : 0.0);
    m.taylor_quinney = lane::splat<V>(p_.heating.taylor_quinney);
    m.specific_heat = lane::splat<V>(p_.specific_heat);
    return m;
  }

 private:
  ElasticPlasticParams p_;
};

}  // namespace impact
