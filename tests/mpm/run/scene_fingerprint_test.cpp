// The scene fingerprint (summary.json "scene_fingerprint", `mpm check --fingerprint`,
// docs/mpm.md#output) of data/scenes/verification/rigid_translation.json (extends
// elastic_base.json, one material file with overrides):
// - 16 lowercase hex digits;
// - a change of where or what a run writes (directory, snapshots, fields, checkpoints) or a new
//   description keeps it; one of the history interval or the gauges changes it;
// - a grid, time, solver, physics or object change changes it, and so does a material value
//   (an override, or the material file's own content in a copy);
// - the scene copied into another directory, its material path rewritten to reach the same file
//   (relative from there), or to a copy of the file elsewhere, gives the same fingerprint, and so
//   does the document written to DIR/scene.json read back (doubles round-trip).
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <regex>

#include "mpm/input/scene_reader.hpp"
#include "mpm/run/scene_fingerprint.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;

namespace {

const std::string kScene =
    std::string(IMPACT_SOURCE_DIR) + "/data/scenes/verification/rigid_translation.json";
const fs::path kMaterial = fs::path(IMPACT_SOURCE_DIR) / "data/materials/al6061_t6.json";

std::string fingerprint(const Json& patch = Json::object()) {
  Json doc = load_scene_document(kScene);
  doc.merge_patch(patch);
  return scene_fingerprint(read_scene(doc, kScene).resolved);
}

fs::path scratch() {
  const fs::path dir =
      fs::temp_directory_path() / ("mpm_scene_fingerprint_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "elsewhere" / "deeper");
  return dir;
}

void write(const fs::path& file, const Json& doc) {
  std::ofstream(file) << doc.dump(2) << '\n';
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_scene_fingerprint)

BOOST_AUTO_TEST_CASE(sixteen_hex_digits_kept_by_output_changed_by_physics) {
  const std::string base = fingerprint();
  BOOST_TEST_MESSAGE("rigid_translation fingerprint " << base);
  BOOST_TEST(std::regex_match(base, std::regex("[0-9a-f]{16}")));
  BOOST_TEST(fingerprint() == base);
  // Where and what a run writes, and free text: the same scene.
  BOOST_TEST(fingerprint({{"output",
                           {{"directory", "elsewhere"},
                            {"snapshots", false},
                            {"fields", {"velocity"}},
                            {"checkpoint_interval_steps", 10}}}}) == base);
  BOOST_TEST(fingerprint({{"description", "another text"}}) == base);
  // What the observables depend on: the history interval (peaks are sampled at its rows) and
  // the gauges' and crater's definitions.
  BOOST_TEST(fingerprint({{"output", {{"interval", 1e-6}}}}) != base);
  BOOST_TEST(
      fingerprint(
          {{"output",
            {{"gauges",
              {{"vx",
                {{"type", "velocity"},
                 {"object", "block"},
                 {"component", "x"},
                 {"region", {{"lower", {0.02, 0.02, 0.02}}, {"upper", {0.04, 0.04, 0.04}}}}}}}},
             {"snapshots", true}}}}) != base);
  // Anything the solution depends on: another scene.
  const std::vector<Json> changes = {
      {{"grid", {{"cells", {24, 24, 24}}}}},
      {{"time", {{"max_time", 1e-4}}}},
      {{"time", {{"multiplier", 0.4}}}},
      {{"solver", {{"scheme", "usl"}}}},
      {{"solver", {{"gravity", {0.0, 0.0, -9.81}}}}},
      {{"objects", {{"block", {{"velocity", {30.0, -20.0, 11.0}}}}}}},
      {{"materials", {{"elastic_al", {{"overrides", {{"density", 2710.0}}}}}}}}};
  for (const Json& change : changes) BOOST_TEST(fingerprint(change) != base, change.dump());
}

BOOST_AUTO_TEST_CASE(a_copy_elsewhere_reaching_the_same_material_has_the_same_fingerprint) {
  const std::string base = fingerprint();
  const fs::path dir = scratch();
  const Json resolved = read_scene(load_scene_document(kScene), kScene).resolved;
  // The resolved scene in a folder of its own, the material reached relatively from there.
  Json copy = resolved;
  const fs::path here = dir / "elsewhere" / "deeper";
  copy["materials"]["elastic_al"]["file"] = fs::relative(kMaterial, here).string();
  write(here / "scene.json", copy);
  const std::string copied = (here / "scene.json").string();
  BOOST_TEST(scene_fingerprint(read_scene(load_scene_document(copied), copied).resolved) == base);
  // The material file copied elsewhere, same content.
  fs::copy_file(kMaterial, dir / "al.json");
  copy["materials"]["elastic_al"]["file"] = "../../al.json";
  write(here / "scene.json", copy);
  BOOST_TEST(scene_fingerprint(read_scene(load_scene_document(copied), copied).resolved) == base);
  // ... and a value of that copy changed: another material, another fingerprint.
  Json material = load_json_file((dir / "al.json").string());
  material["density"] = material["density"].get<double>() * 1.001;
  write(dir / "al.json", material);
  BOOST_TEST(scene_fingerprint(read_scene(load_scene_document(copied), copied).resolved) != base);
  // DIR/scene.json as mpm run writes it (dump(2)), read back.
  const Json written = Json::parse(resolved.dump(2) + '\n');
  BOOST_TEST(scene_fingerprint(written) == base);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
