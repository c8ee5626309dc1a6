// LS-DYNA and Abaqus cards of a Johnson-Cook material (pointdriver/export/solver_cards.hpp)
// against cards written by hand for data/materials/al6061_t6.json: rho = 2700 kg/m^3,
// K = 66.4 GPa, G = 26 GPa (E = 9KG/(3K+G) = 68.994671 GPa, nu = (3K-2G)/(2(3K+G)) =
// 0.3268206), A = 324 MPa, B = 114 MPa, n = 0.42, C = 0.002, m = 1.34, T_m = 925 K,
// T_r = 294 K, reference rate 1 /s, cp = 896 J/(kg K), D1..D5 = -0.77, 1.45, -0.47, 0, 1.6,
// chi = 0.9. In mm-ms-kg: stress in GPa (1 kg / (mm ms^2) = 1e9 Pa), density in kg/mm^3
// (2.7e-6), rate in 1/ms (0.001), cp in mm^2/(ms^2 K) (= J/(kg K): 896).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <sstream>

#include "pointdriver/export/solver_cards.hpp"

using namespace impact;
using namespace impact::pointdriver;

namespace {

const std::string kAluminium = std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json";

// The text from the first line starting with `marker` (the comment line before it names the
// file's absolute path).
std::string from(const std::string& cards, const std::string& marker) {
  return cards.substr(cards.find(marker));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(solver_cards)

BOOST_AUTO_TEST_CASE(ls_dyna_mat_johnson_cook_in_mm_ms_kg) {
  const std::string expected =
      "*MAT_JOHNSON_COOK\n"
      "$#     mid        ro         g         e        pr       dtf        vp    rateop\n"
      "         1    2.7e-6        26 68.994671 0.3268206         0         0         0\n"
      "$#       a         b         n         c         m        tm        tr      epso\n"
      "     0.324     0.114      0.42     0.002      1.34       925       294     0.001\n"
      "$#      cp        pc     spall        it        d1        d2        d3        d4\n"
      "       896     -1e20         1         1     -0.77      1.45     -0.47         0\n"
      "$#      d5\n"
      "       1.6\n"
      "*EOS_LINEAR_POLYNOMIAL\n"
      "$#   eosid        c0        c1        c2        c3        c4        c5        c6\n"
      "         1         0      66.4         0         0         0         0         0\n"
      "$#      e0        v0\n"
      "         0         1\n";
  const std::string cards = ls_dyna_cards(load_material(kAluminium), unit_system("mm-ms-kg"));
  BOOST_TEST(from(cards, "*MAT_JOHNSON_COOK") == expected);
}

BOOST_AUTO_TEST_CASE(ls_dyna_in_si_keeps_pascals) {
  const std::string cards = ls_dyna_cards(load_material(kAluminium), unit_system("SI"));
  BOOST_TEST(cards.find("         1      2700    2.6e10 6.8995e10 0.3268206         0         0"
                        "         0\n") != std::string::npos);
  BOOST_TEST(cards.find("    3.24e8    1.14e8      0.42     0.002      1.34       925       294"
                        "         1\n") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(abaqus_johnson_cook_in_mm_ms_kg) {
  const std::string expected =
      "*MATERIAL, NAME=al6061_t6\n"
      "*DENSITY\n"
      "2.7e-06\n"
      "*ELASTIC\n"
      "68.9946714, 0.3268206039\n"
      "*PLASTIC, HARDENING=JOHNSON COOK\n"
      "0.324, 0.114, 0.42, 1.34, 925, 294\n"
      "*RATE DEPENDENT, TYPE=JOHNSON COOK\n"
      "0.002, 0.001\n"
      "*SPECIFIC HEAT\n"
      "896\n"
      "*INELASTIC HEAT FRACTION\n"
      "0.9\n";
  const std::string cards = abaqus_cards(load_material(kAluminium), unit_system("mm-ms-kg"));
  BOOST_TEST(from(cards, "*MATERIAL") == expected);
}

// A Mie-Gruneisen material gets *EOS_GRUNEISEN (copper: C0 = 3940 m/s, S = 1.489, Gamma0 = 2.02);
// in mm-ms-kg a speed in mm/ms equals its value in m/s.
BOOST_AUTO_TEST_CASE(mie_gruneisen_gets_eos_gruneisen) {
  const std::string copper = std::string(IMPACT_SOURCE_DIR) + "/data/materials/ofhc_copper_jc.json";
  const std::string cards = ls_dyna_cards(load_material(copper), unit_system("mm-ms-kg"));
  BOOST_TEST(from(cards, "*EOS_GRUNEISEN") ==
             "*EOS_GRUNEISEN\n"
             "$#   eosid         c        s1        s2        s3    gamao         a        e0\n"
             "         1      3940     1.489         0         0      2.02         0         0\n"
             "$#      v0\n"
             "         1\n");
}

// Swift x Cowper-Symonds as LS-DYNA's *MAT_POWER_LAW_PLASTICITY (MAT_018), written by hand for
// the 6061-T6 file with Bodner & Symonds' aluminium rate constants on an illustrative Swift set
// (K = 420 MPa, eps0 = 0.005, n = 0.08, D = 6500 /s, q = 4). MAT_018's sigma_y = k (eps_yp +
// ep)^N [1 + (rate / SRC)^(1 / SRP)] is Swift's K (eps0 + ep)^n with k = K, N = n and eps_yp =
// eps0, which SIGY below 0.02 gives directly (the manual: "LT.0.02: eps_yp = SIGY"). In mm-ms-kg:
// k = 0.42 GPa, SRC = 6500 /s = 6.5 /ms; VP = 1 (the rate is the plastic strain rate).
Json swift(double K, double eps0) {
  return {{"constitutive_model",
           {{"flow_stress",
             {{"type", "cowper_symonds"},
              {"A", nullptr},
              {"B", nullptr},
              {"C", nullptr},
              {"m", nullptr},
              {"reference_strain_rate", nullptr},
              {"rate_form", nullptr},
              {"K", K},
              {"eps0", eps0},
              {"n", 0.08},
              {"D", 6500.0},
              {"q", 4.0}}}}}};
}

BOOST_AUTO_TEST_CASE(ls_dyna_power_law_plasticity_in_mm_ms_kg) {
  const std::string cards =
      ls_dyna_cards(load_material(kAluminium, swift(420e6, 0.005)), unit_system("mm-ms-kg"));
  BOOST_TEST(from(cards, "*MAT_POWER_LAW_PLASTICITY") ==
             "*MAT_POWER_LAW_PLASTICITY\n"
             "$#     mid        ro         e        pr         k         n       src       srp\n"
             "         1    2.7e-6 68.994671 0.3268206      0.42      0.08       6.5         4\n"
             "$#    sigy        vp\n"
             "     0.005         1\n");
  BOOST_TEST(cards.find("*EOS") == std::string::npos);  // MAT_018 takes no equation of state
  BOOST_TEST(cards.find("Johnson-Cook damage is not written") != std::string::npos);
}

// eps0 = 0.05 is not below 0.02, so SIGY is the first yield K eps0^n, from which LS-DYNA takes
// eps_yp = (SIGY / k)^(1/N): read back from the card (mm-s-tonne, MPa), that is eps0 to the
// printed digits. In mm-ms-kg a 25 MPa Swift K gives SIGY = 0.0197 GPa, below 0.02: LS-DYNA would
// read it as a strain, so the card is refused, naming the key and a unit system that works.
BOOST_AUTO_TEST_CASE(sigy_as_a_yield_stress_and_its_limit) {
  const std::string cards =
      ls_dyna_cards(load_material(kAluminium, swift(420e6, 0.05)), unit_system("mm-s-tonne"));
  const std::string rows = from(cards, "$#    sigy");
  const double sigy = std::stod(rows.substr(rows.find('\n') + 1, 10));
  BOOST_TEST(sigy == 420.0 * std::pow(0.05, 0.08), boost::test_tools::tolerance(1e-7));
  BOOST_TEST(std::pow(sigy / 420.0, 1.0 / 0.08) == 0.05, boost::test_tools::tolerance(1e-5));
  BOOST_CHECK_EXCEPTION(
      ls_dyna_cards(load_material(kAluminium, swift(25e6, 0.05)), unit_system("mm-ms-kg")),
      std::invalid_argument, [](const std::invalid_argument& e) {
        const std::string m = e.what();
        return m.find("/constitutive_model/flow_stress/eps0") != std::string::npos &&
               m.find("no exact *MAT_POWER_LAW_PLASTICITY in units mm-ms-kg") != std::string::npos;
      });
}

// Abaqus has no Swift hardening: the curve is tabulated. Linear interpolation of the table (as
// Abaqus reads it) is within 1e-3 of K (eps0 + ep)^n everywhere up to its last plastic strain 5
// (measured at 40 points per interval), starts at (K eps0^n, 0), and the rate dependence is
// Abaqus's power law eps_dot_p = D (sigma / sigma0 - 1)^q, Cowper-Symonds' form: D, q.
BOOST_AUTO_TEST_CASE(abaqus_tabulated_swift_with_power_law_rate) {
  const Material m = load_material(kAluminium, swift(420e6, 0.005));
  const std::string cards = abaqus_cards(m, unit_system("SI"));
  BOOST_TEST(cards.find("*RATE DEPENDENT, TYPE=POWER LAW\n6500, 4\n") != std::string::npos);
  const auto swift_law = [](double ep) { return 420e6 * std::pow(0.005 + ep, 0.08); };
  const auto table = swift_table(std::get<CowperSymondsParams>(m.model.params().flow_stress));
  BOOST_TEST_REQUIRE(table.size() >= 2u);
  BOOST_TEST(table.front()[0] == swift_law(0.0));
  BOOST_TEST(table.front()[1] == 0.0);
  BOOST_TEST(table.back()[1] == 5.0);
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < table.size(); ++k) {
    for (int j = 0; j <= 40; ++j) {
      const double t = j / 40.0;
      const double ep = table[k][1] + t * (table[k + 1][1] - table[k][1]);
      const double interpolated = table[k][0] + t * (table[k + 1][0] - table[k][0]);
      worst = std::max(worst, std::abs(interpolated / swift_law(ep) - 1.0));
    }
  }
  BOOST_TEST_MESSAGE(table.size() << " rows, worst interpolation error " << worst);
  BOOST_TEST(worst < 1e-3);
  // The first row is in the card, in Pa (SI), right after *PLASTIC.
  std::ostringstream first;
  first.precision(10);
  first << "*PLASTIC\n" << swift_law(0.0) << ", 0\n";
  BOOST_TEST(cards.find(first.str()) != std::string::npos);
}

BOOST_AUTO_TEST_CASE(other_laws_and_unknown_units_are_refused) {
  const std::string za = std::string(IMPACT_SOURCE_DIR) + "/data/materials/ofhc_copper_za.json";
  BOOST_CHECK_EXCEPTION(ls_dyna_cards(load_material(za), unit_system("SI")), std::invalid_argument,
                        [](const std::invalid_argument& e) {
                          return std::string(e.what()).find("zerilli_armstrong") !=
                                 std::string::npos;
                        });
  BOOST_CHECK_EXCEPTION(unit_system("cgs"), std::invalid_argument,
                        [](const std::invalid_argument& e) {
                          return std::string(e.what()).find("mm-ms-kg") != std::string::npos;
                        });
}

BOOST_AUTO_TEST_SUITE_END()
