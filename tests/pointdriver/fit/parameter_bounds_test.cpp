// Parameters on their bounds (pointdriver/fit/parameter_bounds.hpp): a start value inside its
// bounds is used as given, one on or outside them is moved inside with a warning naming where it
// came from, and a fitted parameter the bound stopped is flagged (StrengthFit::at_bound, the
// report's "AT ... BOUND", fit_report.json's parameters_at_bounds).
//
// The tolerance is 1e-3 of the bound's magnitude (of the width for a bound at 0): for
// Johnson-Cook's A in [1e6, 5e9] Pa that is 1 kPa at the lower bound, for Cowper-Symonds' D in
// [1e-2, 1e8] 1/s 1e-5 /s. The fits run the driver on Swift x Cowper-Symonds curves made by the
// driver itself (the tests' mild-steel set: K = 530 MPa, eps0 = 0.01, n = 0.26, D = 40.4 /s,
// q = 5, on data/materials/ofhc_copper_scg.json's elasticity), two rates at 294 K.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "helpers/cowper_symonds_mild_steel.hpp"
#include "pointdriver/fit/fit_report.hpp"
#include "pointdriver/fit/parameter_bounds.hpp"
#include "pointdriver/fit/strength_fit.hpp"

using namespace impact;
using namespace impact::pointdriver::fit;

