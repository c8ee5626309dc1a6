// default_hypo equation of state (report eq. 2): uniaxial-strain loading through the rate form,
// the longitudinal modulus and wave speed it implies with the bulk modulus (correct) and with the
// report's printed Lame constant (the 2004 code), and the reader.
#include "models/eos/default_hypo.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

using namespace impact;

namespace {

// Report Table 1 (6061-T6).
constexpr double K = 66.4e9;    // bulk modulus [Pa]
constexpr double mu = 26e9;     // shear modulus [Pa]
constexpr double rho = 2700.0;  // density [kg/m^3]

struct UniaxialResult {
  double strain;    // total eps_xx
  double pressure;  // compression positive
  double sigma_xx;  // -p + 2 mu (eps - tr(eps)/3), tension positive
};

/// Drives eps_xx in n equal increments (D = diag(rate, 0, 0)), checking p against -K_eff eps at
/// every step, and returns the final state.
UniaxialResult uniaxial_strain(const DefaultHypoParams& params, double k_expected, double total,
                               int n) {
  const double dt = 1e-7;
  const double rate = total / (n * dt);
  double p = 0.0;
  double eps = 0.0;
  for (int i = 0; i < n; ++i) {
    p = default_hypo_pressure(p, rate, dt, K, mu, params);
    eps += rate * dt;
    // Linear in eps, so forward Euler is exact up to round-off: 1e-12 relative.
    BOOST_TEST(p == -k_expected * eps, boost::test_tools::tolerance(1e-12));
  }
  // Deviatoric part of a uniaxial strain: eps - eps/3 along x.
  return {eps, p, -p + 2.0 * mu * (eps - eps / 3.0)};
}

DefaultHypoParams with(HypoModulus m) {
  DefaultHypoParams p;
  p.modulus = m;
  return p;
}

void expect_input_error_containing(const std::string& json, const std::string& fragment) {
  const Json j = Json::parse(json);
  InputProblems problems("mat.json");
  JsonReader r(j, "/equation_of_state/default_hypo", problems);
  read_default_hypo(r);
  try {
    problems.throw_if_any();
    BOOST_FAIL("expected an InputError");
  } catch (const InputError& e) {
    BOOST_TEST_INFO(e.what());
    BOOST_TEST(std::string(e.what()).find(fragment) != std::string::npos);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(eos_default_hypo)

BOOST_AUTO_TEST_CASE(
    bulk_modulus_pressure_follows_minus_K_trace_strain_in_compression_and_tension) {
  for (double total : {-0.01, 0.004}) {
    const auto r = uniaxial_strain(with(HypoModulus::bulk), K, total, 100);
    BOOST_TEST(r.pressure == -K * total, boost::test_tools::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_CASE(bulk_modulus_gives_longitudinal_modulus_K_plus_four_thirds_mu_and_6118_m_s) {
  const auto r = uniaxial_strain(with(HypoModulus::bulk), K, -0.01, 100);
  const double modulus = r.sigma_xx / r.strain;
  BOOST_TEST(modulus == K + 4.0 * mu / 3.0, boost::test_tools::tolerance(1e-12));
  // c_L = sqrt((66.4 + 34.667) GPa / 2700) = 6118.2 m/s;
  // 1 m/s tolerance on the report-rounded number.
  BOOST_TEST(std::abs(std::sqrt(modulus / rho) - 6118.0) < 1.0);
}

BOOST_AUTO_TEST_CASE(
    report_eq2_lame_gives_lambda_plus_four_thirds_mu_and_5569_m_s_as_the_2004_code) {
  const double lambda = K - 2.0 * mu / 3.0;  // 49.07 GPa
  const auto r = uniaxial_strain(with(HypoModulus::report_eq2_lame), lambda, -0.01, 100);
  const double modulus = r.sigma_xx / r.strain;
  BOOST_TEST(modulus == lambda + 4.0 * mu / 3.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(modulus == K + 2.0 * mu / 3.0, boost::test_tools::tolerance(1e-12));
  // sqrt(83.73 GPa / 2700) = 5568.9 m/s (docs/report_code.md sec. 0 item 3): 9 % slow.
  BOOST_TEST(std::abs(std::sqrt(modulus / rho) - 5569.0) < 1.0);
}

BOOST_AUTO_TEST_CASE(effective_bulk_modulus_is_K_or_the_lame_constant) {
  BOOST_TEST(default_hypo_effective_bulk_modulus(K, mu, with(HypoModulus::bulk)) == K);
  BOOST_TEST(default_hypo_effective_bulk_modulus(K, mu, with(HypoModulus::report_eq2_lame)) ==
                 K - 2.0 * mu / 3.0,
             boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(pure_shear_leaves_the_pressure_unchanged) {
  // tr(D) = 0: an isochoric motion must not change p in either mode.
  for (auto m : {HypoModulus::bulk, HypoModulus::report_eq2_lame})
    BOOST_TEST(default_hypo_pressure(3.5e8, 0.0, 1e-6, K, mu, with(m)) == 3.5e8);
}

BOOST_AUTO_TEST_CASE(reader_defaults_to_bulk_and_accepts_report_eq2_lame) {
  InputProblems problems("mat.json");
  const Json empty = Json::parse(R"({"type": "default_hypo"})");
  JsonReader r1(empty, "/eos", problems);
  BOOST_TEST((read_default_hypo(r1).modulus == HypoModulus::bulk));
  const Json lame = Json::parse(R"({"modulus": "report_eq2_lame"})");
  JsonReader r2(lame, "/eos", problems);
  BOOST_TEST((read_default_hypo(r2).modulus == HypoModulus::report_eq2_lame));
  BOOST_TEST(problems.empty());
}

BOOST_AUTO_TEST_CASE(reader_rejects_an_unknown_modulus_name_and_lists_the_known_ones) {
  expect_input_error_containing(R"({"modulus": "lame"})",
                                "mat.json: /equation_of_state/default_hypo/modulus: unknown name "
                                "\"lame\"; known: bulk, report_eq2_lame");
}

BOOST_AUTO_TEST_CASE(reader_rejects_an_unknown_key) {
  expect_input_error_containing(R"({"moduls": "bulk"})",
                                "/equation_of_state/default_hypo/moduls: unknown key");
}

BOOST_AUTO_TEST_SUITE_END()
