// `mpm study` end to end on a scene directory made here: case01 is a stress-free aluminium block
// (20 mm cube, 4 x 4 x 4 = 64 particles) translating on a free grid; case02 `extends` case01 and
// changes only the velocity. A second study's case01 leaves the grid: it must fail (exit 3) while
// its case02 still runs. Closed form: the particles tile the cube exactly, so the initial kinetic
// energy is 1/2 rho L^3 |v|^2 to round-off (tolerance 1e-12 relative); with no stress and free
// faces the momentum balance closes to round-off (tolerance 1e-12). 25 steps per case.
#include <sys/wait.h>
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "models/core/input.hpp"

namespace fs = std::filesystem;

namespace {

const double kEdge = 0.02;  // block edge [m]

/// A fresh directory under the system temp directory, removed by the destructor.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path / "scenes");
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text << '\n';
}

/// case01: the block at [0.02, 0.04]^3 on a free 6^3 grid (h = 10 mm, 2 particles per cell and
/// axis), base elastic_base.json (elastic 6061-T6, snapshots off), 20 us.
std::string block_scene(const std::string& velocity, const std::string& lower = "0.02") {
  const std::string base =
      std::string(IMPACT_SOURCE_DIR) + "/data/scenes/verification/elastic_base.json";
  const double upper = std::stod(lower) + kEdge;
  std::ostringstream s;
  s << R"({"extends": ")" << base << R"(",
  "description": "Test block: a stress-free 20 mm aluminium cube translating on a free grid.",
  "objects": {"block": {"material": "elastic_al", "velocity": )"
    << velocity << R"(,
    "geometry": {"type": "box", "lower": [)"
    << lower << ", 0.02, 0.02], \"upper\": [" << upper << R"(, 0.04, 0.04]}}},
  "grid": {"lower": [0, 0, 0], "upper": [0.06, 0.06, 0.06], "cells": [6, 6, 6],
           "boundary": {"x-": "free", "x+": "free", "y-": "free", "y+": "free",
                        "z-": "free", "z+": "free"}},
  "time": {"max_time": 2.0e-5}})";
  return s.str();
}

/// `p` in single quotes, for the shell.
std::string quoted(const fs::path& p) {
  std::string s = "'";
  s += p.string();
  s += '\'';
  return s;
}

/// Runs `mpm ARGS`, returns its exit code.
int mpm(const std::string& args) {
  const std::string command = std::string("'") + MPM_PROGRAM + "' " + args;
  BOOST_TEST_MESSAGE("running: " << command);
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool command_ok(const std::string& command) {
  return std::system((command + " >/dev/null 2>&1").c_str()) == 0;
}

/// summary.csv as rows of header -> cell (RFC 4180 quoting: messages may hold commas).
std::vector<std::map<std::string, std::string>> read_table(const fs::path& file) {
  std::ifstream in(file);
  BOOST_REQUIRE_MESSAGE(in, "cannot open " << file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::vector<std::string>> rows(1, std::vector<std::string>(1));
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        rows.back().back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        rows.back().back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().emplace_back();
    } else if (c == '\n') {
      rows.emplace_back(1);
    } else if (c != '\r') {
      rows.back().back() += c;
    }
  }
  if (rows.back().size() == 1 && rows.back()[0].empty()) rows.pop_back();
  std::vector<std::map<std::string, std::string>> table;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    BOOST_REQUIRE_EQUAL(rows[r].size(), rows[0].size());
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < rows[0].size(); ++c) row[rows[0][c]] = rows[r][c];
    table.push_back(row);
  }
  return table;
}

double number(const std::map<std::string, std::string>& row, const std::string& column) {
  const auto it = row.find(column);
  BOOST_REQUIRE_MESSAGE(it != row.end(), "summary.csv has no column '" << column << "'");
  BOOST_REQUIRE_MESSAGE(!it->second.empty(), "summary.csv: empty '" << column << "'");
  return std::stod(it->second);
}

/// 1/2 rho L^3 |v|^2 with rho from the material file.
double block_kinetic_energy(double speed_squared) {
  std::ifstream in(std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json");
  const double rho = impact::Json::parse(in).at("density").get<double>();
  return 0.5 * rho * kEdge * kEdge * kEdge * speed_squared;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_study)

BOOST_AUTO_TEST_CASE(two_cases_complete_with_closed_form_initial_energy) {
  if (!command_ok("python3 -c ''") && !command_ok("/usr/bin/python3 -c ''")) {
    BOOST_TEST_MESSAGE("no python3: the table (study_plot.py) cannot be written; skipped");
    return;
  }
  const TempDir tmp("mpm_study_test_table");
  write(tmp.path / "scenes" / "case01.json", block_scene("[30.0, -20.0, 10.0]"));
  write(tmp.path / "scenes" / "case02.json",
        R"({"extends": "case01.json", "objects": {"block": {"velocity": [10.0, 0.0, 0.0]}}})");
  write(tmp.path / "scenes" / "notes.json", "{}");  // not case*.json: not a case
  const fs::path out = tmp.path / "out";
  BOOST_REQUIRE_EQUAL(
      mpm("study " + quoted(tmp.path / "scenes") + " --out " + quoted(out) + " --no-plot"), 0);
  BOOST_TEST(fs::is_regular_file(out / "summary.md"));
  BOOST_TEST(fs::is_regular_file(out / "study.json"));
  BOOST_TEST(!fs::exists(out / "case01" / "particles"));   // snapshots off
  BOOST_TEST(!fs::exists(out / "case01" / "energy.png"));  // --no-plot
  const auto table = read_table(out / "summary.csv");
  BOOST_REQUIRE_EQUAL(table.size(), 2u);
  const double expected[2] = {block_kinetic_energy(900 + 400 + 100), block_kinetic_energy(100)};
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& row = table[i];
    BOOST_TEST(row.at("case") == (i == 0 ? "case01" : "case02"));
    BOOST_TEST(row.at("status") == "completed");
    BOOST_TEST(number(row, "particles [-]") == 64);
    const double e0 = number(row, "initial_kinetic_energy [J]");
    BOOST_TEST_MESSAGE(row.at("case")
                       << ": E0 " << e0 << " J, closed form " << expected[i]
                       << " J, momentum balance " << number(row, "momentum_balance_error [-]"));
    BOOST_TEST(std::abs(e0 / expected[i] - 1.0) < 1e-12);
    BOOST_TEST(number(row, "momentum_balance_error [-]") < 1e-12);
    BOOST_TEST(std::abs(number(row, "relative_drift [-]")) < 1e-12);  // rigid: nothing changes
    BOOST_TEST(number(row, "steps [-]") > 0);
  }
}

