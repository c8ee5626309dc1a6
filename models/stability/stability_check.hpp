// Stability checks of the report (sec. 3, eqs. 10-11): which check runs ("stability_check" block
// of the material) and one call that builds the tangents and runs it. Evaluated by the composed
// model only for points that flowed plastically in the step, and only with an erosion algorithm,
// as in the report (docs/report_code.md sec. 9).
//   none            no check;
//   drucker         Drucker's postulate, sigma_dot : D^p <= 0 (drucker.hpp);
//   becker          loss of ellipticity, min_n det A^ep / det A^e <= 0 (becker.hpp);
//   drucker_becker  either one fires. Both always run, so both indicators are reported (the 2004
//                   code ran Becker only when Drucker passed).
// The tangent is the consistent J2 tangent of elastic_plastic_tangent.hpp with the effective
// hardening slope H that the caller computes with effective_hardening (RateSlope chosen here).
// Consequence worth knowing: for this tangent Drucker fires at H <= 0 and Becker at
// H <= H_crit = -(3/2)(1 + nu) mu (s_II/tau)^2 <= 0 (becker.hpp), so Becker never fires before
// Drucker; drucker_becker adds Becker's indicator and band normal, not extra failures.
#pragma once

#include "models/core/input.hpp"
#include "models/stability/becker.hpp"
#include "models/stability/drucker.hpp"
#include "models/stability/elastic_plastic_tangent.hpp"

namespace impact {

enum class StabilityCheck { none, drucker, becker, drucker_becker };

/// What a check that fires does: `fail` the point (the report's rule: it is then eroded), or only
/// `report` it (PointState::instability; the point keeps its strength). Loss of Drucker stability
/// or of ellipticity marks where deformation may localise (e.g. adiabatic shear under
/// compression), not a crack; `report` lets a scene that must not fracture there say so.
enum class StabilityOutcome { fail, report };

struct StabilityParams {
  StabilityCheck check = StabilityCheck::none;
  NormalSearch search = NormalSearch::principal_plane;  ///< Becker's normal search
  RateSlope rate_slope = RateSlope::constant_rate;      ///< how rate sensitivity enters H
  StabilityOutcome outcome = StabilityOutcome::fail;    ///< the report's: failure
  /// Drucker only on loading steps (D^p : D > 0), not on every step with plastic flow. With a
  /// rate-dependent flow stress a step can flow while the strain rate already unloads the flow
  /// direction (the flow relaxes as the rate drops, at the tail of a plastic wave); there
  /// sigma_dot : D^p passes through zero and Drucker's postulate, which concerns loading, does
  /// not apply. The report's check (false) fired there on indicators of order 1 Pa/s^2 against
  /// a scale of 1e15 (docs/taylor.md, "What fails in the rod").
  bool drucker_loading_only = false;
};

/// Reads {"type", "normal_search", "rate_slope", "outcome", "drucker_steps"}; "type" is required
/// and read here (not by the caller), the others default to principal_plane, constant_rate, fail
/// and plastic.
StabilityParams read_stability(JsonReader& r);

struct StabilityResult {
  DruckerResult drucker;  ///< default (0, stable) when Drucker did not run
  BeckerResult becker;    ///< default (1, stable) when Becker did not run
  bool unstable = false;  ///< any check that ran fired
};

/// Runs the selected checks at Cauchy stress `stress` [Pa] with K, mu [Pa], effective hardening H
/// [Pa], rate of deformation D and its plastic part D^p [1/s] (same frame as the stress).
StabilityResult check_stability(const StabilityParams& params, double bulk_modulus,
                                double shear_modulus, const Mat3& stress, double H, const Mat3& D,
                                const Mat3& Dp);

}  // namespace impact
