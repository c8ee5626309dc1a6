// Swift hardening with Cowper-Symonds rate scaling (models/flow_stress/cowper_symonds.hpp):
//   - values against sigma_y = K (eps0 + ep)^n [1 + (rate/D)^(1/q)] computed independently
//     (Python, the expression written out again) to 1e-12: altering the equation fails them;
//   - Cowper & Symonds' published meaning: at rate = D the dynamic yield is twice the static
//     one, for their mild steel (D = 40.4 /s, q = 5) and Bodner & Symonds' aluminium (6500 /s, 4);
//   - (its derivatives and the radial-return sweep: flow_stress_laws_test, with every law);
//   - the catalogue: JSON round trip, by-name parameters, and bad input named by its key path.
// The Swift set (K = 530 MPa, eps0 = 0.01, n = 0.26) is illustrative.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "helpers/cowper_symonds_mild_steel.hpp"
#include "helpers/input_problems.hpp"
#include "models/flow_stress/flow_stress_law.hpp"

using namespace impact;

namespace {

using testing::cowper_symonds_mild_steel;

FlowStress at(const CowperSymondsParams& p, double ep, double rate) {
  return flow_stress(p, ep, rate, FlowConditions{});
}

}  // namespace

BOOST_AUTO_TEST_SUITE(flow_stress_cowper_symonds)

BOOST_AUTO_TEST_CASE(values_match_the_equation) {
  const CowperSymondsParams p = cowper_symonds_mild_steel();
  struct Case {
    double ep, rate, expected;
  };
  for (const Case& c : {Case{0.0, 1e-3, 179244110.76527488}, Case{0.1, 40.4, 597128724.8574593},
                        Case{0.35, 1e3, 1178400573.8568065}, Case{0.02, 1e5, 1229342723.514587},
                        Case{0.2, 1e-9, 363862139.29661363}}) {  // below the minimum rate
    BOOST_TEST_CONTEXT("ep " << c.ep << " rate " << c.rate) {
      BOOST_TEST(at(p, c.ep, c.rate).value == c.expected, boost::test_tools::tolerance(1e-12));
    }
  }
  // Perfectly plastic (n = 0): sigma_0 = K, Bodner & Symonds' aluminium at 1e4 /s.
  CowperSymondsParams al;
  al.K = 250e6;
  al.D = 6500.0;
  al.q = 4.0;
  BOOST_TEST(at(al, 0.3, 1e4).value == 528427206.13879544, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(at(al, 0.3, 1e4).d_plastic_strain == 0.0);
}

BOOST_AUTO_TEST_CASE(at_the_rate_constant_the_yield_doubles) {
  for (const auto& [D, q] : {std::pair{40.4, 5.0}, std::pair{6500.0, 4.0}}) {
    CowperSymondsParams p = cowper_symonds_mild_steel();
    p.D = D;
    p.q = q;
    const double ratio = at(p, 0.1, D).value / at(p, 0.1, p.minimum_strain_rate).value;
    const double static_excess = std::pow(p.minimum_strain_rate / D, 1.0 / q);
    BOOST_TEST(ratio == 2.0 / (1.0 + static_excess), boost::test_tools::tolerance(1e-14));
  }
}

BOOST_AUTO_TEST_CASE(json_round_trip_by_name_and_bad_input) {
  const FlowStressLaw law = cowper_symonds_mild_steel();
  const Json written = to_json(law);
  InputProblems problems("cs.json");
  JsonReader r(written, "/flow_stress", problems);
  const FlowStressLaw read = read_flow_stress(r, 294.0, 1800.0);
  BOOST_TEST(problems.empty());
  BOOST_TEST(to_json(read) == written);
  BOOST_TEST(parameter(read, "D") == 40.4);
  BOOST_TEST(parameter_unit(read, "K") == "Pa");

  // With hardening, eps0 = 0 would yield at zero stress: it is required and > 0.
  Json bad = written;
  bad["eps0"] = 0.0;
  bad["q"] = 0.5;
  InputProblems bad_problems("cs.json");
  JsonReader rb(bad, "/constitutive_model/flow_stress", bad_problems);
  read_flow_stress(rb, 294.0, 1800.0);
  const std::string text = testing::problems_text(bad_problems);
  BOOST_TEST(text.find("cs.json: /constitutive_model/flow_stress/eps0") != std::string::npos);
  BOOST_TEST(text.find("cs.json: /constitutive_model/flow_stress/q") != std::string::npos);
  // Perfectly plastic (n = 0): eps0 may be left out.
  const Json plastic = {
      {"type", "cowper_symonds"}, {"K", 250e6}, {"n", 0.0}, {"D", 6500.0}, {"q", 4.0}};
  InputProblems ok("cs.json");
  JsonReader rp(plastic, "/flow_stress", ok);
  read_flow_stress(rp, 294.0, 1800.0);
  BOOST_TEST(ok.empty());
}

BOOST_AUTO_TEST_SUITE_END()
