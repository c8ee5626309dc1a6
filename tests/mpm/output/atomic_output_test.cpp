// Outputs survive a crash or kill (docs/mpm.md#output): run() writes every whole file
// (scene.json, summary.json, status.json, particles.pvd, the VTU snapshots) to `<name>.tmp` and
// renames it into place, and status.json says where the run is or how it ended.
// - A completed run of data/scenes/verification/two_spheres.json (2 us, snapshots on, 2 threads)
//   leaves no `*.tmp` file; status.json says "completed" with the final step and time of
//   summary.json; summary.json and particles.pvd are complete; history.csv has one row per output.
// - A failed run (linear/USL at multiplier 1.2, stopped by the energy-growth check within a few
//   steps) leaves status.json "failed" with the step and the solver's message.
// - write_file_atomically: a writer that throws leaves neither the file nor its `.tmp`, and a
//   previous version of the file untouched; an unwritable directory names the file.
#include <unistd.h>
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../verification_helpers.hpp"
#include "support/atomic_file.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("mpm_atomic_output_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

Json read_json(const fs::path& file) {
  std::ifstream in(file);
  BOOST_REQUIRE_MESSAGE(in, "cannot open " << file);
  return Json::parse(in);  // throws on a truncated file
}

std::size_t tmp_files(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.path().extension() == ".tmp";
  return n;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_atomic_output)

BOOST_AUTO_TEST_CASE(completed_run_leaves_no_tmp_and_a_completed_status) {
  const fs::path dir = scratch("completed");
  const Scene scene = test::verification_scene(
      "two_spheres.json",
      {{"time", {{"max_time", 2e-6}}}, {"output", {{"snapshots", true}, {"interval", 5e-7}}}});
  RunOptions options;
  options.out_dir = dir.string();
  options.threads = 2;
  BOOST_REQUIRE(run(scene, options) == 0);

  BOOST_TEST(tmp_files(dir) == 0u);
  const Json summary = read_json(dir / "summary.json");
  const Json status = read_json(dir / "status.json");
  BOOST_TEST_MESSAGE("status.json: " << status.dump());
  BOOST_TEST(status.at("status") == "completed");
  BOOST_TEST(summary.at("status") == "completed");
  BOOST_TEST(status.at("step").get<long>() == summary.at("steps").get<long>());
  BOOST_TEST(status.at("step").get<long>() > 0);
  BOOST_TEST(status.at("time [s]").get<double>() == summary.at("time [s]").get<double>());
  BOOST_TEST(status.at("energy_error [-]").get<double>() ==
             summary.at("final").at("energy_error [-]").get<double>());
  BOOST_TEST(status.at("message") == "");
  BOOST_TEST(status.contains("wall_time [s]"));
  BOOST_TEST(read_json(dir / "scene.json").is_object());

  // history.csv: header + the t = 0 row + one per 0.5 us (4), every line complete.
  std::ifstream h(dir / "history.csv");
  std::string line;
  std::size_t lines = 0;
  while (std::getline(h, line)) ++lines;
  BOOST_TEST(lines == 6u);
  // Snapshots: step 0 and one per output, each listed in the complete collection.
  std::size_t vtu = 0;
  for (const auto& e : fs::directory_iterator(dir / "particles"))
    vtu += e.path().extension() == ".vtu";
  BOOST_TEST(vtu == 5u);
  const std::string pvd = read_text(dir / "particles.pvd");
  BOOST_TEST(pvd.find("</VTKFile>") != std::string::npos);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(failed_run_says_where_it_stopped) {
  const fs::path dir = scratch("failed");
  Json patch = test::with_solver("linear", "usl");
  patch["time"] = {{"multiplier", 1.2}};
  const Scene scene = test::verification_scene("two_spheres.json", patch);
  RunOptions options;
  options.out_dir = dir.string();
  options.threads = 2;
  BOOST_REQUIRE(run(scene, options) == 3);
  BOOST_TEST(tmp_files(dir) == 0u);
  const Json status = read_json(dir / "status.json");
  BOOST_TEST_MESSAGE("status.json: " << status.dump());
  BOOST_TEST(status.at("status") == "failed");
  BOOST_TEST(status.at("step").get<long>() ==
             read_json(dir / "summary.json").at("steps").get<long>());
  BOOST_TEST(status.at("message").get<std::string>().find("max_energy_growth") !=
             std::string::npos);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_failed_write_leaves_the_previous_file) {
  const fs::path dir = scratch("helper");
  fs::create_directories(dir);
  const fs::path file = dir / "out.json";
  write_file_atomically(file, [](std::ostream& o) { o << "{\"version\": 1}\n"; });
  BOOST_TEST(read_text(file) == "{\"version\": 1}\n");
  BOOST_CHECK_THROW(write_file_atomically(file,
                                          [](std::ostream& o) {
                                            o << "{\"vers";
                                            throw std::runtime_error("killed");
                                          }),
                    std::runtime_error);
  BOOST_TEST(read_text(file) == "{\"version\": 1}\n");
  BOOST_TEST(!fs::exists(dir / "out.json.tmp"));
  try {
    write_file_atomically(dir / "no_such_dir" / "x.json", [](std::ostream& o) { o << 1; });
    BOOST_ERROR("no exception");
  } catch (const std::runtime_error& e) {
    BOOST_TEST(std::string(e.what()).find("x.json") != std::string::npos);
  }
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
