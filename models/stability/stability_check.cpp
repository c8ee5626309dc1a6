#include "models/stability/stability_check.hpp"

namespace impact {

StabilityParams read_stability(JsonReader& r) {
  StabilityParams p;
  const std::string type = r.choice("type", {"none", "drucker", "becker", "drucker_becker"},
                                    "stability check run on plastically flowing points");
  if (type == "drucker") p.check = StabilityCheck::drucker;
  if (type == "becker") p.check = StabilityCheck::becker;
  if (type == "drucker_becker") p.check = StabilityCheck::drucker_becker;
  const std::string search = r.choice(
      "normal_search", {"principal_plane", "full_sphere"},
      "Becker band-normal search: max-min principal plane or the whole sphere", "principal_plane");
  if (search == "full_sphere") p.search = NormalSearch::full_sphere;
  const std::string rate = r.choice(
      "rate_slope", {"constant_rate", "algorithmic"},
      "rate term of the hardening slope H: none at constant rate, or d sigma_y/d rate / dt",
      "constant_rate");
  if (rate == "algorithmic") p.rate_slope = RateSlope::algorithmic;
  const std::string outcome =
      r.choice("outcome", {"fail", "report"},
               "what a check that fires does: fail the point, or only report it", "fail");
  if (outcome == "report") p.outcome = StabilityOutcome::report;
  p.drucker_loading_only =
      r.choice("drucker_steps", {"plastic", "loading"},
               "steps Drucker's check runs on: every plastic step (the report's), or only those "
               "whose strain rate loads the flow direction (D^p : D > 0)",
               "plastic") == "loading";
  r.reject_unknown_keys();
  return p;
}

StabilityResult check_stability(const StabilityParams& params, double bulk_modulus,
                                double shear_modulus, const Mat3& stress, double H, const Mat3& D,
                                const Mat3& Dp) {
  StabilityResult r;
  if (params.check == StabilityCheck::none) return r;
  const bool drucker =
      params.check == StabilityCheck::drucker || params.check == StabilityCheck::drucker_becker;
  const bool becker =
      params.check == StabilityCheck::becker || params.check == StabilityCheck::drucker_becker;
  // The 9x9 tangent only where a check needs it: Drucker, and Becker in Becker's plane, have
  // closed forms for the J2 tangent.
  const bool need_tangent = becker && params.search == NormalSearch::full_sphere;
  const Tensor4 tangent = need_tangent
                              ? elastic_plastic_tangent(bulk_modulus, shear_modulus, stress, H)
                              : Tensor4::Zero();
  if (drucker) {
    r.drucker = drucker_check_j2(bulk_modulus, shear_modulus, stress, H, D, Dp);
    if (params.drucker_loading_only && !(ddot(Dp, D) > 0.0)) r.drucker.unstable = false;
  }
  if (becker) {
    r.becker = params.search == NormalSearch::principal_plane
                   ? becker_check_j2(bulk_modulus, shear_modulus, stress, H)
                   : becker_check(tangent, isotropic_elasticity(bulk_modulus, shear_modulus),
                                  stress, params.search);
  }
  r.unstable = r.drucker.unstable || r.becker.unstable;
  return r;
}

}  // namespace impact
