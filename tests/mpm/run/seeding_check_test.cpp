// The seeded bodies' check (mpm/run/seeding_check.hpp): a body whose particles hold a volume more
// than 5 % off the part of its geometry they should fill is warned of, naming its key path and the
// ratio. The new-user trial's case: a block seeded where its faces cut coarser cells (a box
// refined 2.5 times on one base cell, its cells then growing back) held 0.903 of its volume, and
// nothing said so. The same block on the uniform grid (faces on nodes), a quarter model (clipped
// on purpose by two symmetric faces), a union whose parts overlap (the ramp) and every shipped
// scene are read without a word.
#include "mpm/run/seeding_check.hpp"

#include <array>
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

// The trial of the first version (which took the body's share inside the grid over its whole
// bounding box, less a share claimed by earlier bodies anywhere) found false warnings where a body
// overlaps another outside the grid (1.67), a quarter rod is pushed 0.5 mm into its plate (1.07),
// a plate lies mostly outside the grid (1.05) and a plane-strain union's parts span different z
// (0.75); and none for an overlap in a quarter model whose seeding is 1.10 off (the same bodies
// in full are warned of at 1.10). Measured now where the seeding seeds, every one is right.
BOOST_AUTO_TEST_CASE(overlaps_clipping_and_plane_sections_are_measured_where_the_seeding_seeds) {
  const auto scene = [](const std::string& base, const Json& patch) {
    Json doc = load_scene_document(kScenes + base);
    doc.merge_patch(patch);
    return doc;
  };
  const auto box = [](std::array<double, 3> lo, std::array<double, 3> hi) {
    return Json{{"material", "elastic_al"},
                {"geometry", {{"type", "box"}, {"lower", lo}, {"upper", hi}}},
                {"velocity", {0, 0, 0}}};
  };
  // a (seeded first) overlaps b only where both lie beyond x+ = 0.06.
  BOOST_TEST(warnings_of(scene("verification/rigid_translation.json",
                               {{"objects",
                                 {{"block", nullptr},
                                  {"a", box({0.055, 0.02, 0.02}, {0.09, 0.04, 0.04})},
                                  {"b", box({0.03, 0.02, 0.02}, {0.07, 0.04, 0.04})}}}}),
                         "outside.json")
                 .empty());
  BOOST_TEST(
      warnings_of(
          scene("rod_plate/quarter.json",
                {{"objects",
                  {{"rod",
                    {{"geometry", {{"bottom", {-0.0195, 0, 0}}, {"top", {0.0005, 0, 0}}}}}}}}}),
          "embedded.json")
          .empty());
  const Json plate = {{"material", "elastic_al"},
                      {"geometry",
                       {{"type", "cylinder"},
                        {"bottom", {0.02, 0.03, 0.03}},
                        {"top", {0.03, 0.03, 0.03}},
                        {"radius", 0.1}}},
                      {"velocity", {0, 0, 0}}};
  BOOST_TEST(warnings_of(scene("verification/rigid_translation.json",
                               {{"objects", {{"block", nullptr}, {"p", plate}}}}),
                         "wide.json")
                 .empty());
  const Json split = {
      {"type", "union"},
      {"parts",
       {{"p1", {{"type", "box"}, {"lower", {0.05, 0.025, -0.5}}, {"upper", {0.1, 0.125, 0.5}}}},
        {"p2",
         {{"type", "box"}, {"lower", {0.075, 0.025, -0.1}}, {"upper", {0.125, 0.125, 2.0}}}}}}};
  BOOST_TEST(
      warnings_of(
          scene("verification/resting_block_plane_strain.json",
                {{"objects",
                  {{"block", nullptr}, {"u", {{"material", "soft"}, {"geometry", split}}}}}}),
          "section.json")
          .empty());
  // Two cylinders along x in a quarter model (all faces symmetric): b loses to a what it shares
  // with it, and its seeding is 1.10 off what is left.
  const auto rod = [](double x0, double x1, double r) {
    return Json{
        {"material", "elastic_al"},
        {"geometry",
         {{"type", "cylinder"}, {"bottom", {x0, 0, 0}}, {"top", {x1, 0, 0}}, {"radius", r}}},
        {"velocity", {0, 0, 0}}};
  };
  Json quarter =
      scene("verification/rigid_translation.json",
            {{"objects",
              {{"block", nullptr}, {"a", rod(0.0, 0.02, 0.02)}, {"b", rod(0.014, 0.034, 0.01)}}}});
  for (const char* face : {"x-", "x+", "y-", "y+", "z-", "z+"})
    quarter["grid"]["boundary"][face] = "symmetric";
  const std::vector<std::string> w = warnings_of(quarter, "quarter.json");
  BOOST_TEST_REQUIRE(w.size() == 1u);
  BOOST_TEST_MESSAGE(w[0]);
  BOOST_TEST(w[0].find("quarter.json: /objects/b/geometry: its particles hold 1.1") == 0u);
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
