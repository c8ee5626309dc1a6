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

#include "models/core/input.hpp"

namespace impact {

enum class HypoModulus {
  bulk,             ///< K: correct isotropic hypoelasticity (default)
  report_eq2_lame,  ///< K - 2 mu/3 = lambda: the report's eq. (2) and the 2004 code
};

struct DefaultHypoParams {
  HypoModulus modulus = HypoModulus::bulk;
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

/// Reads {"modulus": "bulk" (default) | "report_eq2_lame"}; "type" is read by the caller.
DefaultHypoParams read_default_hypo(JsonReader& r);

}  // namespace impact
