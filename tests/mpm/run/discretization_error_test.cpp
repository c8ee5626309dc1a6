// The error bar from a ladder table (summary.json "discretization_error", docs/mpm.md#output;
// mpm/run/discretization_error.hpp) on tables and summaries written here:
// - a level with this run's fingerprint: per observable the run's value at its JSON pointer, the
//   table's extrapolated value, order, GCI and status, and error = (value - extrapolated) /
//   abs(extrapolated) where the table says the extrapolation is quotable, null when it is not, or
//   the extrapolated value is null or 0 (then the table's range is carried); an observable whose
//   pointer names no number here is left out; a string that is no JSON pointer gives that
//   observable the status "path not found in this run's summary";
// - a value that differs from the ladder's own run of the level by more than the larger of 1e-3
//   relative and 1 % of the change to a neighbouring level: the table is stale (another code or
//   material data), not quotable;
// - no matching level: the status sentence with the fingerprint;
// - malformed tables (not JSON, wrong types, missing keys): "unreadable: <reason>" naming the
//   key path, never an exception (a directory where the table would be: not a regular file);
// - the table is "<stem>.ladder.json" beside the scene file; none there: no key.
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>

#include "mpm/run/discretization_error.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;

namespace {

const std::string kMine = "0123456789abcdef";

Json summary() {
  return {{"observables", {{"crater", {{"depth [m]", 0.009}, {"object", "target"}}}}},
          {"final", {{"energy_error", -1e-3}}}};
}

// `level_value`: the ladder's own run of the matching level (values[1]), what this run repeats.
Json observable(const std::string& name, const std::string& path, const Json& extrapolated,
                double level_value = 0.009) {
  return {{"name", name},
          {"path", path},
          {"unit", "m"},
          {"values", {0.0095, level_value}},
          {"extrapolated", extrapolated},
          {"order", 1.06},
          {"gci_fine [-]", 0.05},
          {"status", "extrapolated"},
          {"quotable", true}};
}

Json table(const std::string& fingerprint = kMine);

Json with_conservative(Json o) {
  o["gci_conservative [-]"] = 0.12;
  return o;
}

Json table(const std::string& fingerprint) {
  return {{"scene", "data/scenes/sphere_cylinder/recommended.json"},
          {"command", "python3 -m campaigns.study.ladder"},
          {"commit", "750b794"},
          {"date", "2026-11-28"},
          {"levels",
           {{{"level", 1.0}, {"fingerprint", "ffffffffffffffff"}, {"cells", {50, 20, 20}}},
            {{"level", 2.0}, {"fingerprint", fingerprint}, {"cells", {100, 40, 40}}}}},
          {"observables",
           {with_conservative(observable("crater depth", "/observables/crater/depth [m]", 0.0084)),
            observable("no extrapolation", "/observables/crater/depth [m]", nullptr),
            observable("zero", "/final/energy_error", 0.0, -1e-3),
            observable("missing", "/observables/crater/volume [m^3]", 1.0),
            observable("not a number", "/observables/crater/object", 1.0),
            observable("into a string", "/observables/crater/object/x", 1.0),
            observable("bad pointer", "observables/crater", 1.0)}}};
}

Json of(const Json& t) {
  return discretization_error_of("T.ladder.json", t.dump(), kMine, summary());
}

std::string status_of(const std::string& text) {
  const Json e = discretization_error_of("T.ladder.json", text, kMine, summary());
  BOOST_TEST(e.at("table") == "T.ladder.json");
  BOOST_TEST(!e.contains("observables"));
  return e.at("status").get<std::string>();
}

// The status of an unreadable table starts with the reason, naming the key path.
void starts(const std::string& status, const std::string& reason) {
  BOOST_TEST(status.rfind("unreadable: " + reason, 0) == 0u, status << " / " << reason);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_discretization_error)

BOOST_AUTO_TEST_CASE(a_matching_level_gives_each_observables_error) {
  const Json e = of(table());
  BOOST_TEST_MESSAGE(e.dump(2));
  BOOST_TEST(e.at("table") == "T.ladder.json");
  BOOST_TEST(e.at("level").get<double>() == 2.0);
  BOOST_TEST(e.at("ladder_commit") == "750b794");
  BOOST_TEST(!e.contains("status"));
  const Json& o = e.at("observables");
  const Json& depth = o.at("crater depth");
  BOOST_TEST(depth.at("path") == "/observables/crater/depth [m]");
  BOOST_TEST(depth.at("value").get<double>() == 0.009);
  BOOST_TEST(depth.at("extrapolated").get<double>() == 0.0084);
  BOOST_TEST(depth.at("error [-]").get<double>() == (0.009 - 0.0084) / 0.0084);
  BOOST_TEST(depth.at("gci_fine [-]").get<double>() == 0.05);
  BOOST_TEST(depth.at("order").get<double>() == 1.06);
  BOOST_TEST(depth.at("status") == "extrapolated");
  BOOST_TEST(depth.at("gci_conservative [-]").get<double>() == 0.12);
  BOOST_TEST(!o.at("zero").contains("gci_conservative [-]"));  // optional: absent, not invented
  // No extrapolated value, or 0: no relative error.
  BOOST_TEST(o.at("no extrapolation").at("error [-]").is_null());
  BOOST_TEST(o.at("no extrapolation").at("value").get<double>() == 0.009);
  BOOST_TEST(o.at("zero").at("error [-]").is_null());
  BOOST_TEST(o.at("zero").at("value").get<double>() == -1e-3);
  // A pointer that names no number in this summary: left out.
  BOOST_TEST(!o.contains("missing"));
  BOOST_TEST(!o.contains("not a number"));
  BOOST_TEST(!o.contains("into a string"));
  // Not a JSON pointer at all: that observable only.
  BOOST_TEST(o.at("bad pointer").at("status") == "path not found in this run's summary");
  BOOST_TEST(!o.at("bad pointer").contains("value"));
  BOOST_TEST(o.size() == 4u);
  BOOST_TEST(!e.contains("scope"));  // a uniform ladder: no scope
}

// A graded grid's ladder refines its box alone; the table says so ("scope") and the error bar
// carries it to the run's summary, so that the GCI is not read as the whole grid's.
BOOST_AUTO_TEST_CASE(a_ladders_scope_is_carried_to_the_run) {
  Json t = table();
  t["scope"] = "the refined box of a graded grid";
  BOOST_TEST(of(t).at("scope") == "the refined box of a graded grid");
  t["scope"] = 3;
  starts(status_of(t.dump()), "/scope: expected a string, got 3");
}

// Issue 52: where the ladder is not in the asymptotic range or its order is implausible, no
// signed error against the one extrapolated value is given (the summary printed -180.9 % off an
// "extrapolated" +22.8 m/s while every level was negative); the range the table gives is carried
// instead. A table from before the key ("quotable" absent) is never quotable; a key of the wrong
// type makes the table unreadable.
BOOST_AUTO_TEST_CASE(an_extrapolation_that_may_not_be_quoted_gives_its_range_not_an_error) {
  Json t = table();
  Json& depth = t["observables"][0];
  depth["quotable"] = false;
  depth["status"] = "implausible order 2.4; not in the asymptotic range";
  depth["range"] = {{"low", 0.0075}, {"high", 0.0081}, {"unit", "m"}, {"basis", "p in [1, 2.43]"}};
  depth["verdict"] = "order 2.43 outside the plausible [0.5, 2]; not in the asymptotic range";
  const Json e = of(t).at("observables").at("crater depth");
  BOOST_TEST_MESSAGE(e.dump());
  BOOST_TEST(e.at("value").get<double>() == 0.009);
  BOOST_TEST(e.at("error [-]").is_null());
  BOOST_TEST(e.at("quotable") == false);
  BOOST_TEST(e.at("range").at("low").get<double>() == 0.0075);
  BOOST_TEST(e.at("range").at("high").get<double>() == 0.0081);
  BOOST_TEST(e.at("range").at("basis") == "p in [1, 2.43]");
  BOOST_TEST(e.at("verdict") ==
             "order 2.43 outside the plausible [0.5, 2]; not in the asymptotic range");
  depth.erase("quotable");
  BOOST_TEST(of(t).at("observables").at("crater depth").at("error [-]").is_null());
  BOOST_TEST(of(t).at("observables").at("crater depth").at("quotable") == false);
  depth["verdict"] = 3;
  starts(status_of(t.dump()), "/observables/0/verdict: expected a string");
  depth["verdict"] = "not in the asymptotic range";
  depth["quotable"] = "yes";
  starts(status_of(t.dump()), "/observables/0/quotable: expected true or false");
  depth["quotable"] = false;
  depth["range"] = {{"low", 0.0075}};
  starts(status_of(t.dump()), "/observables/0/range/high: expected a number");
}

// Issue 52: a table made by another code (or material data) was applied silently: the run
// repeats the level's scene, same fingerprint, but its value is not the ladder's. Beyond the
// larger of 1e-3 relative and 1 % of the ladder's step to a neighbouring level the entry says
// stale, gives no error or quotable extrapolation (the range is kept); within it the entry is
// the table's.
BOOST_AUTO_TEST_CASE(a_run_that_does_not_repeat_its_levels_value_marks_the_table_stale) {
  Json t = table();
  Json& depth = t["observables"][0];
  depth["range"] = {{"low", 0.0075}, {"high", 0.0081}, {"unit", "m"}, {"basis", "p in [1, 2]"}};
  depth["values"] = {0.0095, 0.009 * (1.0 + 0.9e-3)};
  const Json same = of(t).at("observables").at("crater depth");
  BOOST_TEST(same.at("quotable") == true);
  BOOST_TEST(same.at("status") == "extrapolated");
  BOOST_TEST(same.contains("range"));
  BOOST_TEST(!same.contains("ladder_value"));
  depth["values"] = {0.0095, 0.0091};  // 1.1 % off the run's 0.009
  const Json stale = of(t).at("observables").at("crater depth");
  BOOST_TEST_MESSAGE(stale.dump());
  BOOST_TEST(stale.at("quotable") == false);
  BOOST_TEST(stale.at("error [-]").is_null());
  BOOST_TEST(stale.at("range").at("low").get<double>() == 0.0075);  // kept, under the verdict
  BOOST_TEST(stale.at("value").get<double>() == 0.009);
  BOOST_TEST(stale.at("ladder_value").get<double>() == 0.0091);
  BOOST_TEST(stale.at("verdict") == "stale table: re-run the ladder");
  BOOST_TEST(stale.at("status").get<std::string>().rfind(
                 "stale: this run gives 0.009, the ladder's run of this level gave 0.0091", 0) ==
             0u);
  // Where the ladder's own levels differ by much more (0.0195 against 0.0091), 1 % of that step
  // (1.04e-4) is the tolerance: 0.0091 against the run's 0.009 is round-off of such a quantity.
  depth["values"] = {0.0195, 0.0091};
  BOOST_TEST(of(t).at("observables").at("crater depth").at("quotable") == true);
  // Other observables of the same table are judged on their own values.
  BOOST_TEST(of(t).at("observables").at("zero").at("status") == "extrapolated");
  depth["values"] = {0.0095};
  starts(status_of(t.dump()), "/observables/0/values: expected one entry per level (2)");
}

// A null path (Lf, Dm: measured by the ladder from snapshots, not in summary.json): the value is
// the ladder's own at the matching level (the second: values[1]), marked as such.
BOOST_AUTO_TEST_CASE(an_observable_without_a_path_takes_the_ladders_value_of_the_level) {
  Json t = table();
  t["observables"][0]["path"] = nullptr;
  t["observables"][0]["values"] = {0.0095, 0.0091};
  const Json e = of(t);
  const Json& depth = e.at("observables").at("crater depth");
  BOOST_TEST(depth.at("path").is_null());
  BOOST_TEST(depth.at("value").get<double>() == 0.0091);
  BOOST_TEST(depth.at("error [-]").get<double>() == (0.0091 - 0.0084) / 0.0084);
  BOOST_TEST(depth.at("value_source").get<std::string>().find("ladder") != std::string::npos);
  // No number for the level (a failed run there): left out.
  t["observables"][0]["values"] = {0.0095, nullptr};
  BOOST_TEST(!of(t).at("observables").contains("crater depth"));
  // Not one entry per level, or a string: the table is unreadable, not silently short.
  t["observables"][0]["values"] = {0.0095};
  starts(status_of(t.dump()), "/observables/0/values: expected one entry per level (2), got 1");
  t["observables"][0]["values"] = {0.0095, "0.0091"};
  starts(status_of(t.dump()), "/observables/0/values/1: expected a number or null");
}

// Two levels with one fingerprint would name one run twice: the table is unreadable.
BOOST_AUTO_TEST_CASE(two_levels_with_one_fingerprint_make_the_table_unreadable) {
  Json t = table();
  t["levels"][0]["fingerprint"] = kMine;
  starts(status_of(t.dump()),
         "/levels/1/fingerprint: the same as /levels/0/fingerprint (two levels cannot be one "
         "scene)");
}

BOOST_AUTO_TEST_CASE(no_matching_level_says_so) {
  const Json e = of(table("aaaaaaaaaaaaaaaa"));
  BOOST_TEST(e == Json({{"table", "T.ladder.json"},
                        {"status", "no level of the ladder matches this scene (fingerprint " +
                                       kMine + ")"}}));
}

BOOST_AUTO_TEST_CASE(a_malformed_table_is_unreadable_naming_the_key_path) {
  starts(status_of("{\"levels\": ["), "not JSON");
  starts(status_of(""), "not JSON");
  starts(status_of("[1, 2]"), "/: expected an object");
  Json t = table();
  t.erase("levels");
  starts(status_of(t.dump()), "/levels: missing");
  t = table();
  t["levels"] = "many";
  starts(status_of(t.dump()), "/levels: expected an array");
  t = table();
  t["levels"][1]["fingerprint"] = 12345;
  starts(status_of(t.dump()), "/levels/1/fingerprint: expected a string, got 12345");
  t = table();
  t["levels"][0] = 7;
  starts(status_of(t.dump()), "/levels/0: expected an object");
  t = table();
  t["levels"][0].erase("level");
  starts(status_of(t.dump()), "/levels/0/level: missing");
  t = table();
  t["levels"][1]["level"] = "fine";
  starts(status_of(t.dump()), "/levels/1/level: expected a number, got \"fine\"");
  t = table();
  t.erase("commit");
  starts(status_of(t.dump()), "/commit: missing");
  t = table();
  t["observables"] = Json::object();
  starts(status_of(t.dump()), "/observables: expected an array");
  t = table();
  t["observables"][0].erase("name");
  starts(status_of(t.dump()), "/observables/0/name: missing");
  t = table();
  t["observables"][2]["extrapolated"] = "0.0084";
  starts(status_of(t.dump()), "/observables/2/extrapolated: expected a number or null");
  t = table();
  t["observables"][1]["gci_fine [-]"] = Json::array();
  starts(status_of(t.dump()), "/observables/1/gci_fine [-]: expected a number or null");
  t = table();
  t["observables"][0]["path"] = 1;
  starts(status_of(t.dump()), "/observables/0/path: expected a string, got 1");
  t = table();
  t["observables"][0]["path"] = nullptr;
  t["observables"][0]["values"] = "0.0091";
  starts(status_of(t.dump()), "/observables/0/values: expected an array");
  t = table();
  t["observables"][3]["status"] = false;
  starts(status_of(t.dump()), "/observables/3/status: expected a string");
}

BOOST_AUTO_TEST_CASE(the_table_beside_the_scene_file_or_none) {
  BOOST_TEST(ladder_table_path("data/scenes/sphere_cylinder/recommended.json") ==
             fs::path("data/scenes/sphere_cylinder/recommended.ladder.json"));
  const fs::path dir =
      fs::temp_directory_path() / ("mpm_discretization_error_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = (dir / "s.json").string();
  BOOST_TEST(!discretization_error(scene, kMine, summary()).has_value());
  BOOST_TEST(!discretization_error("", kMine, summary()).has_value());
  std::ofstream(dir / "s.ladder.json") << table().dump(2);
  const auto e = discretization_error(scene, kMine, summary());
  BOOST_REQUIRE(e.has_value());
  BOOST_TEST(e->at("table") == (dir / "s.ladder.json").string());
  BOOST_TEST(e->at("observables").size() == 4u);
  fs::create_directories(dir / "d.ladder.json");  // a directory where the table would be
  const auto d = discretization_error((dir / "d.json").string(), kMine, summary());
  BOOST_REQUIRE(d.has_value());
  BOOST_TEST(d->at("status") == "unreadable: not a regular file");
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