BOOST_AUTO_TEST_CASE(a_failed_case_is_recorded_and_the_study_goes_on) {
  if (!command_ok("python3 -c ''") && !command_ok("/usr/bin/python3 -c ''")) {
    BOOST_TEST_MESSAGE("no python3: the table (study_plot.py) cannot be written; skipped");
    return;
  }
  const TempDir tmp("mpm_study_test_failure");
  // case01 leaves through x+ (2 km/s for 20 us is 40 mm, the block starts 10 mm from the face).
  write(tmp.path / "scenes" / "case01.json", block_scene("[2000.0, 0.0, 0.0]", "0.03"));
  write(tmp.path / "scenes" / "case02.json", block_scene("[10.0, 0.0, 0.0]"));
  const fs::path out = tmp.path / "out";
  BOOST_REQUIRE_EQUAL(
      mpm("study " + quoted(tmp.path / "scenes") + " --out " + quoted(out) + " --no-plot"), 3);
  const auto table = read_table(out / "summary.csv");
  BOOST_REQUIRE_EQUAL(table.size(), 2u);
  BOOST_TEST(table[0].at("status") == "failed");
  BOOST_TEST(!table[0].at("message").empty());
  BOOST_TEST_MESSAGE("case01 message: " << table[0].at("message"));
  BOOST_TEST(table[1].at("status") == "completed");
}

BOOST_AUTO_TEST_CASE(selected_case_and_figures) {
  const bool matplotlib = command_ok("/usr/bin/python3 -c 'import matplotlib'") ||
                          command_ok("python3 -c 'import matplotlib'");
  if (!matplotlib) {
    BOOST_TEST_MESSAGE("no python3 with matplotlib: figures not tested");
    return;
  }
  const TempDir tmp("mpm_study_test_plot");
  write(tmp.path / "scenes" / "case01.json", block_scene("[30.0, -20.0, 10.0]"));
  write(tmp.path / "scenes" / "case02.json",
        R"({"extends": "case01.json", "objects": {"block": {"velocity": [10.0, 0.0, 0.0]}}})");
  write(tmp.path / "scenes" / "case03.json",
        R"({"extends": "case01.json", "objects": {"block": {"velocity": [0.0, 5.0, 0.0]}}})");
  const fs::path out = tmp.path / "out";
  BOOST_REQUIRE_EQUAL(mpm("study " + quoted(tmp.path / "scenes") + " --out " + quoted(out) +
                          " --threads 1 --cases case01,case03"),
                      0);
  BOOST_TEST(!fs::exists(out / "case02"));  // not selected
  for (const char* name : {"case01", "case03"}) {
    const fs::path png = out / name / "energy.png";
    BOOST_TEST_MESSAGE(png << ": " << (fs::exists(png) ? fs::file_size(png) : 0) << " B");
    BOOST_TEST(fs::is_regular_file(png));
    BOOST_TEST((fs::exists(png) && fs::file_size(png) > 1000));
  }
  BOOST_TEST(read_table(out / "summary.csv").size() == 2u);
}

BOOST_AUTO_TEST_CASE(bad_input_is_exit_2_and_runs_nothing) {
  const TempDir tmp("mpm_study_test_input");
  write(tmp.path / "scenes" / "case01.json", block_scene("[10.0, 0.0, 0.0]"));
  write(tmp.path / "scenes" / "case02.json", R"({"extends": "case01.json", "tme": {}})");
  const fs::path out = tmp.path / "out";
  const std::string dir = quoted(tmp.path / "scenes");
  BOOST_TEST(mpm("study " + dir + " --out " + quoted(out) + " --no-plot") == 2);
  BOOST_TEST(!fs::exists(out / "case01"));  // validated before anything ran
  BOOST_TEST(mpm("study " + dir + " --out " + quoted(out) + " --cases case09") == 2);
  BOOST_TEST(mpm("study " + dir + " --no-plot") == 1);  // --out is required
  BOOST_TEST(mpm("study " + dir + " --out x --cases ,") == 1);
  BOOST_TEST(mpm("study " + dir + " --out x --fast") == 1);
}

BOOST_AUTO_TEST_SUITE_END()
