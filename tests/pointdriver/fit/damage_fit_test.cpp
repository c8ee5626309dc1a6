// Johnson-Cook damage fit (eq. 7 at constant triaxiality): recovery of D1..D5 from fracture
// strains made with a known set at 10 triaxialities, 5 rates and 4 temperatures, start 30 % off
// (D4: 0.02 for a true 0.1): without scatter to 1e-6; with 3 % scatter (fixed seed) within 3
// standard errors. The reader names the file and line of bad rows.
#include "pointdriver/fit/damage_fit.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

using namespace impact;
using namespace impact::pointdriver::fit;

namespace {

const std::vector<double> truth{0.05, 0.8, -1.5, 0.1, 1.6};

std::vector<FracturePoint> synthetic(const JohnsonCookDamageParams& base, double scatter) {
  std::vector<FracturePoint> pts;
  for (double eta : {-0.2, 0.0, 0.2, 1.0 / 3.0, 0.5, 0.7, 0.9, 1.2, 1.6, 2.0})
    pts.push_back({eta, 1e-3, 294.0, 0.0, 0});
  for (double rate : {1e-1, 10.0, 1e2, 1e3, 1e4}) pts.push_back({1.0 / 3.0, rate, 294.0, 0.0, 0});
  for (double T : {350.0, 450.0, 550.0, 700.0}) pts.push_back({1.0 / 3.0, 1e-3, T, 0.0, 0});
  const auto e = fracture_strains(base, truth, pts);
  std::mt19937 rng(42);
  std::normal_distribution<double> z(0.0, 1.0);
  for (std::size_t k = 0; k < pts.size(); ++k)
    pts[k].fracture_strain = e[k] * (1.0 + scatter * z(rng));
  return pts;
}

std::vector<Parameter> start() {
  return {{"D1", 0.065, true, -3, 3},
          {"D2", 0.56, true, -10, 10},
          {"D3", -1.95, true, -10, 10},
          {"D4", 0.02, true, -1, 1},
          {"D5", 1.12, true, -10, 10}};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(damage_fit)

BOOST_AUTO_TEST_CASE(exact_fracture_strains_give_the_truth) {
  JohnsonCookDamageParams base;
  const auto pts = synthetic(base, 0.0);
  const auto r = fit_damage(pts, base, start(), {});
  for (std::size_t i = 0; i < 5; ++i) {
    BOOST_TEST_MESSAGE("D" << i + 1 << " fitted " << r.values[i] << " truth " << truth[i]);
    BOOST_TEST(std::abs(r.values[i] - truth[i]) <= 1e-6 * std::abs(truth[i]));
  }
}

BOOST_AUTO_TEST_CASE(three_percent_scatter_within_3_standard_errors) {
  JohnsonCookDamageParams base;
  const auto pts = synthetic(base, 0.03);
  const auto r = fit_damage(pts, base, start(), {});
  for (std::size_t i = 0; i < 5; ++i) {
    BOOST_TEST_MESSAGE("D" << i + 1 << " fitted " << r.values[i] << " +- " << r.std_errors[i]
                           << " truth " << truth[i]);
    BOOST_TEST(r.std_errors[i] > 0.0);
    BOOST_TEST(std::abs(r.values[i] - truth[i]) <= 3.0 * r.std_errors[i]);
  }
}

BOOST_AUTO_TEST_CASE(bad_rows_name_the_file_and_line) {
  const std::string file = (std::filesystem::temp_directory_path() / "bad_fracture.csv").string();
  std::ofstream(file) << "# source: test\n"
                         "triaxiality [-],strain_rate [1/s],temperature [K],fracture_strain [-]\n"
                         "0.33,1e-3,294,0.4\n0.33,1e-3,25,0.4\n0.5,nan,294,0.3\n";
  try {
    read_fracture_data(file);
    BOOST_FAIL("expected an InputError");
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("bad_fracture.csv:4:") == std::string::npos);  // 25 K: a warning only
    BOOST_TEST(m.find("bad_fracture.csv:5: column 2 (strain_rate [1/s]): non-finite value") !=
               std::string::npos);
  }
  // A temperature that looks like degC (25) is possible (a cryogenic test): read, with a warning.
  std::ofstream(file) << "# source: test\n"
                         "triaxiality [-],strain_rate [1/s],temperature [K],fracture_strain [-]\n"
                         "0.33,1e-3,294,0.4\n0.33,1e-3,25,0.4\n";
  const FractureData d = read_fracture_data(file);
  BOOST_TEST(d.points.size() == 2u);
  BOOST_TEST_REQUIRE(d.warnings.size() == 1u);
  BOOST_TEST(d.warnings[0].find("bad_fracture.csv:4: temperature 25 looks like degC") !=
             std::string::npos);
}

// The fracture-strain reader reads past a UTF-8 byte-order mark (a spreadsheet's "CSV UTF-8"):
// the citation on the marked first line is kept, the points are those of the unmarked file.
BOOST_AUTO_TEST_CASE(a_utf8_byte_order_mark_is_read_past) {
  const std::string file = (std::filesystem::temp_directory_path() / "bom_fracture.csv").string();
  std::ofstream(file) << "\xEF\xBB\xBF# source: test\n"
                         "triaxiality [-],strain_rate [1/s],temperature [K],fracture_strain [-]\n"
                         "0.33,1e-3,294,0.4\n0.5,1e-3,294,0.3\n";
  const FractureData d = read_fracture_data(file);
  BOOST_TEST(d.source == "test");
  BOOST_TEST_REQUIRE(d.points.size() == 2u);
  BOOST_TEST(d.points[1].triaxiality == 0.5);
  BOOST_TEST(d.points[1].fracture_strain == 0.3);
}

BOOST_AUTO_TEST_SUITE_END()
