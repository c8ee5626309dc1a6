// Hypoelastic pressure ("default_hypo" equation of state), report eq. (2), rate form integrated by
// forward Euler:
//   p_{n+1} = p_n - K_eff tr(D) dt,      p = -tr(sigma)/3 (compression positive).
// The report prints p_{n+1} = p_n + (K - 2 mu/3) tr(D) dt with p the mean stress (tension
// positive). The sign differs only because our p is compression positive. The modulus does not: K -
// 2 mu/3 is the Lame constant lambda, not the bulk modulus. Isotropic hypoelasticity sigma_rate =
// lambda tr(D) I
// + 2 mu D splits into a deviatoric part 2 mu dev(D) and a mean part (lambda + 2 mu/3) tr(D) = K
// tr(D), so the correct pressure rate is -K tr(D) (modulus = bulk, the default). Using lambda
// together with the deviatoric 2 mu dev(D) gives a uniaxial-strain modulus lambda + 4 mu/3 = K + 2
// mu/3 instead of K + 4 mu/3: for 6061-T6 (K = 66.4, mu = 26 GPa, rho = 2700) the longitudinal wave
// speed drops from 6118 to 5569 m/s. The 2004 code (DefaultHypoElasticEOS) used lambda; modulus =
// report_eq2_lame reproduces it, for comparison with the report only (docs/report_code.md sec. 0
// item 3).
#pragma once

#include "models/core/catalogue.hpp"
#include "models/core/input.hpp"
#include "models/core/lane_math.hpp"
#include "models/eos/eos_step.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace impact {

enum class HypoModulus {
  bulk,             ///< K: correct isotropic hypoelasticity (default)
  report_eq2_lame,  ///< K - 2 mu/3 = lambda: the report's eq. (2) and the 2004 code
};

struct DefaultHypoParams {
  HypoModulus modulus = HypoModulus::bulk;

  static constexpr std::string_view kType = "default_hypo";
  static constexpr std::string_view kMeaning =
      "default_hypo parameters";                                   ///< of its block, in messages
  static constexpr NoParameters<DefaultHypoParams> kParameters{};  // the modulus is a choice
};

/// Modulus multiplying -tr(D) dt: K (bulk) or K - 2 mu/3 (report_eq2_lame) [Pa]. Also the bulk
/// modulus to use in the wave speed sqrt((K_eff + 4 mu/3)/rho), so the stable time step matches the
/// stiffness actually used.
inline double default_hypo_effective_bulk_modulus(double bulk_modulus, double shear_modulus,
                                                  const DefaultHypoParams& p) {
  return p.modulus == HypoModulus::bulk ? bulk_modulus : bulk_modulus - 2.0 * shear_modulus / 3.0;
}

/// p_{n+1} = p_n - K_eff tr(D) dt [Pa]; trace_D = tr(D) [1/s], dt [s], moduli [Pa].
double default_hypo_pressure(double p_old, double trace_D, double dt, double bulk_modulus,
                             double shear_modulus, const DefaultHypoParams& p);

/// Step 4 with the default_hypo pressure (report eq. 2), for one point (V = double) or a vector of
/// them (V = lane::Vec, the batched update, models/material/elastic_plastic_batch.cpp): p_{n+1} =
/// p_n - K_eff tr(D) dt, and the specific internal energy e_{n+1} = e_n - (p_n + p_{n+1})/2 dv +
/// the retained heat (trapezoidal work, dv = 1/rho_{n+1} - 1/rho_n).
template <class V>
struct alignas(lane::kLaneBytes) PressureLanes {
  V pressure{};         ///< p_{n+1} [Pa]
  V internal_energy{};  ///< e_{n+1} [J/kg]
};

template <class V>
[[gnu::always_inline]] inline PressureLanes<V> hypo_pressure_lanes(V K_eff, V p_n, V trace_D, V dt,
                                                                   V e_n, V rho0_n, V rho1,
                                                                   V heat_per_mass) {
  PressureLanes<V> out;
  out.pressure = p_n - K_eff * trace_D * dt;
  const V dv = 1.0 / rho1 - 1.0 / rho0_n;
  out.internal_energy = e_n - 0.5 * (p_n + out.pressure) * dv + heat_per_mass;
  return out;
}

/// The catalogue's step (models/eos/eos_step.hpp): hypo_pressure_lanes with K_eff; always in
/// range.
inline EosStep eos_step(const DefaultHypoParams& p, const EosMaterial& m, const EosStepInput& in) {
  const PressureLanes<double> pr = hypo_pressure_lanes<double>(
      default_hypo_effective_bulk_modulus(m.bulk_modulus, m.shear_modulus, p), in.pressure,
      in.trace_D, in.dt, in.internal_energy, in.density, in.new_density, in.heat_per_mass);
  return {pr.pressure, pr.internal_energy, true};
}
/// K_eff, whatever the density and energy.
inline double eos_bulk_modulus(const DefaultHypoParams& p, const EosMaterial& m, double, double) {
  return default_hypo_effective_bulk_modulus(m.bulk_modulus, m.shear_modulus, p);
}

/// Reads {"modulus": "bulk" (default) | "report_eq2_lame"}; "type" is read by the caller.
DefaultHypoParams read_default_hypo(JsonReader& r);
/// The catalogue's reader (models/eos/equation_of_state.hpp): read_default_hypo.
inline DefaultHypoParams read_model(JsonReader& r, const DefaultHypoParams*) {
  return read_default_hypo(r);
}
/// {"modulus"}: the block read_default_hypo reads back.
Json to_json(const DefaultHypoParams& p);

}  // namespace impact

#pragma GCC diagnostic pop
