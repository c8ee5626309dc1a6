// The flow-stress laws of the catalogue (models/flow_stress/flow_stress_law.hpp) beside
// Johnson-Cook: Zerilli-Armstrong (fcc and bcc), Steinberg-Cochran-Guinan and
// Preston-Tonks-Wallace.
//   - Values at fixed (ep, rate, T, conditions) against numbers computed independently from the
//     papers' equations (Python's math module, the expressions written out again; the script is
//     in the comment of each case), to 1e-12 relative: altering an equation fails them.
//   - Each law's derivatives against central finite differences.
//   - The radial return converges onto each law's yield surface over the sweep of
//     radial_return_test (temperatures, rates, overshoots, initial plastic strains).
//   - The catalogue: JSON read and written back, parameters by name, bad input named.
// Parameter sets: Zerilli & Armstrong (1987) J. Appl. Phys. 61:1816, OFHC copper (fcc: C0 =
// 46.5 MPa, C2 = 890 MPa, C3 = 0.0028 /K, C4 = 0.000115 /K) and Armco iron (bcc: C0 = 70 MPa,
// C1 = 1033 MPa, C3 = 0.00698 /K, C4 = 0.000415 /K, C5 = 266 MPa, n = 0.289); Steinberg (1996)
// UCRL-MA-106439 for 6061-T6 (G0 = 27.6 GPa, Y0 = 0.29 GPa, Y_max = 0.68 GPa, beta = 125,
// n = 0.10, G'_p / G0 = 65.0e-12 /Pa, G'_T / G0 = -0.62e-3 /K); Preston, Tonks & Wallace (2003)
// J. Appl. Phys. 93:211, Table I, copper (theta 0.025, p 2, s0 0.0085, s_inf 0.00055, kappa 0.11,
// gamma 1e-5, y0 = y_inf = 0.0001, y1 0.094, y2 0.575, beta 0.25) with G0 = 51.8 GPa,
// alpha = 0.2, M = 63.546 g/mol, T_melt = 1356 K.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <set>
#include <string>

#include "helpers/cowper_symonds_mild_steel.hpp"
#include "helpers/mts_illustrative.hpp"
#include "models/flow_stress/flow_stress_law.hpp"
#include "models/plasticity/radial_return.hpp"

using namespace impact;

