// The experiment reader: bad data gives an InputError naming the file and the line; conversions
// (engineering -> true, total -> plastic, tension stopped at the maximum) are exact; every shipped
// 6061-T6 curve reads.
#include "pointdriver/fit/experiment_data.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "pointdriver/fit/fit_config.hpp"

using namespace impact;
using namespace impact::pointdriver::fit;

namespace {

const std::string header =
    "# test_type: uniaxial_compression\n"
    "# strain_rate [1/s]: 1000\n"
    "# temperature [K]: 294\n"
    "# strain_measure: true_plastic\n"
    "# stress_measure: true\n"
    "# source: test\n";

Experiment parse(const std::string& text, std::optional<double> E = std::nullopt) {
  std::istringstream in(text);
  return parse_experiment(in, "curve.csv", E);
}

/// The error message of parsing `text` ("" if it parses).
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(experiment_data)

BOOST_AUTO_TEST_CASE(a_good_curve_reads) {
  const Experiment e =
      parse(header + "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n0.05,3.5e8\n");
  BOOST_TEST(e.strain_rate == 1000.0);
  BOOST_TEST(e.temperature == 294.0);
  BOOST_TEST(e.plastic_strain.size() == 2u);
  BOOST_TEST(e.stress[1] == 3.5e8);
  BOOST_TEST(e.conversions.empty());
}

// A spreadsheet saving "CSV UTF-8" starts the file with the UTF-8 byte-order mark EF BB BF. The
// file is valid UTF-8 and reads exactly as without the mark (before, the mark made the first
// "# key: value" line a column header, and every header key was reported missing or misnamed).
BOOST_AUTO_TEST_CASE(a_utf8_byte_order_mark_is_read_past) {
  const std::string text =
      header + "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n0.05,3.5e8\n";
  const Experiment plain = parse(text);
  const Experiment marked = parse("\xEF\xBB\xBF" + text);
  BOOST_TEST(marked.strain_rate == plain.strain_rate);
  BOOST_TEST(marked.temperature == plain.temperature);
  BOOST_TEST(marked.source == "test");
  BOOST_TEST(marked.plastic_strain == plain.plastic_strain);
  BOOST_TEST(marked.stress == plain.stress);
}

// UTF-16 (Excel's "Unicode text") cannot be read line by line: one error saying how to save the
// file, at line 1, instead of an error on every line.
BOOST_AUTO_TEST_CASE(utf16_text_is_refused_with_what_to_do) {
  const std::string m = error_of(std::string("\xFF\xFE#\0 \0t\0", 8) + "\n");
  BOOST_TEST(contains(m, "curve.csv:1: the file is UTF-16 text"));
  BOOST_TEST(contains(m, "save it as UTF-8"));
  BOOST_TEST(!contains(m, "missing header line"));
}

BOOST_AUTO_TEST_CASE(empty_file) {
  const std::string m = error_of("");
  BOOST_TEST(contains(m, "curve.csv"));
  BOOST_TEST(contains(m, "missing header line '# test_type"));
  BOOST_TEST(contains(m, "no column header line"));
  const std::string m2 = error_of(header + "true_plastic_strain [-],true_stress [Pa]\n");
  BOOST_TEST(contains(m2, "no data rows"));
}

BOOST_AUTO_TEST_CASE(non_monotone_strain_names_the_line) {
  const std::string m = error_of(header +
                                 "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n"
                                 "0.05,3.5e8\n0.04,3.6e8\n");
  BOOST_TEST(contains(m, "curve.csv:10:"));
  BOOST_TEST(contains(m, "does not increase"));
}

BOOST_AUTO_TEST_CASE(nan_names_the_line) {
  const std::string m = error_of(header +
                                 "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n"
                                 "0.02,nan\n");
  BOOST_TEST(contains(m, "curve.csv:9:"));
  BOOST_TEST(contains(m, "NaN"));
  const std::string m2 =
      error_of(header + "true_plastic_strain [-],true_stress [Pa]\n0.01,abc\n0.02,3e8\n");
  BOOST_TEST(contains(m2, "curve.csv:8:"));
  BOOST_TEST(contains(m2, "not a number"));
}

BOOST_AUTO_TEST_CASE(stress_in_mpa_is_recognised_from_its_magnitude) {
  const std::string m = error_of(header +
                                 "true_plastic_strain [-],true_stress [Pa]\n0.01,330\n"
                                 "0.02,345\n");
  BOOST_TEST(contains(m, "curve.csv:9:"));  // the line of the largest stress
  BOOST_TEST(contains(m, "look like MPa"));
  // An unknown stress unit is named at the header line with the units the reader converts.
  const std::string m2 =
      error_of(header + "true_plastic_strain [-],true_stress [bar]\n0.01,3300\n0.02,3450\n");
  BOOST_TEST(contains(m2, "curve.csv:7:"));
  BOOST_TEST(contains(m2, "stress unit [bar] unknown"));
  BOOST_TEST(contains(m2, "Pa, kPa, MPa, GPa, psi, ksi"));
}

// The units labs write are converted on read and reported: a stress column in MPa (x 1e6), in
// ksi (x 6.894757293168361e6), a strain column in percent (x 0.01), the temperature in degC
// (+ 273.15) and Young's modulus in GPa (x 1e9). The same curve in SI reads to the same numbers.
BOOST_AUTO_TEST_CASE(declared_lab_units_are_converted_and_reported) {
  const Experiment si =
      parse(header + "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n0.02,3.45e8\n");
  const Experiment mpa =
      parse(header + "true_plastic_strain [%],true_stress [MPa]\n1,330\n2,345\n");
  BOOST_TEST_REQUIRE(mpa.stress.size() == si.stress.size());
  for (std::size_t k = 0; k < si.stress.size(); ++k) {
    BOOST_TEST(mpa.stress[k] == si.stress[k], boost::test_tools::tolerance(1e-15));
    BOOST_TEST(mpa.plastic_strain[k] == si.plastic_strain[k], boost::test_tools::tolerance(1e-15));
  }
  const auto reported = [](const Experiment& e, const std::string& part) {
    return std::any_of(e.conversions.begin(), e.conversions.end(),
                       [&](const std::string& c) { return contains(c, part); });
  };
  BOOST_TEST(reported(mpa, "stress column in MPa -> Pa (x 1e+06)"));
  BOOST_TEST(reported(mpa, "strain column in % -> fraction (x 0.01)"));
  const Experiment ksi =
      parse(header + "true_plastic_strain [-],true_stress [ksi]\n0.01,50\n0.02,52\n");
  BOOST_TEST(ksi.stress.front() == 50 * 6894757.293168361, boost::test_tools::tolerance(1e-15));
  std::string celsius = header;
  celsius.replace(celsius.find("temperature [K]: 294"), 20, "temperature [degC]: 20.85");
  const Experiment c =
      parse(celsius + "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n0.02,3.5e8\n");
  BOOST_TEST(c.temperature == 294.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.warnings.empty());
  BOOST_TEST(reported(c, "temperature 20.85 degC -> 294 K"));
  // A unit the reader does not convert is refused, naming the ones it does.
  std::string rankine = header;
  rankine.replace(rankine.find("temperature [K]: 294"), 20, "temperature [R]: 529");
  const std::string m =
      error_of(rankine + "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n0.02,3.5e8\n");
  BOOST_TEST(contains(m, "or K, degC, C"));
}

BOOST_AUTO_TEST_CASE(strain_in_percent_and_temperature_in_celsius) {
  const std::string m = error_of(header +
                                 "true_plastic_strain [-],true_stress [Pa]\n1,3.3e8\n"
                                 "20,3.5e8\n");
  BOOST_TEST(contains(m, "curve.csv:9:"));
  BOOST_TEST(contains(m, "percent"));  // declared [-]: a magnitude check, not a conversion
  // A temperature that looks like degC is possible (a cryogenic test): read, with a warning.
  std::string celsius = header;
  celsius.replace(celsius.find("294"), 3, "25");
  const Experiment e =
      parse(celsius + "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n0.02,3.5e8\n");
  BOOST_TEST(e.temperature == 25.0);
  BOOST_TEST_REQUIRE(e.warnings.size() == 1u);
  BOOST_TEST(e.warnings[0] ==
             "curve.csv:3: temperature 25 looks like degC (25 degC = 298.15 K); "
             "SI expects K; the value is used as given");
  BOOST_TEST(parse(header + "true_plastic_strain [-],true_stress [Pa]\n0.01,3.3e8\n0.02,3.5e8\n")
                 .warnings.empty());
}

BOOST_AUTO_TEST_CASE(bad_cells_name_the_line_and_the_column) {
  const std::string columns = "true_plastic_strain [-],true_stress [Pa]\n";
  const std::string m = error_of(header + columns + "0.01,3.3e8\n0.02,\n0.03\n0.04,3.4e8,1\n");
  BOOST_TEST(contains(m, "curve.csv:9: column 2 (true_stress [Pa]): empty cell"));
  BOOST_TEST(contains(m,
                      "curve.csv:10: short row: expected 2 values (true_plastic_strain [-], "
                      "true_stress [Pa]), got 1: '0.03'"));
  BOOST_TEST(contains(m, "curve.csv:11: long row"));
  const std::string m2 = error_of(header + columns + "0.01,\n0.02,\n");
  BOOST_TEST(contains(m2,
                      "curve.csv:7: column 2 (true_stress [Pa]) is empty (no value on any of "
                      "the 2 data rows)"));
  const std::string m3 = error_of(header + columns + "x,3.3e8\n0.02,inf\n");
  BOOST_TEST(contains(m3, "curve.csv:8: column 1 (true_plastic_strain [-]): not a number: 'x'"));
  BOOST_TEST(contains(m3, "curve.csv:9: column 2 (true_stress [Pa]): non-finite value"));
}

BOOST_AUTO_TEST_CASE(a_missing_unit_is_named) {
  const std::string m = error_of(header + "true_plastic_strain,true_stress\n0.01,3.3e8\n");
  BOOST_TEST(contains(m, "curve.csv:7: column 1 'true_plastic_strain' has no unit"));
  BOOST_TEST(
      contains(m, "curve.csv:7: column 2 'true_stress' has no unit: write 'true_stress [Pa]'"));
  std::string h = header;
  h.replace(h.find("# strain_rate [1/s]"), 19, "# strain_rate");
  const std::string m2 = error_of(h + "true_plastic_strain [-],true_stress [Pa]\n0.01,3e8\n");
  BOOST_TEST(contains(m2,
                      "curve.csv:2: header key 'strain_rate' has no unit: write it "
                      "'strain_rate [1/s]' (SI)"));
}

BOOST_AUTO_TEST_CASE(unknown_header_key_and_wrong_rate_unit) {
  std::string h = header;
  h.replace(h.find("# strain_rate [1/s]"), 19, "# strain_rate [1/ms]");
  const std::string m =
      error_of(h + "# temprature [K]: 3\ntrue_plastic_strain [-],true_stress [Pa]\n0.01,3e8\n");
  BOOST_TEST(contains(m, "curve.csv:2:"));
  BOOST_TEST(contains(m, "[1/s]"));
  BOOST_TEST(contains(m, "did you mean temperature"));
}

BOOST_AUTO_TEST_CASE(engineering_total_tension_is_converted_and_stopped_at_the_maximum) {
  const double E = 70e9;
  const std::string text =
      "# test_type: uniaxial_tension\n# strain_rate [1/s]: 0.001\n# temperature [K]: 294\n"
      "# strain_measure: engineering_total\n# stress_measure: engineering\n# source: test\n"
      "engineering_strain [-],engineering_stress [Pa]\n"
      "0.002,1.4e8\n0.02,3.0e8\n0.06,3.2e8\n0.10,3.3e8\n0.14,3.1e8\n";
  const Experiment e = parse(text, E);
  // The first point is elastic (eps_p < 0); the last is after the maximum.
  BOOST_REQUIRE(e.plastic_strain.size() == 3u);
  const double eps = std::log1p(0.10), sig = 3.3e8 * 1.10;
  BOOST_TEST(e.stress[2] == sig, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(e.plastic_strain[2] == eps - sig / E, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(e.conversions.size() == 5u);
  // Without a modulus, a total-strain curve is an error.
  BOOST_TEST(contains(error_of(text), "Young's modulus"));
}

BOOST_AUTO_TEST_CASE(engineering_compression_uses_the_compressive_formulas) {
  const std::string text =
      "# test_type: uniaxial_compression\n# strain_rate [1/s]: 0.001\n# temperature [K]: 294\n"
      "# strain_measure: engineering_total\n# stress_measure: engineering\n# source: test\n"
      "# youngs_modulus [Pa]: 7e10\n"
      "engineering_strain [-],engineering_stress [Pa]\n0.05,3.0e8\n0.10,3.2e8\n";
  const Experiment e = parse(text);
  const double eps = -std::log1p(-0.10), sig = 3.2e8 * 0.90;
  BOOST_TEST(e.stress[1] == sig, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(e.plastic_strain[1] == eps - sig / 7e10, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(every_shipped_6061_curve_reads_with_its_citation) {
  const auto files =
      glob_files(std::string(IMPACT_SOURCE_DIR) + "/data/experiments/al6061_t6/*.csv");
  BOOST_TEST(files.size() >= 30u);
  for (const auto& f : files) {
    const Experiment e = read_experiment(f);
    BOOST_TEST(!e.source.empty());
    BOOST_TEST(contains(e.converted_from, "SigEpsEp"));
    BOOST_TEST(e.plastic_strain.size() >= 5u);
    BOOST_TEST(e.stress.front() > 1e7);  // Pa, not MPa
  }
}

BOOST_AUTO_TEST_CASE(a_missing_file_is_named) {
  try {
    read_experiment("no_such_curve.csv");
    BOOST_FAIL("expected an InputError");
  } catch (const InputError& e) {
    BOOST_TEST(contains(e.what(), "no_such_curve.csv"));
  }
}

BOOST_AUTO_TEST_SUITE_END()
