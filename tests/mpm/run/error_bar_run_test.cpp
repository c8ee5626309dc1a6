// What `mpm run` adds to summary.json for the error bars of issue 42 (docs/mpm.md#output), through
// run() and restart() on data/scenes/verification/rigid_translation.json with gravity g_x =
// -4e5 m/s^2 (v_x(t) = 30 + g_x t: 30 m/s at t = 0, -50 m/s at 200 us, a rigid body's closed form,
// exact to round-off on a free grid):
// - "gauges": the velocity gauge's max is 30 m/s (t = 0), its min and signed peak v_x(T) at the
//   end time T, the peak's time T (closed form, 1e-9 relative); every gauge's max, min, peak and
//   peak time equal the extremes of its history.csv column (17 digits: exactly), the peak the
//   first row of largest magnitude;
// - a run stopped by SIGTERM after step 30 and restarted has the same "gauges" (and
//   "discretization_error") as the uninterrupted one;
// - "scene_fingerprint" is scene_fingerprint() of the scene; with a ladder table beside the
//   scene file (a copy of the scene in a scratch folder): a level with that fingerprint gives
//   error = (value - extrapolated) / abs(extrapolated) for the mean velocity and for a gauge's
//   maximum read back from the summary (pointers with "/" in a key written "~1", RFC 6901:
//   "/gauges/ vx/max [m~1s]"); no matching level gives the status sentence; a table that is not
//   JSON, of wrong types or with a bad pointer never fails the run (exit 0).
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../verification_helpers.hpp"
#include "mpm/input/scene_reader.hpp"
#include "mpm/run/scene_fingerprint.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;

