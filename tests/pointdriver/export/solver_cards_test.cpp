// LS-DYNA and Abaqus cards of a Johnson-Cook material (pointdriver/export/solver_cards.hpp)
// against cards written by hand for data/materials/al6061_t6.json: rho = 2700 kg/m^3,
// K = 66.4 GPa, G = 26 GPa (E = 9KG/(3K+G) = 68.994671 GPa, nu = (3K-2G)/(2(3K+G)) =
// 0.3268206), A = 324 MPa, B = 114 MPa, n = 0.42, C = 0.002, m = 1.34, T_m = 925 K,
// T_r = 294 K, reference rate 1 /s, cp = 896 J/(kg K), D1..D5 = -0.77, 1.45, -0.47, 0, 1.6,
// chi = 0.9. In mm-ms-kg: stress in GPa (1 kg / (mm ms^2) = 1e9 Pa), density in kg/mm^3
// (2.7e-6), rate in 1/ms (0.001), cp in mm^2/(ms^2 K) (= J/(kg K): 896).
#include <boost/test/unit_test.hpp>

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
