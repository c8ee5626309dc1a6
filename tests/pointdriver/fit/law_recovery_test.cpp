// Parameter recovery for laws other than Johnson-Cook: `pointdriver fit` varies any law's
// parameters by name (models/flow_stress/flow_stress_law.hpp, docs/fitting.md). Synthetic curves
// are computed by the driver itself on OFHC copper (data/materials/ofhc_copper_scg.json:
// elasticity, Mie-Gruneisen EOS, adiabatic heating with chi = 0.9 at and above 10 /s) with its
// flow-stress law replaced by a known set, at 3 rates x 3 temperatures, no noise; the fit starts
// 20 % off every free parameter (alternately above and below) and must find the set again:
//  - Zerilli-Armstrong fcc (C0, C2, C3, C4 free): each within 1e-4 of the truth;
//  - Preston-Tonks-Wallace (theta, p, s0, s_inf, kappa free; gamma, y0, y_inf and the overdriven
//    y1, y2, beta fixed): each within 1e-4;
//  - Steinberg-Cochran-Guinan, rate-independent (Y0, beta, n free, Y_max fixed above the curves'
//    stresses): each within 1e-4;
//  - Mechanical Threshold Stress, an illustrative set (sigma_a, sigma_i, a0, sigma_es0 free),
//    its internal variable integrated along each driver curve: each within 1e-4;
//  - Swift hardening with Cowper-Symonds rate scaling (K, eps0, n, D, q all free; the tests'
//    mild-steel set, tests/helpers/cowper_symonds_mild_steel.hpp): each within 1e-4.
// The acceptance asks 1 %; 1e-4 is what a noise-free fit through the same model must reach.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <map>

#include "helpers/cowper_symonds_mild_steel.hpp"
#include "helpers/mts_illustrative.hpp"
#include "pointdriver/fit/strength_fit.hpp"

using namespace impact;
using namespace impact::pointdriver::fit;