namespace {

constexpr double kG = -4.0e5;  // [m/s^2] along x

Json gauge(const char* type, const char* component) {
  Json g = {{"type", type},
            {"object", "block"},
            {"region", {{"lower", {0.02, 0.02, 0.02}}, {"upper", {0.03, 0.04, 0.04}}}}};
  if (component != nullptr) g["component"] = component;
  return g;
}

// The rigid translation with gravity and three gauges, as a scene file of its own in `dir`
// (material path absolute: the copy reaches the shipped material).
fs::path write_scene(const fs::path& dir, const Json& patch = Json::object()) {
  Json doc = load_scene_document(std::string(IMPACT_SOURCE_DIR) +
                                 "/data/scenes/verification/rigid_translation.json");
  doc["materials"]["elastic_al"]["file"] =
      (fs::path(IMPACT_SOURCE_DIR) / "data/materials/al6061_t6.json").string();
  doc.merge_patch({{"solver", {{"gravity", {kG, 0.0, 0.0}}}},
                   {"output",
                    {{"interval", 1e-5},
                     {"gauges",
                      {{"vx", gauge("velocity", "x")},
                       {"ex", gauge("strain", "x")},
                       {"p", gauge("pressure", nullptr)}}}}}});
  doc.merge_patch(patch);
  fs::create_directories(dir);
  const fs::path file = dir / "rigid.json";
  std::ofstream(file) << doc.dump(2) << '\n';
  return file;
}

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("mpm_error_bar_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

Json read_json(const fs::path& file) {
  std::ifstream in(file);
  BOOST_REQUIRE_MESSAGE(in, "cannot open " << file);
  return Json::parse(in);
}

// history.csv: header and rows.
std::pair<std::vector<std::string>, std::vector<std::vector<double>>> read_csv(
    const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::string line;
  for (bool first = true; std::getline(in, line); first = false) {
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> row;
    while (std::getline(ss, cell, ',')) {
      if (first) {
        header.push_back(cell);
      } else {
        row.push_back(std::stod(cell));
      }
    }
    if (!first) rows.push_back(row);
  }
  return {header, rows};
}

int run_file(const fs::path& scene_file, const fs::path& out,
             const std::vector<FaultInjection>& faults = {}) {
  RunOptions options;
  options.out_dir = out.string();
  options.threads = 2;
  options.faults = faults;
  return run(load_scene(scene_file.string()), options);
}

std::string fingerprint_of(const fs::path& scene_file) {
  return scene_fingerprint(load_scene(scene_file.string()).resolved);
}

Json ladder(const std::string& fingerprint) {
  // values: one per level, the second (this scene's) what the run gives (the closed form), so
  // that the table is not stale.
  const auto observable = [](const char* name, const char* path, double extrapolated,
                             double level_value) {
    return Json{{"name", name},
                {"path", path},
                {"unit", "m/s"},
                {"values", {level_value + 1.0, level_value}},
                {"extrapolated", extrapolated},
                {"order", 2.0},
                {"gci_fine [-]", 0.01},
                {"status", "extrapolated"},
                {"quotable", true}};
  };
  return {{"scene", "rigid.json"},
          {"command", "test"},
          {"commit", "abc1234"},
          {"date", "2026-11-28"},
          {"levels",
           {{{"level", 0.5}, {"fingerprint", "0000000000000000"}},
            {{"level", 1.0}, {"fingerprint", fingerprint}}}},
          {"observables",
           {observable("mean vx", "/observables/objects/block/mean_velocity [m~1s]/0", -48.0,
                       30.0 + kG * 5e-5),
            observable("gauge max", "/gauges/vx/max [m~1s]", 31.0, 30.0)}}};
}

void write_table(const fs::path& dir, const std::string& text) {
  std::ofstream(dir / "rigid.ladder.json") << text;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_error_bar_run)

BOOST_AUTO_TEST_CASE(gauge_extrema_are_the_history_columns_extremes_and_the_closed_form) {
  const fs::path dir = scratch("gauges");
  const fs::path scene = write_scene(dir);
  BOOST_REQUIRE(run_file(scene, dir / "out") == 0);
  const Json summary = read_json(dir / "out" / "summary.json");
  BOOST_TEST(!summary.contains("discretization_error"));  // no table beside the scene
  const Json& gauges = summary.at("gauges");
  BOOST_TEST_MESSAGE("summary gauges: " << gauges.dump());
  const auto [header, rows] = read_csv(dir / "out" / "history.csv");
  BOOST_REQUIRE(rows.size() > 10u);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    BOOST_REQUIRE_MESSAGE(it != header.end(), "no column " << name);
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t time = column("time [s]");
  for (const auto& [name, unit] :
       std::vector<std::pair<std::string, std::string>>{{"vx", "m/s"}, {"ex", "-"}, {"p", "Pa"}}) {
    const std::size_t c = column("gauge_" + name + " [" + unit + "]");
    double max = rows[0][c], min = rows[0][c], peak = rows[0][c], peak_time = rows[0][time];
    for (const auto& r : rows) {
      max = std::max(max, r[c]);
      min = std::min(min, r[c]);
      if (std::abs(r[c]) > std::abs(peak)) {
        peak = r[c];
        peak_time = r[time];
      }
    }
    const Json& g = gauges.at(name);
    BOOST_TEST(g.at("particles").get<std::size_t>() > 0u);
    BOOST_TEST(g.at("max [" + unit + "]").get<double>() == max, name);
    BOOST_TEST(g.at("min [" + unit + "]").get<double>() == min, name);
    BOOST_TEST(g.at("peak [" + unit + "]").get<double>() == peak, name);
    BOOST_TEST(g.at("peak_time [s]").get<double>() == peak_time, name);
  }
  // The closed form: v_x = 30 + g t, largest at t = 0, smallest and of largest magnitude at T.
  const double T = summary.at("time [s]").get<double>();
  const double end = 30.0 + kG * T;
  BOOST_TEST(T == 2e-4, boost::test_tools::tolerance(1e-9));
  const Json& vx = gauges.at("vx");
  BOOST_TEST(vx.at("max [m/s]").get<double>() == 30.0, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(vx.at("min [m/s]").get<double>() == end, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(vx.at("peak [m/s]").get<double>() == end, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(vx.at("peak_time [s]").get<double>() == T);
  BOOST_TEST(std::abs(gauges.at("ex").at("peak [-]").get<double>()) < 1e-12);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_ladder_table_gives_the_error_bar_and_never_fails_the_run) {
  const fs::path dir = scratch("ladder");
  const fs::path scene = write_scene(dir, {{"time", {{"max_time", 5e-5}}}});
  const std::string fingerprint = fingerprint_of(scene);
  const std::string table = (dir / "rigid.ladder.json").string();

  write_table(dir, ladder(fingerprint).dump(2));
  BOOST_REQUIRE(run_file(scene, dir / "match") == 0);
  Json summary = read_json(dir / "match" / "summary.json");
  BOOST_TEST(summary.at("scene_fingerprint") == fingerprint);
  const Json& e = summary.at("discretization_error");
  BOOST_TEST_MESSAGE("discretization_error: " << e.dump(2));
  BOOST_TEST(e.at("table") == table);
  BOOST_TEST(e.at("level").get<double>() == 1.0);
  BOOST_TEST(e.at("ladder_commit") == "abc1234");
  const double vx = summary.at("observables")
                        .at("objects")
                        .at("block")
                        .at("mean_velocity [m/s]")[0]
                        .get<double>();
  BOOST_TEST(vx == 30.0 + kG * 5e-5, boost::test_tools::tolerance(1e-9));  // -> -48 + 2e-8...
  const Json& mean = e.at("observables").at("mean vx");
  BOOST_TEST(mean.at("value").get<double>() == vx);
  BOOST_TEST(mean.at("error [-]").get<double>() == (vx + 48.0) / 48.0);
  BOOST_TEST(mean.at("order").get<double>() == 2.0);
  BOOST_TEST(mean.at("gci_fine [-]").get<double>() == 0.01);
  const Json& max = e.at("observables").at("gauge max");
  BOOST_TEST(max.at("value").get<double>() == summary.at("gauges").at("vx").at("max [m/s]"));
  BOOST_TEST(max.at("error [-]").get<double>() == (max.at("value").get<double>() - 31.0) / 31.0);

  write_table(dir, ladder("fedcba9876543210").dump(2));
  BOOST_REQUIRE(run_file(scene, dir / "other") == 0);
  summary = read_json(dir / "other" / "summary.json");
  BOOST_TEST(summary.at("discretization_error") ==
             Json({{"table", table},
                   {"status", "no level of the ladder matches this scene (fingerprint " +
                                  fingerprint + ")"}}));

  // Malformed: the run completes, the summary says why the table was not read.
  Json bad_pointer = ladder(fingerprint);
  bad_pointer["observables"][1]["path"] = "gauges/vx";
  Json wrong_type = ladder(fingerprint);
  wrong_type["levels"][1]["fingerprint"] = 1;
  const std::vector<std::pair<std::string, std::string>> malformed = {
      {"{\"levels\": [", "unreadable: not JSON"},
      {wrong_type.dump(), "unreadable: /levels/1/fingerprint: expected a string, got 1"},
      {"[]", "unreadable: /: expected an object"}};
  for (const auto& [text, status] : malformed) {
    write_table(dir, text);
    BOOST_REQUIRE(run_file(scene, dir / "malformed") == 0);
    const Json s = read_json(dir / "malformed" / "summary.json");
    BOOST_TEST(s.at("status") == "completed");
    BOOST_TEST(s.at("discretization_error").at("status").get<std::string>().rfind(status, 0) == 0u,
               s.at("discretization_error").dump());
  }
  write_table(dir, bad_pointer.dump());
  BOOST_REQUIRE(run_file(scene, dir / "malformed") == 0);
  const Json s = read_json(dir / "malformed" / "summary.json");
  const Json& observables = s.at("discretization_error").at("observables");
  BOOST_TEST(observables.at("gauge max").at("status") == "path not found in this run's summary");
  BOOST_TEST(observables.at("mean vx").at("value").get<double>() == vx);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_restarted_run_has_the_same_extrema_and_error_bar) {
  const fs::path dir = scratch("restart");
  const fs::path scene = write_scene(dir, {{"time", {{"max_time", 5e-5}}}});
  write_table(dir, ladder(fingerprint_of(scene)).dump(2));
  BOOST_REQUIRE(run_file(scene, dir / "whole") == 0);
  BOOST_REQUIRE(run_file(scene, dir / "parts", {{FaultInjection::Kind::sigterm, 30, 0}}) ==
                128 + 15);
  // From another working directory: the table is found by the path the checkpoint recorded.
  const fs::path cwd = fs::current_path();
  fs::current_path(fs::temp_directory_path());
  const int code = restart((dir / "parts").string(), RunOptions{});
  fs::current_path(cwd);
  BOOST_REQUIRE(code == 0);
  const Json whole = read_json(dir / "whole" / "summary.json");
  const Json parts = read_json(dir / "parts" / "summary.json");
  BOOST_TEST(parts.at("gauges") == whole.at("gauges"));
  BOOST_TEST(parts.at("scene_fingerprint") == whole.at("scene_fingerprint"));
  BOOST_TEST(whole.at("discretization_error").contains("observables"));
  Json with_whole = whole.at("discretization_error"), with_parts = parts.at("discretization_error");
  BOOST_TEST(with_parts.at("table") == fs::absolute(dir / "rigid.ladder.json").string());
  with_whole.erase("table");
  with_parts.erase("table");
  BOOST_TEST(with_parts == with_whole);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
