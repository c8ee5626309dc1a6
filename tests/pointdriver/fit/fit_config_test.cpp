// FIT.json and CHECK.json readers: every problem named with the file and the JSON key path; the
// shipped examples read.
#include "pointdriver/fit/fit_config.hpp"

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
  BOOST_TEST(room.parameters[0].free);
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
  // A room temperature in degC: read, with a warning at its key path (and one from the material
  // it overrides).
  Json celsius = base;
  celsius["room_temperature"] = 21.0;
  const FitConfig c = read_fit_config(celsius, fits + "test.json");
  BOOST_TEST_REQUIRE(c.warnings.size() == 2u);
  BOOST_TEST(contains(c.warnings[0], "test.json: /room_temperature: 21 looks like degC"));
  BOOST_TEST(contains(c.warnings[1], "/material: in material "));
}

BOOST_AUTO_TEST_SUITE_END()
