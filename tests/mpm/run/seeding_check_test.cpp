// The seeded bodies' check (mpm/run/seeding_check.hpp): a body whose particles hold a volume more
// than 5 % off the part of its geometry they should fill is warned of, naming its key path and the
// ratio. The new-user trial's case: a block seeded where its faces cut coarser cells (a box
// refined 2.5 times on one base cell, its cells then growing back) held 0.903 of its volume, and
// nothing said so. The same block on the uniform grid (faces on nodes), a quarter model (clipped
// on purpose by two symmetric faces), a union whose parts overlap (the ramp) and every shipped
// scene are read without a word.
#include "mpm/run/seeding_check.hpp"

#include <boost/test/unit_test.hpp>
#include <filesystem>

#include "mpm/input/scene_reader.hpp"
#include "mpm/particles/particles.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;

namespace {

const std::string kScenes = std::string(IMPACT_SOURCE_DIR) + "/data/scenes/";

std::vector<std::string> warnings_of(const Json& doc, const std::string& name) {
  const Scene scene = read_scene(doc, name);
  return seeding_warnings(scene, seed_particles(scene), Communicator());
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_block_whose_faces_cut_coarse_cells_is_warned_of) {
  Json doc = load_scene_document(kScenes + "verification/rigid_translation.json");
  BOOST_TEST(warnings_of(doc, "uniform.json").empty());
  doc["grid"]["refine"] = {
      {"lower", {0.02, 0.02, 0.02}}, {"upper", {0.025, 0.025, 0.025}}, {"factor", 2.5}};
  const std::vector<std::string> w = warnings_of(doc, "graded.json");
  BOOST_TEST_REQUIRE(w.size() == 1u);
  BOOST_TEST_MESSAGE(w[0]);
  BOOST_TEST(w[0].find("graded.json: /objects/block/geometry: its particles hold 0.903 of the "
                       "volume they should fill") == 0u);
}

BOOST_AUTO_TEST_CASE(every_shipped_scene_seeds_within_the_tolerance) {
  int scenes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kScenes)) {
    const fs::path p = entry.path();
    if (p.extension() != ".json" || p.string().find(".ladder.json") != std::string::npos) continue;
    const Json doc = load_scene_document(p.string());
    if (!doc.contains("grid") || !doc.contains("objects")) continue;  // a base (elastic_base)
    const Scene scene = read_scene(doc, p.string());
    if (scene.grid.cells[0] * scene.grid.cells[1] * scene.grid.cells[2] > 200000) continue;
    BOOST_TEST_CONTEXT(p.string()) {
      BOOST_TEST(seeding_warnings(scene, seed_particles(scene), Communicator()).empty());
    }
    ++scenes;
  }
  BOOST_TEST(scenes > 30);  // the quarter models and the ramp's overlapping union among them
}