namespace {

ZerilliArmstrongParams copper_za() {
  ZerilliArmstrongParams p;
  p.form = ZerilliArmstrongForm::fcc;
  p.C0 = 46.5e6;
  p.C2 = 890e6;
  p.C3 = 0.0028;
  p.C4 = 0.000115;
  return p;
}

ZerilliArmstrongParams iron_za() {
  ZerilliArmstrongParams p;
  p.form = ZerilliArmstrongForm::bcc;
  p.C0 = 70e6;
  p.C1 = 1033e6;
  p.C3 = 0.00698;
  p.C4 = 0.000415;
  p.C5 = 266e6;
  p.n = 0.289;
  return p;
}

SteinbergCochranGuinanParams al6061_scg() {
  SteinbergCochranGuinanParams p;
  p.Y0 = 0.29e9;
  p.Y_max = 0.68e9;
  p.beta = 125.0;
  p.n = 0.10;
  p.G0 = 27.6e9;
  p.dG_dp = 65.0e-12 * p.G0;
  p.dG_dT = -0.62e-3 * p.G0;
  return p;
}

// Steinberg-Lund with constants of the order of the paper's tantalum (not a published set):
// C1 = 7.1e5 /s, U_k = 0.31 eV, Y_P = 0.82 GPa, C2 = 1.2e3 Pa s, Y_A = 0.375 GPa, Y_max = 1.1 GPa,
// beta = 10, n = 0.1, G0 = 69 GPa, G'_p/G0 = 1.45e-11 /Pa, G'_T/G0 = -1.3e-4 /K.
SteinbergCochranGuinanParams tantalum_like_sl() {
  SteinbergCochranGuinanParams p;
  p.rate_form = SteinbergRateForm::steinberg_lund;
  p.Y0 = 0.375e9;
  p.Y_max = 1.1e9;
  p.beta = 10.0;
  p.n = 0.1;
  p.G0 = 69e9;
  p.dG_dp = 1.45e-11 * p.G0;
  p.dG_dT = -1.3e-4 * p.G0;
  p.C1 = 7.1e5;
  p.U_k = 0.31 * 1.602176634e-19;
  p.Y_P = 0.82e9;
  p.C2 = 1.2e3;
  return p;
}

PrestonTonksWallaceParams copper_ptw() {
  PrestonTonksWallaceParams p;
  p.theta = 0.025;
  p.p = 2.0;
  p.s0 = 0.0085;
  p.s_inf = 0.00055;
  p.kappa = 0.11;
  p.gamma = 1e-5;
  p.y0 = 0.0001;
  p.y_inf = 0.0001;
  p.y1 = 0.094;
  p.y2 = 0.575;
  p.beta = 0.25;
  p.G0 = 51.8e9;
  p.alpha = 0.2;
  p.molar_mass = 63.546e-3;
  p.melt_temperature = 1356.0;
  return p;
}

// One instance of every law of the catalogue (two of Zerilli-Armstrong: fcc and bcc; two of
// Steinberg: SCG and Steinberg-Lund), the lists the every-law tests below sweep;
// the_every_law_list_holds_every_law_of_the_catalogue fails when a law is added without one.
std::vector<FlowStressLaw> every_law() {
  InputProblems problems("mts_illustrative.json");
  const Json mts_law = testing::mts_illustrative_law();  // the reader keeps a reference
  JsonReader mts(mts_law, "/flow_stress", problems);
  std::vector<FlowStressLaw> laws = {JohnsonCookParams{324e6, 114e6, 0.42, 0.002, 1.34},
                                     copper_za(),
                                     iron_za(),
                                     al6061_scg(),
                                     tantalum_like_sl(),
                                     copper_ptw(),
                                     read_flow_stress(mts, 294.0, 1356.0),
                                     testing::cowper_symonds_mild_steel()};
  problems.throw_if_any();
  return laws;
}

FlowConditions at(double T, double pressure = 0.0, double compression = 1.0,
                  double density = 8960.0) {
  return {T, pressure, compression, density};
}

void check_value(const FlowStressLaw& law, double ep, double rate, const FlowConditions& c,
                 double expected) {
  const double value = flow_stress(law, ep, rate, c).value;
  BOOST_TEST_CONTEXT(law_type(law) << " ep " << ep << " rate " << rate << " T " << c.temperature) {
    BOOST_TEST(std::abs(value - expected) <= 1e-12 * expected);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(flow_stress_laws)

// Python: C0 + (C1 + C2 sqrt(ep)) exp(-C3 T + C4 T ln(max(rate, 1e-6))) + C5 ep^n.
BOOST_AUTO_TEST_CASE(zerilli_armstrong_fcc_and_bcc_equal_the_papers_equations) {
  check_value(copper_za(), 0.2, 1000.0, at(300.0), 264570861.69862702);
  check_value(copper_za(), 0.05, 1e-3, at(600.0), 69528215.19503705);
  check_value(copper_za(), 0.5, 5000.0, at(77.0), 593510292.3034481);
  check_value(copper_za(), 0.1, 0.0, at(300.0), 121936693.05855498);  // at minimum_strain_rate
  check_value(iron_za(), 0.2, 1000.0, at(300.0), 537800189.8564817);
  check_value(iron_za(), 0.05, 1e-3, at(600.0), 184721094.7261898);
  check_value(iron_za(), 0.0, 1.0, at(294.0), 202701529.74541923);
}

// Python: min(Y0 (1 + beta ep)^n, Y_max) max(0, 1 + G'_p/G0 p / eta^(1/3) + G'_T/G0 (T - 300)).
BOOST_AUTO_TEST_CASE(steinberg_cochran_guinan_equals_the_papers_equation) {
  check_value(al6061_scg(), 0.0, 0.0, at(300.0), 290000000.0);
  check_value(al6061_scg(), 0.05, 0.0, at(400.0, 5e9, 1.05), 444660541.5892776);
  check_value(al6061_scg(), 2.0, 1e6, at(700.0, 20e9, 1.2), 995425430.1580318);  // capped
  check_value(al6061_scg(), 0.01, 0.0, at(294.0, -1e9, 0.98), 295086321.11644435);
  // Hot enough that G(p, T) reaches zero: no strength, not a negative one.
  BOOST_TEST(flow_stress(FlowStressLaw(al6061_scg()), 0.1, 0.0, at(2000.0)).value == 0.0);
}

// Python: Y_T the root of 1/rate = (1/C1) exp(2 U_k/(k_B T) (1 - Y/Y_P)^2) + C2/Y by bisection
// (Y_P when h(Y_P) <= 0, 0 at rest), then (Y_T + min(Y_A (1 + beta ep)^n, Y_max)) G/G0.
BOOST_AUTO_TEST_CASE(steinberg_lund_equals_the_papers_equations) {
  const SteinbergCochranGuinanParams p = tantalum_like_sl();
  const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-12 * b; };
  BOOST_TEST(near(steinberg_lund_thermal_stress(p, 1e3, 300.0).value, 391066924.10371375));
  BOOST_TEST(near(steinberg_lund_thermal_stress(p, 1e-3, 300.0).value, 64080702.927518725));
  BOOST_TEST(steinberg_lund_thermal_stress(p, 1e8, 300.0).value == p.Y_P);  // capped
  BOOST_TEST(steinberg_lund_thermal_stress(p, 0.0, 300.0).value == 0.0);    // at rest
  check_value(p, 0.1, 1e3, at(300.0), 792981972.5548236);
  check_value(p, 0.1, 1e-3, at(300.0), 465995751.3786287);
  check_value(p, 0.3, 1e5, at(600.0, 5e9, 1.05), 973129325.1457609);
  check_value(p, 0.0, 1e8, at(300.0), 1195000000.0);
  check_value(p, 0.2, 0.0, at(300.0), 418546190.26271415);
}

// Python (PTW eq. 5-12): G = G0 (1 - alpha T/Tm); xi = 0.5 (4 pi rho N_A / (3 M))^(1/3)
// sqrt(G/rho); r = max(rate, 1e-6) / (gamma xi); e = erf(kappa T^ ln(1/r)); tau_s = max(s0 -
// (s0 - s_inf) e, s0 r^beta); tau_y = max(y0 - (y0 - y_inf) e, min(y1 r^y2, s0 r^beta));
// a = s0 - tau_y; x = p (tau_s - tau_y)/a; tau = tau_s + a/p ln(1 - (1 - e^-x)
// exp(-p theta psi / (a (e^x - 1)))); sigma = 2 G tau.
BOOST_AUTO_TEST_CASE(preston_tonks_wallace_equals_the_papers_equations) {
  check_value(copper_ptw(), 0.0, 1e3, at(300.0, 0.0, 1.0, 8960.0), 13789280.469852187);
  check_value(copper_ptw(), 0.2, 1e3, at(300.0, 0.0, 1.0, 8960.0), 299697602.5594661);
  check_value(copper_ptw(), 0.5, 1e-3, at(600.0, 0.0, 1.0, 8900.0), 114811764.36608115);
  check_value(copper_ptw(), 0.1, 1e9, at(300.0, 0.0, 1.0, 9500.0), 1570566454.523307);
  check_value(copper_ptw(), 0.3, 0.0, at(300.0, 0.0, 1.0, 8960.0), 242479144.50086424);
}

// Central differences with steps 1e-6 relative (1e-7 absolute at ep = 0 is avoided: the laws'
// slopes are unbounded there) against each law's derivatives.
BOOST_AUTO_TEST_CASE(every_laws_derivatives_match_finite_differences) {
  const std::vector<FlowStressLaw> laws = every_law();
  int checked = 0;
  for (const FlowStressLaw& law : laws)
    for (const double ep : {0.01, 0.2, 0.6})
      for (const double rate : {1e-2, 10.0, 1e4})
        for (const double T : {250.0, 500.0}) {
          const FlowConditions c = at(T, 2e9, 1.02, 9000.0);
          const FlowStress f = flow_stress(law, ep, rate, c);
          const auto value = [&](double e, double r, double t) {
            FlowConditions ct = c;
            ct.temperature = t;
            return flow_stress(law, e, r, ct).value;
          };
          const double he = 1e-6 * ep, hr = 1e-6 * rate, hT = 1e-6 * T;
          const double d_ep = (value(ep + he, rate, T) - value(ep - he, rate, T)) / (2 * he);
          const double d_rate = (value(ep, rate + hr, T) - value(ep, rate - hr, T)) / (2 * hr);
          const double d_T = (value(ep, rate, T + hT) - value(ep, rate, T - hT)) / (2 * hT);
          // Tolerance: the differences' truncation and round-off, scaled by the value's size.
          const auto close = [&](double analytic, double numeric, double h) {
            return std::abs(analytic - numeric) <= 1e-6 * std::abs(numeric) + 1e-9 * f.value / h;
          };
          BOOST_TEST_CONTEXT(law_type(law) << " ep " << ep << " rate " << rate << " T " << T) {
            BOOST_TEST(close(f.d_plastic_strain, d_ep, he));
            BOOST_TEST(close(f.d_rate, d_rate, hr));
            BOOST_TEST(close(f.d_temperature, d_T, hT));
          }
          ++checked;
        }
  BOOST_TEST(checked == 18 * int(laws.size()));
}

// radial_return_test's sweep for every law: converged, on the yield surface at the step's rate
// (|q_{n+1} - sigma_y(ep + d, d/dt)| <= 1e-10 q_tr), q_{n+1} = q_tr - 3 mu d. Without an
// increment bound the Newton iteration starts from the elastic bound; the worst count is printed.
BOOST_AUTO_TEST_CASE(the_radial_return_converges_with_every_law) {
  const double mu = 40e9, dt = 1e-8;
  const std::vector<FlowStressLaw> laws = every_law();
  Mat3 direction;
  direction << 2.0, 0.3, -0.1, 0.3, -0.5, 0.2, -0.1, 0.2, -1.5;
  direction = deviator(direction);
  direction /= std::sqrt(1.5 * ddot(direction, direction));
  int cases = 0, worst = 0;
  for (const FlowStressLaw& law : laws)
    for (const double T : {294.0, 600.0, 850.0})
      for (const double rate : {1e-4, 1.0, 1e3, 1e5})
        for (const double over : {1e-9, 1e-4, 1e-1, 10.0})
          for (const double ep0 : {0.0, 1e-3, 0.5}) {
            const FlowConditions c = at(T, 1e9, 1.01, 9000.0);
            const auto flow = [&](double e, double r) { return flow_stress(law, e, r, c); };
            const double yield = flow(ep0, 0.0).value;
            const double q = yield * (1.0 + over);
            const ReturnResult r = radial_return(direction * q, mu, ep0, dt, flow,
                                                 ReturnAlgorithm::newton, 0.0, {}, rate * dt);
            ++cases;
            worst = std::max(worst, r.iterations);
            BOOST_TEST_CONTEXT(law_type(law) << " T " << T << " rate " << rate << " overshoot "
                                             << over << " ep0 " << ep0) {
              BOOST_TEST_REQUIRE(r.converged);
              const double d = r.delta_plastic_strain;
              const double q_new = std::sqrt(1.5 * ddot(r.deviator, r.deviator));
              BOOST_TEST(std::abs(q_new - (q - 3.0 * mu * d)) <= 1e-12 * q);
              if (d > 0.0) {
                BOOST_TEST(std::abs(q_new - flow(ep0 + d, d / dt).value) <= 1e-10 * q);
              } else {
                BOOST_TEST(std::abs(q_new - yield) <= 1e-8 * q);
              }
            }
          }
  BOOST_TEST(cases == 144 * int(laws.size()));
  BOOST_TEST_MESSAGE("every law: " << cases << " returns, worst " << worst << " iterations");
}

BOOST_AUTO_TEST_CASE(the_every_law_list_holds_every_law_of_the_catalogue) {
  std::set<std::string> listed;
  for (const FlowStressLaw& law : every_law()) listed.insert(std::string(law_type(law)));
  for (const auto& type : law_types())
    BOOST_TEST(listed.count(std::string(type)) == 1,
               "no instance of " << type << " in every_law()");
}

// Every law read from JSON and written back gives the same document; parameters by name.
BOOST_AUTO_TEST_CASE(the_catalogue_reads_writes_and_names_every_laws_parameters) {
  const std::vector<FlowStressLaw> laws = every_law();
  BOOST_TEST(law_types().size() == std::variant_size_v<FlowStressLaw>);
  for (const FlowStressLaw& law : laws) {
    const Json written = to_json(law);
    InputProblems problems("law.json");
    JsonReader r(written, "/flow_stress", problems);
    const FlowStressLaw read = read_flow_stress(r, 294.0, 1356.0);
    BOOST_TEST_CONTEXT(law_type(law) << ": " << written.dump()) {
      BOOST_TEST(problems.empty());
      BOOST_TEST(law_type(read) == law_type(law));
      BOOST_TEST(to_json(read) == written);
      for (const std::string& name : parameter_names(law))
        BOOST_TEST(parameter(read, name) == parameter(law, name));
    }
  }
  FlowStressLaw za = copper_za();
  set_parameter(za, "C2", 900e6);
  BOOST_TEST(std::get<ZerilliArmstrongParams>(za).C2 == 900e6);
  BOOST_TEST(parameter_unit(za, "C3") == "1/K");
  BOOST_CHECK_EXCEPTION(parameter(za, "A"), std::invalid_argument, [](const auto& e) {
    return std::string(e.what()).find("zerilli_armstrong has no parameter A (it has C0, C1") !=
           std::string::npos;
  });
}

BOOST_AUTO_TEST_CASE(bad_law_input_is_named_with_its_key_path) {
  const auto problems_of = [](const Json& j) {
    InputProblems problems("mat.json");
    JsonReader r(j, "/constitutive_model/flow_stress", problems);
    read_flow_stress(r, 294.0, 1356.0);
    std::string all;
    try {
      problems.throw_if_any();
    } catch (const InputError& e) {
      all = e.what();
    }
    return all;
  };
  Json ptw = to_json(FlowStressLaw(copper_ptw()));
  ptw["y0"] = 0.01;  // above s0
  BOOST_TEST(
      problems_of(ptw).find("mat.json: /constitutive_model/flow_stress: expected y0 <= s0") !=
      std::string::npos);
  Json scg = to_json(FlowStressLaw(al6061_scg()));
  scg["Y_max"] = 1e8;
  BOOST_TEST(problems_of(scg).find("/constitutive_model/flow_stress/Y_max: expected a stress >= "
                                   "Y0") != std::string::npos);
  Json za = to_json(FlowStressLaw(copper_za()));
  za.erase("C2");
  BOOST_TEST(problems_of(za).find("/constitutive_model/flow_stress/C2: missing required number") !=
             std::string::npos);
  za["form"] = "hcp";
  BOOST_TEST(problems_of(za).find("/constitutive_model/flow_stress/form: unknown name \"hcp\"; "
                                  "known: fcc, bcc") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
