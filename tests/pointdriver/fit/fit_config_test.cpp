// FIT.json and CHECK.json readers: every problem named with the file and the JSON key path; the
// shipped examples read.
#include "pointdriver/fit/fit_config.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <boost/test/unit_test.hpp>

using namespace impact;
using namespace impact::pointdriver::fit;

namespace {

const std::string fits = std::string(IMPACT_SOURCE_DIR) + "/data/fits/";

std::string error_of(const Json& doc) {
  try {
    read_fit_config(doc, fits + "test.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(fit_config)

BOOST_AUTO_TEST_CASE(the_shipped_configurations_read) {
  const FitConfig room = read_fit_config(fits + "al6061_t6_room_temperature.json");
  BOOST_TEST(room.data.size() >= 15u);
  BOOST_TEST(!room.parameters[4].free);  // m fixed
  // A held at the curves' 0.2 % offset yield (docs/fitting.md, worked example 2); B free.
  BOOST_TEST(!room.parameters[0].free);
  BOOST_TEST(room.parameters[0].start.value() == 293.5e6);
  BOOST_TEST(room.parameters[1].free);
  BOOST_TEST(read_fit_config(fits + "al6061_t6_all.json").data.size() >= 35u);
  BOOST_TEST(read_fit_config(fits + "al6061_t6_damage_synthetic.json").mode == "damage");
  const CheckConfig check = read_check_config(fits + "al6061_t6_check_high_rate.json");
  BOOST_TEST(check.tolerance.rms_percent.has_value());
  BOOST_TEST(*check.tolerance.max == 80e6);
}

BOOST_AUTO_TEST_CASE(problems_name_the_key_path) {
  const Json base = {{"material", "data/materials/al6061_t6.json"},
                     {"data", {{{"glob", "data/experiments/al6061_t6/lee_*.csv"}}}}};
  BOOST_TEST(error_of(base).empty());
  Json typo = base;
  typo["paramters"] = Json::object();
  BOOST_TEST(contains(error_of(typo), "/paramters"));
  BOOST_TEST(contains(error_of(typo), "did you mean parameters"));
  Json bounds = base;
  bounds["parameters"] = {{"n", {{"start", 3.0}, {"upper", 2.0}}}};
  BOOST_TEST(contains(error_of(bounds), "/parameters/n/start"));
  Json no_match = base;
  no_match["data"] = {{{"glob", "data/experiments/al6061_t6/nothing_*.csv"}}};
  BOOST_TEST(contains(error_of(no_match), "/data/0/glob"));
  Json both = base;
  both["data"] = {{{"glob", "a*.csv"}, {"file", "b.csv"}}};
  BOOST_TEST(contains(error_of(both), "exactly one of"));
  Json mode = base;
  mode["mode"] = "strenght";
  BOOST_TEST(contains(error_of(mode), "/mode"));
  Json steps = base;
  steps["driver"] = {{"steps", "many"}};
  BOOST_TEST(contains(error_of(steps), "/driver/steps"));
  BOOST_TEST(contains(error_of(steps), "test.json"));
}

// Strength mode fits the parameters of the material's law by name: every parameter listed in
// the law's order with its default bounds, free when the law gives bounds and the material's
// value is not 0; a name the law lacks is named with its key path; a parameter with no default
// range can be freed only with bounds.
BOOST_AUTO_TEST_CASE(parameters_are_the_laws_by_name) {
  const Json za = {{"material", "data/materials/ofhc_copper_za.json"},
                   {"data", {{{"glob", "data/experiments/al6061_t6/lee_*.csv"}}}}};
  const FitConfig c = read_fit_config(za, fits + "test.json");
  std::vector<std::string> names, free;
  for (const ParameterSpec& s : c.parameters) {
    names.push_back(s.name);
    if (s.free) free.push_back(s.name);
  }
  const std::vector<std::string> all{
      "C0", "C1", "C2", "C3", "C4", "C5", "n", "reference_strain_rate", "minimum_strain_rate"};
  const std::vector<std::string> fcc{"C0", "C2", "C3", "C4"};  // C1, C5 are 0 in an fcc set
  BOOST_TEST(names == all, boost::test_tools::per_element());
  BOOST_TEST(free == fcc, boost::test_tools::per_element());
  BOOST_TEST(find_parameter(c, "C3")->lower == 0.0);
  BOOST_TEST(find_parameter(c, "C3")->upper == 0.05);
  BOOST_TEST(find_parameter(c, "C0")->unit == "Pa");
  Json jc_name = za;  // Johnson-Cook's A is not a Zerilli-Armstrong parameter
  jc_name["parameters"] = {{"A", {{"free", false}}}};
  BOOST_TEST(contains(error_of(jc_name), "/parameters/A"));
  Json no_range = za;
  no_range["parameters"] = {{"reference_strain_rate", {{"free", true}}}};
  BOOST_TEST(contains(error_of(no_range), "/parameters/reference_strain_rate/lower"));
  BOOST_TEST(contains(error_of(no_range), "no default range"));
  Json freed = za;
  freed["parameters"] = {
      {"reference_strain_rate", {{"free", true}, {"lower", 0.1}, {"upper", 10.0}}},
      {"C4", {{"free", false}}}};
  const FitConfig f = read_fit_config(freed, fits + "test.json");
  BOOST_TEST(find_parameter(f, "reference_strain_rate")->free);
  BOOST_TEST(!find_parameter(f, "C4")->free);
}

// A data entry may replace its files' strain rate and temperature; the replacement is reported
// with the experiment's conversions.
BOOST_AUTO_TEST_CASE(a_data_entry_replaces_rate_and_temperature) {
  const Json doc = {{"material", "data/materials/al6061_t6.json"},
                    {"data",
                     {{{"file", "data/experiments/al6061_t6/lee_298K_1000per_s.csv"},
                       {"strain_rate", 1200.0},
                       {"temperature", 300.0}}}}};
  const FitConfig c = read_fit_config(doc, fits + "test.json");
  BOOST_TEST_REQUIRE(c.data.size() == 1u);
  BOOST_TEST(*c.data[0].strain_rate == 1200.0);
  const std::vector<Experiment> e = read_experiments(c.data, 69e9);
  BOOST_TEST(e[0].strain_rate == 1200.0);
  BOOST_TEST(e[0].temperature == 300.0);
  const auto& notes = e[0].conversions;
  BOOST_TEST(std::count(notes.begin(), notes.end(),
                        "strain_rate 1000 -> 1200 1/s (the configuration's)") == 1);
  BOOST_TEST(std::count(notes.begin(), notes.end(),
                        "temperature 298 -> 300 K (the configuration's)") == 1);
  Json bad = doc;
  bad["data"][0]["strain_rate"] = -1.0;
  BOOST_TEST(contains(error_of(bad), "/data/0/strain_rate"));
}

// A glob without a folder matches beside the configuration file, whatever the working directory
// (before: the working directory, where "lee_*.csv" matched nothing or the wrong files).
BOOST_AUTO_TEST_CASE(a_bare_glob_matches_beside_the_configuration) {
  const std::string experiments = std::string(IMPACT_SOURCE_DIR) + "/data/experiments/al6061_t6/";
  const Json doc = {{"material", "data/materials/al6061_t6.json"},
                    {"data", {{{"glob", "lee_298K_*.csv"}}}}};
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  const FitConfig config = read_fit_config(doc, experiments + "fit.json");
  std::filesystem::current_path(cwd);
  const auto expected = glob_files(experiments + "lee_298K_*.csv");
  BOOST_TEST(!expected.empty());
  BOOST_REQUIRE(config.data.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) BOOST_TEST(config.data[i].file == expected[i]);
}

// A shortcut typed in degC is reported once, at the configuration's key; the material check of
// the overridden value said the same again before.
BOOST_AUTO_TEST_CASE(a_shortcut_in_celsius_warns_once) {
  const FitConfig config = read_fit_config(std::string(IMPACT_SOURCE_DIR) +
                                           "/tests/data/unit_warnings/fits/"
                                           "fit_room_temperature_in_celsius.json");
  const auto about_room_temperature = std::count_if(
      config.warnings.begin(), config.warnings.end(),
      [](const std::string& w) { return contains(w, "room_temperature: 21 looks like degC"); });
  BOOST_TEST(about_room_temperature == 1);
  BOOST_TEST(
      contains(config.warnings.at(0), "fit_room_temperature_in_celsius.json: /room_temperature"));
}

// Referenced files are checked with the configuration: a missing one is named at its key path,
// and the material (with the overrides) is validated before anything runs.
BOOST_AUTO_TEST_CASE(referenced_files_are_checked_at_their_key_path) {
  const Json base = {{"material", "data/materials/al6061_t6.json"},
                     {"data", {{{"file", "data/experiments/al6061_t6/cad_298K_0.001per_s.csv"}}}}};
  BOOST_TEST(error_of(base).empty());
  Json material = base;
  material["material"] = "data/materials/steel.json";
  BOOST_TEST(
      contains(error_of(material),
               "test.json: /material: cannot find the material file 'data/materials/steel.json'"));
  Json data = base;
  data["data"].push_back("data/experiments/none.csv");
  BOOST_TEST(
      contains(error_of(data),
               "test.json: /data/1: cannot find the experiment file 'data/experiments/none.csv'"));
  Json override = base;
  override["material_overrides"] = {{"density", -1.0}};
  BOOST_TEST(contains(error_of(override), "test.json: /material: in material "));
  BOOST_TEST(
      contains(error_of(override), "al6061_t6.json: /density: expected a number in (0, 30000]"));
  // A room temperature in degC: read, with one warning at its key path (the material it
  // overrides does not repeat it).
  Json celsius = base;
  celsius["room_temperature"] = 21.0;
  const FitConfig c = read_fit_config(celsius, fits + "test.json");
  BOOST_TEST_REQUIRE(c.warnings.size() == 1u);
  BOOST_TEST(contains(c.warnings[0], "test.json: /room_temperature: 21 looks like degC"));
}

BOOST_AUTO_TEST_CASE(a_glob_matches_star_and_question_mark_in_linear_time) {
  // '*' any run, '?' one character; counted against the directory's listing by hand. Twenty
  // stars that cannot match (no file name has twenty 'a's before a 'b') return at once: the
  // recursive matcher tried every split and the fuzzer timed out on such a name.
  const std::string dir = std::string(IMPACT_SOURCE_DIR) + "/data/experiments/al6061_t6/";
  const std::vector<std::string> cad = glob_files(dir + "cad_298K_*per_s.csv");
  BOOST_TEST(cad.size() == 2u);
  BOOST_TEST(glob_files(dir + "ca?_298K_0.001per_s.csv").size() == 1u);
  BOOST_TEST(glob_files(dir + "cad_298K_0.001per_s.cs").empty());
  // A name of 40 'a's against twenty "*a" and a 'b': the recursion tried every split, about
  // C(40, 20) = 1.4e11 of them; the greedy matcher about 40 x 41 steps.
  namespace fs = std::filesystem;
  const fs::path tmp = fs::temp_directory_path() / "impact_glob_test";
  fs::create_directories(tmp);
  { std::ofstream(tmp / std::string(40, 'a')) << ""; }
  std::string stars;
  for (int k = 0; k < 20; ++k) stars += "*a";
  BOOST_TEST(glob_files((tmp / (stars + "b")).string()).empty());
  BOOST_TEST(glob_files((tmp / (stars + "*")).string()).size() == 1u);
  fs::remove_all(tmp);
}

BOOST_AUTO_TEST_SUITE_END()
