// A material used outside its fitted range (mpm/scene/fitted_range.hpp, docs/models.md
// fitted_range): the nominal strain rate of an object against v / L worked by hand, and the
// scene's warnings for the 4340 MTS Rc 49 file (fitted on 1e-4 to 1000 /s, 173 to 373 K): a
// Taylor rod at 1100 m/s on a mirror anvil (4.4e4 /s), the same rod at 20 m/s (800 /s: none), a
// hot rod, two rods of one material (one warning), a file without a range (none), and a range
// whose bounds are reversed (refused with its key path).
#include "mpm/scene/fitted_range.hpp"

#include <boost/test/unit_test.hpp>

#include "helpers/scene_error.hpp"
#include "mpm/input/scene_reader.hpp"

using namespace impact;
using namespace impact::mpm;
namespace tt = boost::test_tools;

namespace {

const std::string kMaterials = std::string(IMPACT_SOURCE_DIR) + "/data/materials/";

// A 25 mm rod of radius 4 mm along x at speed v toward the mirror face x- (the anvil), on a grid
// whose other faces are free.
Json rod_scene(double v, const std::string& material = "steel_4340_mts_rc49.json") {
  return {{"materials", {{"steel", {{"file", kMaterials + material}}}}},
          {"objects",
           {{"rod",
             {{"material", "steel"},
              {"geometry",
               {{"type", "cylinder"},
                {"bottom", {0.0, 0.0, 0.0}},
                {"top", {0.025, 0.0, 0.0}},
                {"radius", 0.004}}},
              {"velocity", {-v, 0.0, 0.0}}}}}},
          {"grid",
           {{"lower", {0.0, 0.0, 0.0}},
            {"upper", {0.03, 0.012, 0.012}},
            {"cells", {10, 4, 4}},
            {"boundary",
             {{"x-", "symmetric"},
              {"x+", "free"},
              {"y-", "symmetric"},
              {"y+", "free"},
              {"z-", "symmetric"},
              {"z+", "free"}}}}},
          {"time", {{"max_time", 1e-5}}}};
}

std::vector<std::string> warnings_of(const Json& doc) {
  std::vector<std::string> found;
  for (const std::string& w : read_scene(doc, "rod.json").warnings)
    if (w.find("fitted_range") != std::string::npos) found.push_back(w);
  return found;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_fitted_range)

BOOST_AUTO_TEST_CASE(the_nominal_rate_is_the_speed_toward_what_holds_or_hits_over_the_length) {
  // Toward the mirror anvil x-: 1100 / 0.025; moving away from it (+x, the x+ face free): none.
  BOOST_TEST(nominal_strain_rate(read_scene(rod_scene(1100.0), "rod.json"), 0) == 1100.0 / 0.025,
             tt::tolerance(1e-12));
  BOOST_TEST(nominal_strain_rate(read_scene(rod_scene(-1100.0), "rod.json"), 0) == 0.0);
  // Against a second object: the relative speed over the extent along it (the anvil plate at
  // rest, 10 mm thick along x: its rate is 1100 / 0.01; the rod's stays 1100 / 0.025).
  Json two = rod_scene(1100.0);
  two["grid"]["boundary"]["x-"] = "free";
  two["grid"]["lower"] = {-0.012, 0.0, 0.0};
  two["grid"]["cells"] = {14, 4, 4};
  two["objects"]["plate"] = {
      {"material", "steel"},
      {"geometry",
       {{"type", "box"}, {"lower", {-0.0105, 0.0, 0.0}}, {"upper", {-0.0005, 0.012, 0.012}}}}};
  const Scene s = read_scene(two, "two.json");
  const std::size_t rod = s.objects[0].name == "rod" ? 0 : 1;
  BOOST_TEST(nominal_strain_rate(s, rod) == 1100.0 / 0.025, tt::tolerance(1e-12));
  BOOST_TEST(nominal_strain_rate(s, 1 - rod) == 1100.0 / 0.01, tt::tolerance(1e-12));
  // Flying apart (the rod at +1100 m/s, away from the plate at rest; x+ free): neither is
  // loaded, though the relative speed is the same (issue 52: it counted, and warned).
  two["objects"]["rod"]["velocity"] = {1100.0, 0.0, 0.0};
  const Scene apart = read_scene(two, "two.json");
  BOOST_TEST(nominal_strain_rate(apart, rod) == 0.0);
  BOOST_TEST(nominal_strain_rate(apart, 1 - rod) == 0.0);
  // Bounding boxes that overlap on every axis (as a sleeve's about a rod): in contact, counted
  // whatever the direction of the relative velocity.
  two["objects"]["plate"]["geometry"] = {
      {"type", "box"}, {"lower", {0.010, 0.0, 0.0}}, {"upper", {0.015, 0.012, 0.012}}};
  const Scene nested = read_scene(two, "two.json");
  BOOST_TEST(nominal_strain_rate(nested, rod) == 1100.0 / 0.025, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_material_outside_its_fitted_range_warns_once) {
  const auto fast = warnings_of(rod_scene(1100.0));
  BOOST_REQUIRE(fast.size() == 1u);
  BOOST_TEST_MESSAGE(fast[0]);
  for (const char* part : {"rod.json: /materials/steel/file: ",
                           "steel_4340_mts_rc49.json was fitted on strain rates "
                           "0.0001 to 1e+03 /s and temperatures 173 to 373 K",
                           "object rod's nominal strain rate is "
                           "4.4e+04 /s"})
    BOOST_TEST(fast[0].find(part) != std::string::npos, part);
  BOOST_TEST(warnings_of(rod_scene(20.0)).empty());  // 800 /s: inside

  Json hot = rod_scene(20.0);
  hot["objects"]["rod"]["temperature"] = 500.0;
  const auto warm = warnings_of(hot);
  BOOST_REQUIRE(warm.size() == 1u);
  BOOST_TEST(warm[0].find("object rod's initial temperature 500 K") != std::string::npos, warm[0]);

  Json twice = rod_scene(1100.0);
  twice["grid"]["upper"] = {0.03, 0.03, 0.012};
  twice["grid"]["cells"] = {10, 10, 4};
  twice["objects"]["second"] = twice["objects"]["rod"];
  twice["objects"]["second"]["geometry"]["bottom"] = {0.0, 0.02, 0.0};
  twice["objects"]["second"]["geometry"]["top"] = {0.025, 0.02, 0.0};
  BOOST_TEST(warnings_of(twice).size() == 1u);  // one per material, not per object

  BOOST_TEST(warnings_of(rod_scene(1100.0, "steel_4340_jc.json")).empty());  // states no range
}

BOOST_AUTO_TEST_CASE(a_reversed_fitted_range_is_refused_with_its_key_path) {
  Json doc = rod_scene(20.0);
  doc["materials"]["steel"]["overrides"] = {
      {"fitted_range", {{"strain_rate_min", 10.0}, {"strain_rate_max", 1.0}}}};
  const std::string error = impact::testing::scene_error_of(doc);
  BOOST_TEST_MESSAGE(error);
  BOOST_TEST(error.find("/fitted_range/strain_rate_max: expected at least strain_rate_min") !=
             std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