namespace {

const std::string kMaterial =
    std::string(IMPACT_SOURCE_DIR) + "/data/materials/ofhc_copper_scg.json";

// The copper file's SCG keys removed (a merge patch's null), then the Swift x Cowper-Symonds
// law with the given D.
Json cowper_symonds_patch(double D) {
  const CowperSymondsParams p = testing::cowper_symonds_mild_steel();
  Json flow = {{"Y0", nullptr},
               {"Y_max", nullptr},
               {"beta", nullptr},
               {"G0", nullptr},
               {"initial_plastic_strain", nullptr},
               {"dG_dp", nullptr},
               {"dG_dT", nullptr},
               {"type", "cowper_symonds"},
               {"K", p.K},
               {"eps0", p.eps0},
               {"n", p.n},
               {"D", D},
               {"q", p.q}};
  return {{"constitutive_model", {{"flow_stress", flow}}}};
}

CurveSettings settings() {
  CurveSettings s;
  s.steps = 40;
  return s;
}

// Curves at 1e-3 and 1e3 /s, 294 K, eps_p 0.002 .. 0.3 (20 points), from the driver with the
// mild-steel set (D = 40.4 /s); the model then carries the material's D = `material_D`.
CurveModel synthetic(double material_D) {
  std::vector<Experiment> shells;
  for (double rate : {1e-3, 1e3}) {
    Experiment e;
    e.name = e.file = "synthetic_" + std::to_string(rate);
    e.temperature = 294.0;
    e.strain_rate = rate;
    for (int k = 0; k < 20; ++k) {
      e.plastic_strain.push_back(0.002 * std::pow(150.0, k / 19.0));
      e.stress.push_back(1.0);
    }
    shells.push_back(e);
  }
  const CurveModel truth(kMaterial, cowper_symonds_patch(40.4), shells, settings());
  const auto pred = truth.predict({law_values(truth.base().flow_stress)});
  for (std::size_t e = 0; e < shells.size(); ++e) shells[e].stress = pred[0][e];
  return CurveModel(kMaterial, cowper_symonds_patch(material_D), shells, settings());
}

// A configuration with every parameter of the law at the law's default bounds (free as the
// fitter's defaults say), `free` overriding which are free.
FitConfig config_for(const CurveModel& model, const std::vector<std::string>& free) {
  FitConfig c;
  c.initial_guess = "start";
  const FlowStressLaw& law = model.base().flow_stress;
  for (const std::string& name : model.parameter_names()) {
    const FitBounds b = fit_bounds(law, name);
    c.parameters.push_back({name, std::string(parameter_unit(law, name)),
                            std::find(free.begin(), free.end(), name) != free.end(), std::nullopt,
                            b.lower, b.upper});
  }
  return c;
}

std::size_t index_of(const StrengthFit& fit, const std::string& name) {
  for (std::size_t i = 0; i < fit.parameters.size(); ++i)
    if (fit.parameters[i].name == name) return i;
  throw std::logic_error("no parameter " + name);
}

ParameterSpec& spec(FitConfig& c, const std::string& name) {
  for (ParameterSpec& s : c.parameters)
    if (s.name == name) return s;
  throw std::logic_error("no parameter " + name);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(parameter_bounds)

BOOST_AUTO_TEST_CASE(a_bound_is_judged_at_its_own_scale) {
  const Parameter A{"A", 0.0, true, 1e6, 5e9};
  BOOST_TEST(bound_tolerance(A, A.lower) == 1e3);
  BOOST_TEST(bound_tolerance(A, A.upper) == 1e-3 * (5e9 - 1e6));  // the width is the smaller
  BOOST_TEST(to_string(at_bound(A, 1.0009e6)) == "lower");
  BOOST_TEST(to_string(at_bound(A, 1.0011e6)) == "");
  BOOST_TEST(to_string(at_bound(A, 4.996e9)) == "upper");
  BOOST_TEST(to_string(at_bound(A, 4.994e9)) == "");
  // Cowper-Symonds' D over eight decades: 6500 /s (Bodner & Symonds' aluminium) is far inside,
  // though within 1e-3 of the width (1e5 /s) of the lower bound.
  const Parameter D{"D", 0.0, true, 1e-2, 1e8};
  BOOST_TEST(bound_tolerance(D, D.lower) == 1e-5);
  BOOST_TEST(to_string(at_bound(D, 6500.0)) == "");
  BOOST_TEST(!move_inside_bounds(D, 6500.0).has_value());
  BOOST_TEST(move_inside_bounds(D, 1e-3).value() == 1e-2 + 1e-4);  // outside: 10 tolerances in
  // A bound at 0 (Johnson-Cook's B in [0, 5e9] Pa) is judged against the width: 5 MPa.
  const Parameter B{"B", 0.0, true, 0.0, 5e9};
  BOOST_TEST(to_string(at_bound(B, 0.0)) == "lower");
  BOOST_TEST(move_inside_bounds(B, 0.0).value() == 5e7);
  BOOST_TEST(!move_inside_bounds(B, 1e9).has_value());
}

// The case: a Cowper-Symonds start D = 6500 /s was moved to 1e5 /s without a word (the
// old margin was 1e-3 of the width). Now it is kept; a material's D of 1e-3 /s, below the lower
// bound 1e-2 /s, is moved to 0.0101 /s with a warning that names the value and its origin.
BOOST_AUTO_TEST_CASE(a_start_inside_is_kept_one_outside_moved_with_a_warning) {
  {
    const CurveModel model = synthetic(6500.0);
    FitConfig c = config_for(model, {"D"});
    c.solver.max_iterations = 1;
    const StrengthFit fit = fit_strength(model, c);
    BOOST_TEST(fit.start[index_of(fit, "D")] == 6500.0);
    BOOST_TEST(fit.start_warnings.empty());
  }
  const CurveModel model = synthetic(1e-3);
  FitConfig c = config_for(model, {"D"});
  c.solver.max_iterations = 1;
  const StrengthFit fit = fit_strength(model, c);
  BOOST_TEST(std::abs(fit.start[index_of(fit, "D")] - 0.0101) < 1e-15);
  BOOST_TEST_REQUIRE(fit.start_warnings.size() == 1u);
  BOOST_TEST_MESSAGE(fit.start_warnings[0]);
  BOOST_TEST(fit.start_warnings[0] ==
             "start value of D (0.001 1/s, the material's) is on or outside its bounds [0.01, "
             "1e+08] 1/s: moved to 0.0101 1/s");
  BOOST_TEST(fit_report_json(c, fit)["warnings"][0] == fit.start_warnings[0]);
}

// K of the data is 530 MPa. With K's upper bound at 400 MPa the solver stops on the bound: K is
// flagged "upper" in the fit, the printed table and fit_report.json; with the default bound
// (1e10 Pa) it is recovered (to 1e-4) and nothing is flagged.
BOOST_AUTO_TEST_CASE(a_parameter_the_data_push_past_its_bound_is_flagged) {
  const CurveModel model = synthetic(40.4);
  FitConfig c = config_for(model, {"K"});
  spec(c, "K").upper = 400e6;
  spec(c, "K").start = 300e6;
  const StrengthFit fit = fit_strength(model, c);
  const std::size_t k = index_of(fit, "K");
  BOOST_TEST_MESSAGE("K fitted " << fit.fitted[k] << " Pa, " << fit.lsq.stop_reason);
  BOOST_TEST(to_string(fit.at_bound[k]) == "upper");
  BOOST_TEST(fit.fitted[k] >= 400e6 * (1 - 1e-3));
  BOOST_TEST_REQUIRE(fit.at_bound_messages().size() == 1u);
  BOOST_TEST(fit.at_bound_messages()[0].rfind("K ended on its upper bound 4e+08 Pa", 0) == 0);
  const Json report = fit_report_json(c, fit);
  BOOST_TEST(report["parameters_at_bounds"] == Json::array({"K"}));
  BOOST_TEST(report["parameters"]["K"]["at_bound"] == "upper");
  std::ostringstream printed;
  print_fit_report(printed, c, fit);
  BOOST_TEST(printed.str().find("AT UPPER BOUND [1, 400]") != std::string::npos);

  FitConfig inside = config_for(model, {"K"});
  spec(inside, "K").start = 300e6;
  const StrengthFit free_fit = fit_strength(model, inside);
  BOOST_TEST(std::abs(free_fit.fitted[k] / 530e6 - 1.0) < 1e-4);
  BOOST_TEST(to_string(free_fit.at_bound[k]) == "");
  BOOST_TEST(free_fit.at_bound_messages().empty());
  BOOST_TEST(fit_report_json(inside, free_fit)["parameters_at_bounds"].empty());
}

BOOST_AUTO_TEST_SUITE_END()
