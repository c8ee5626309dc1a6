// Stability-check selection: read_stability's names, defaults and errors, and check_stability runs
// exactly the selected checks, with the tangent built from K, mu, the stress and H.
#include "models/stability/stability_check.hpp"
#include "helpers/input_problems.hpp"

#include <boost/test/unit_test.hpp>
#include <string>

using namespace impact;
using impact::testing::problems_text;

namespace {

constexpr double kK = 66.4e9, kMu = 26e9;

StabilityParams read(const Json& j, InputProblems& problems) {
  JsonReader r(j, "/constitutive_model/stability_check", problems);
  return read_stability(r);
}

// Uniaxial plastic loading sigma_y e1 (x) e1 at plastic rate 1e3/s with slope H, D consistent with
// the tangent's own plastic rate (the tangent's response is checked in drucker_test.cpp).
struct Loading {
  Mat3 stress, D, Dp;
};
Loading uniaxial(double H) {
  const double E = 9.0 * kK * kMu / (3.0 * kK + kMu);
  const double nu = (3.0 * kK - 2.0 * kMu) / (2.0 * (3.0 * kK + kMu));
  const double rate = 1e3, sigma_dot = H * rate;
  Loading l;
  l.stress = Mat3::Zero();
  l.stress(0, 0) = 250e6;
  l.Dp = rate * Vec3(1.0, -0.5, -0.5).asDiagonal();
  l.D = l.Dp + (sigma_dot / E) * Vec3(1.0, -nu, -nu).asDiagonal().toDenseMatrix();
  return l;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stability_stability_check)

BOOST_AUTO_TEST_CASE(reads_every_name_and_defaults_to_principal_plane_and_constant_rate) {
  InputProblems problems("mat.json");
  const StabilityParams d = read(Json{{"type", "drucker_becker"}}, problems);
  BOOST_TEST((d.check == StabilityCheck::drucker_becker));
  BOOST_TEST((d.search == NormalSearch::principal_plane));
  BOOST_TEST((d.rate_slope == RateSlope::constant_rate));
  const StabilityParams b = read(
      Json{{"type", "becker"}, {"normal_search", "full_sphere"}, {"rate_slope", "algorithmic"}},
      problems);
  BOOST_TEST((b.check == StabilityCheck::becker));
  BOOST_TEST((b.search == NormalSearch::full_sphere));
  BOOST_TEST((b.rate_slope == RateSlope::algorithmic));
  BOOST_TEST((read(Json{{"type", "drucker"}}, problems).check == StabilityCheck::drucker));
  BOOST_TEST((read(Json{{"type", "none"}}, problems).check == StabilityCheck::none));
  BOOST_TEST(problems.empty());
}

BOOST_AUTO_TEST_CASE(rejects_unknown_names_unknown_keys_and_a_missing_type) {
  InputProblems problems("mat.json");
  read(Json{{"type", "druker"}, {"normal_search", "sphere"}, {"rate_slop", "algorithmic"}},
       problems);
  read(Json::object(), problems);
  const std::string text = problems_text(problems);
  BOOST_TEST_MESSAGE(text);
  BOOST_TEST(text.find("/constitutive_model/stability_check/type") != std::string::npos);
  BOOST_TEST(text.find("did you mean drucker") != std::string::npos);
  BOOST_TEST(text.find("/constitutive_model/stability_check/normal_search") != std::string::npos);
  BOOST_TEST(text.find("rate_slop") != std::string::npos);
  BOOST_TEST(text.find("missing") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(runs_only_the_selected_checks) {
  // H = -20 MPa: Drucker fires (H <= 0); Becker does not (uniaxial H_crit = -(1+nu) mu/2 = -17
  // GPa).
  const double H = -20e6;
  const Loading l = uniaxial(H);
  StabilityParams p;
  auto run = [&](StabilityCheck c) {
    p.check = c;
    return check_stability(p, kK, kMu, l.stress, H, l.D, l.Dp);
  };
  const Tensor4 tangent = elastic_plastic_tangent(kK, kMu, l.stress, H);
  const DruckerResult drucker = drucker_check(tangent, l.D, l.Dp);
  const BeckerResult becker =
      becker_check(tangent, isotropic_elasticity(kK, kMu), l.stress, NormalSearch::principal_plane);
  BOOST_TEST(drucker.unstable);
  BOOST_TEST(!becker.unstable);
  BOOST_TEST(becker.indicator < 1.0);

  const StabilityResult none = run(StabilityCheck::none);
  BOOST_TEST(!none.unstable);
  BOOST_TEST(none.drucker.indicator == 0.0);
  BOOST_TEST(none.becker.indicator == 1.0);

  // check_stability uses Drucker's closed form: equal to the assembled tangent's to 1e-12.
  const StabilityResult d = run(StabilityCheck::drucker);
  BOOST_TEST(d.drucker.indicator == drucker.indicator, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(d.becker.indicator == 1.0);  // not run
  BOOST_TEST(d.unstable);

  const StabilityResult b = run(StabilityCheck::becker);
  BOOST_TEST(b.drucker.indicator == 0.0);  // not run
  // check_stability uses the closed form in Becker's plane: equal to the numerical search to 1e-9.
  BOOST_TEST(b.becker.indicator == becker.indicator, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(!b.unstable);

  const StabilityResult db = run(StabilityCheck::drucker_becker);
  BOOST_TEST(db.drucker.indicator == drucker.indicator, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(db.becker.indicator == becker.indicator, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(db.unstable);  // either one fires
}

BOOST_AUTO_TEST_CASE(drucker_on_loading_steps_ignores_flow_that_relaxes_while_unloading) {
  // A hardening point (H = +500 MPa) still flowing (D^p at 1e3 /s, as a rate-dependent return
  // gives while the rate drops) under a strain rate that unloads it elastically (sigma_dot =
  // -1e12 Pa/s along x): D^p : D < 0. The tangent's sigma_dot : D^p is then negative, so the
  // report's check (every plastic step) fires; with drucker_steps = loading it does not. A
  // softening point under loading (H = -20 MPa, the case above) fires either way.
  const double H = 500e6;
  Loading l = uniaxial(H);
  const double E = 9.0 * kK * kMu / (3.0 * kK + kMu);
  const double nu = (3.0 * kK - 2.0 * kMu) / (2.0 * (3.0 * kK + kMu));
  l.D = (-1e12 / E) * Vec3(1.0, -nu, -nu).asDiagonal().toDenseMatrix();
  BOOST_REQUIRE(ddot(l.Dp, l.D) < 0.0);
  StabilityParams p;
  p.check = StabilityCheck::drucker;
  const StabilityResult every = check_stability(p, kK, kMu, l.stress, H, l.D, l.Dp);
  p.drucker_loading_only = true;
  const StabilityResult loading = check_stability(p, kK, kMu, l.stress, H, l.D, l.Dp);
  BOOST_TEST(every.drucker.indicator < 0.0);
  BOOST_TEST(every.unstable);
  BOOST_TEST(loading.drucker.indicator == every.drucker.indicator);  // still reported
  BOOST_TEST(!loading.unstable);
  const Loading soft = uniaxial(-20e6);
  BOOST_TEST(check_stability(p, kK, kMu, soft.stress, -20e6, soft.D, soft.Dp).unstable);
  InputProblems problems("mat.json");
  BOOST_TEST(
      read(Json{{"type", "drucker"}, {"drucker_steps", "loading"}}, problems).drucker_loading_only);
  BOOST_TEST(!read(Json{{"type", "drucker"}}, problems).drucker_loading_only);
  BOOST_TEST(problems.empty());
}

BOOST_AUTO_TEST_CASE(becker_fires_below_its_critical_slope_and_uses_the_chosen_search) {
  // Uniaxial: -(1 + nu) mu / 2 = -17.25 GPa; 1 % either side.
  const double nu = (3.0 * kK - 2.0 * kMu) / (2.0 * (3.0 * kK + kMu));
  const double h_crit = -0.5 * (1.0 + nu) * kMu;
  for (NormalSearch search : {NormalSearch::principal_plane, NormalSearch::full_sphere}) {
    const StabilityParams p{StabilityCheck::becker, search, RateSlope::constant_rate};
    const Loading below = uniaxial(1.01 * h_crit), above = uniaxial(0.99 * h_crit);
    BOOST_TEST(
        check_stability(p, kK, kMu, below.stress, 1.01 * h_crit, below.D, below.Dp).unstable);
    BOOST_TEST(
        !check_stability(p, kK, kMu, above.stress, 0.99 * h_crit, above.D, above.Dp).unstable);
  }
}

BOOST_AUTO_TEST_SUITE_END()
