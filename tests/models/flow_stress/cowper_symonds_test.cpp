// Swift hardening with Cowper-Symonds rate scaling (models/flow_stress/cowper_symonds.hpp):
//   - values against sigma_y = K (eps0 + ep)^n [1 + (rate/D)^(1/q)] computed independently
//     (Python, the expression written out again) to 1e-12: altering the equation fails them;
//   - Cowper & Symonds' published meaning: at rate = D the dynamic yield is twice the static
//     one, for their mild steel (D = 40.4 /s, q = 5) and Bodner & Symonds' aluminium (6500 /s, 4);
//   - its derivatives against central differences;
//   - the radial return converges over a sweep of rates, overshoots and plastic strains;
//   - the catalogue: JSON round trip, by-name parameters, and bad input named by its key path.
// The Swift set (K = 530 MPa, eps0 = 0.01, n = 0.26) is illustrative.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "models/flow_stress/flow_stress_law.hpp"
#include "models/plasticity/radial_return.hpp"
#include "support/input_problems.hpp"

using namespace impact;

namespace {

CowperSymondsParams mild_steel() {
  CowperSymondsParams p;
  p.K = 530e6;
  p.eps0 = 0.01;
  p.n = 0.26;
  p.D = 40.4;
  p.q = 5.0;
  return p;
}

FlowStress at(const CowperSymondsParams& p, double ep, double rate) {
  return flow_stress(p, ep, rate, FlowConditions{});
}

}  // namespace

BOOST_AUTO_TEST_SUITE(flow_stress_cowper_symonds)

BOOST_AUTO_TEST_CASE(values_match_the_equation) {
  const CowperSymondsParams p = mild_steel();
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
    CowperSymondsParams p = mild_steel();
    p.D = D;
    p.q = q;
    const double ratio = at(p, 0.1, D).value / at(p, 0.1, p.minimum_strain_rate).value;
    const double static_excess = std::pow(p.minimum_strain_rate / D, 1.0 / q);
    BOOST_TEST(ratio == 2.0 / (1.0 + static_excess), boost::test_tools::tolerance(1e-14));
  }
}

BOOST_AUTO_TEST_CASE(derivatives_match_central_differences) {
  const CowperSymondsParams p = mild_steel();
  int checked = 0;
  for (const double ep : {0.001, 0.2, 0.6})
    for (const double rate : {1e-3, 10.0, 1e4}) {
      const FlowStress f = at(p, ep, rate);
      const double he = 1e-6 * ep, hr = 1e-6 * rate;
      const double d_ep = (at(p, ep + he, rate).value - at(p, ep - he, rate).value) / (2 * he);
      const double d_rate = (at(p, ep, rate + hr).value - at(p, ep, rate - hr).value) / (2 * hr);
      // Tolerance: the differences' truncation and round-off, scaled by the value's size.
      const auto close = [&](double analytic, double numeric, double h) {
        return std::abs(analytic - numeric) <= 1e-6 * std::abs(numeric) + 1e-9 * f.value / h;
      };
      BOOST_TEST_CONTEXT("ep " << ep << " rate " << rate) {
        BOOST_TEST(close(f.d_plastic_strain, d_ep, he));
        BOOST_TEST(close(f.d_rate, d_rate, hr));
        BOOST_TEST(f.d_temperature == 0.0);
      }
      ++checked;
    }
  BOOST_TEST(checked == 9);
}

// radial_return_test's sweep: converged, on the yield surface at the step's rate
// (|q_{n+1} - sigma_y(ep + d, d/dt)| <= 1e-10 q_tr).
BOOST_AUTO_TEST_CASE(the_radial_return_converges) {
  const CowperSymondsParams p = mild_steel();
  const double mu = 80e9, dt = 1e-8;
  Mat3 direction;
  direction << 2.0, 0.3, -0.1, 0.3, -0.5, 0.2, -0.1, 0.2, -1.5;
  direction = deviator(direction);
  direction /= std::sqrt(1.5 * ddot(direction, direction));
  int cases = 0, worst = 0;
  for (const double rate : {1e-4, 1.0, 1e3, 1e5})
    for (const double over : {1e-9, 1e-4, 1e-1, 10.0})
      for (const double ep0 : {0.0, 1e-3, 0.5}) {
        const auto flow = [&](double e, double r) { return at(p, e, r); };
        const double q = flow(ep0, 0.0).value * (1.0 + over);
        const ReturnResult r = radial_return(direction * q, mu, ep0, dt, flow,
                                             ReturnAlgorithm::newton, 0.0, {}, rate * dt);
        ++cases;
        worst = std::max(worst, r.iterations);
        BOOST_TEST_CONTEXT("rate " << rate << " overshoot " << over << " ep0 " << ep0) {
          BOOST_TEST_REQUIRE(r.converged);
          const double d = r.delta_plastic_strain;
          const double q_new = std::sqrt(1.5 * ddot(r.deviator, r.deviator));
          if (d > 0.0) BOOST_TEST(std::abs(q_new - flow(ep0 + d, d / dt).value) <= 1e-10 * q);
        }
      }
  BOOST_TEST(cases == 48);
  BOOST_TEST_MESSAGE("Cowper-Symonds: " << cases << " returns, worst " << worst << " iterations");
}

BOOST_AUTO_TEST_CASE(json_round_trip_by_name_and_bad_input) {
  const FlowStressLaw law = mild_steel();
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