namespace {

const std::string kMaterial =
    std::string(IMPACT_SOURCE_DIR) + "/data/materials/ofhc_copper_scg.json";

// The copper file's SCG keys removed (a merge patch's null), then the law given.
Json law_patch(const Json& law) {
  Json flow = {{"Y0", nullptr},    {"Y_max", nullptr}, {"beta", nullptr},
               {"n", nullptr},     {"G0", nullptr},    {"initial_plastic_strain", nullptr},
               {"dG_dp", nullptr}, {"dG_dT", nullptr}};
  flow.merge_patch(law);
  return {{"constitutive_model", {{"flow_stress", flow}}}};
}

CurveSettings settings() {
  CurveSettings s;
  s.steps = 40;
  s.adiabatic_above_rate = 10.0;
  return s;
}

// Experiments at eps_p = 0.002 .. 0.4 (60 points, log-spaced) with the driver's stresses for
// `patch` (the truth).
CurveModel synthetic(const Json& patch) {
  std::vector<Experiment> shells;
  for (double T : {294.0, 500.0, 700.0}) {
    for (double rate : {1e-3, 1e2, 4e3}) {
      Experiment e;
      e.name = "synthetic_" + std::to_string(static_cast<int>(T)) + "K_" + std::to_string(rate);
      e.file = e.name;
      e.temperature = T;
      e.strain_rate = rate;
      e.type = TestType::uniaxial_compression;
      for (int k = 0; k < 60; ++k) {
        e.plastic_strain.push_back(0.002 * std::pow(200.0, k / 59.0));
        e.stress.push_back(1.0);
      }
      shells.push_back(e);
    }
  }
  const CurveModel truth(kMaterial, patch, shells, settings());
  const auto pred = truth.predict({law_values(truth.base().flow_stress)});
  for (std::size_t e = 0; e < shells.size(); ++e) shells[e].stress = pred[0][e];
  return CurveModel(kMaterial, patch, shells, settings());
}

// Fits `free` (name -> bounds) from 20 % off the truth; every other parameter fixed at the truth.
void recovers(const Json& law, const std::map<std::string, std::array<double, 2>>& free) {
  const CurveModel model = synthetic(law_patch(law));
  FitConfig c;
  c.initial_guess = "start";
  const FlowStressLaw& truth = model.base().flow_stress;
  double sign = 1.0;
  for (const std::string& name : model.parameter_names()) {
    const auto f = free.find(name);
    ParameterSpec s{name,
                    std::string(parameter_unit(truth, name)),
                    f != free.end(),
                    parameter(truth, name),
                    0.0,
                    0.0};
    if (s.free) {
      s.start = parameter(truth, name) * (1.0 + 0.2 * sign);
      s.lower = f->second[0];
      s.upper = f->second[1];
      sign = -sign;
    }
    c.parameters.push_back(s);
  }
  const StrengthFit fit = fit_strength(model, c);
  BOOST_TEST_MESSAGE(law["type"] << ": " << fit.lsq.iterations << " iterations, "
                                 << fit.lsq.residual_evaluations << " parameter sets, "
                                 << fit.lsq.wall_time << " s, " << fit.lsq.stop_reason << "; RMS "
                                 << fit.overall_fitted.rms << " Pa");
  for (std::size_t i = 0; i < fit.parameters.size(); ++i) {
    const double want = parameter(truth, fit.parameters[i].name);
    if (!fit.parameters[i].free) {
      BOOST_TEST(fit.fitted[i] == want);  // a fixed parameter is never moved
      continue;
    }
    BOOST_TEST_MESSAGE("  " << fit.parameters[i].name << ": start " << fit.start[i] << ", fitted "
                            << fit.fitted[i] << ", truth " << want << " ("
                            << 100 * (fit.fitted[i] / want - 1) << " %)");
    BOOST_TEST(std::abs(fit.fitted[i] / want - 1.0) < 1e-4);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(fit_law_recovery)

// Zerilli & Armstrong (1987), OFHC copper: C0 = 46.5 MPa, C2 = 890 MPa, C3 = 0.0028 /K,
// C4 = 0.000115 /K.
BOOST_AUTO_TEST_CASE(zerilli_armstrong_fcc) {
  recovers({{"type", "zerilli_armstrong"},
            {"form", "fcc"},
            {"C0", 46.5e6},
            {"C2", 890e6},
            {"C3", 0.0028},
            {"C4", 0.000115}},
           {{"C0", {0.0, 5e9}}, {"C2", {0.0, 2e10}}, {"C3", {0.0, 0.05}}, {"C4", {0.0, 0.01}}});
}

// Preston, Tonks & Wallace (2003), copper.
BOOST_AUTO_TEST_CASE(preston_tonks_wallace) {
  recovers({{"type", "preston_tonks_wallace"},
            {"theta", 0.025},
            {"p", 2.0},
            {"s0", 0.0085},
            {"s_inf", 0.00055},
            {"kappa", 0.11},
            {"gamma", 1e-5},
            {"y0", 0.0001},
            {"y_inf", 0.0001},
            {"y1", 0.094},
            {"y2", 0.575},
            {"beta", 0.25},
            {"G0", 51.8e9},
            {"alpha", 0.2},
            {"molar_mass", 63.546e-3}},
           {{"theta", {1e-4, 1.0}},
            {"p", {0.0, 20.0}},
            {"s0", {1e-5, 0.2}},
            {"s_inf", {1e-6, 0.2}},
            {"kappa", {0.01, 2.0}}});
}

// Steinberg (1996), OFHC copper as in the material file, Y_max fixed.
BOOST_AUTO_TEST_CASE(steinberg_cochran_guinan) {
  recovers({{"type", "steinberg_cochran_guinan"},
            {"Y0", 0.12e9},
            {"Y_max", 0.64e9},
            {"beta", 36.0},
            {"n", 0.45},
            {"G0", 47.7e9},
            {"dG_dp", 1.34991},
            {"dG_dT", -1.79829e7}},
           {{"Y0", {1e6, 5e9}}, {"beta", {0.0, 1e4}}, {"n", {0.01, 2.0}}});
}

// Mechanical Threshold Stress, the illustrative set (tests/data/flow_stress/mts_illustrative.json).
BOOST_AUTO_TEST_CASE(mechanical_threshold_stress) {
  recovers(testing::mts_illustrative_law(), {{"sigma_a", {0.0, 2e9}},
                                             {"sigma_i", {0.0, 1e10}},
                                             {"a0", {0.0, 1e11}},
                                             {"sigma_es0", {1e6, 1e10}}});
}

// Swift x Cowper-Symonds: every parameter free, from the fitter's default bounds (kParameters).
BOOST_AUTO_TEST_CASE(cowper_symonds) {
  recovers(to_json(FlowStressLaw(testing::cowper_symonds_mild_steel())), {{"K", {1e6, 1e10}},
                                                                          {"eps0", {1e-6, 0.5}},
                                                                          {"n", {0.0, 1.0}},
                                                                          {"D", {1e-2, 1e8}},
                                                                          {"q", {1.0, 20.0}}});
}

BOOST_AUTO_TEST_SUITE_END()
