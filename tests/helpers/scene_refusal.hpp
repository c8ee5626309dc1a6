// Shared by the tests of the scene reader's refusals (mpm/input/): a refusal's message checked
// part by part, and a valid axisymmetric scene to break.
#pragma once

#include <boost/test/unit_test.hpp>
#include <string>
#include <vector>

#include "helpers/scene_error.hpp"

namespace impact::testing {

/// The message reading `doc` as "test.json" throws, checked to name the file and to contain every
/// expected part.
inline void check_refused(const nlohmann::json& doc, const std::vector<std::string>& parts) {
  const std::string e = scene_error_of(doc);
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("test.json: ") != std::string::npos);
  for (const std::string& part : parts)
    BOOST_TEST(e.find(part) != std::string::npos, "\"" << part << "\" in\n" << e);
}

/// A rod on the axis of an axisymmetric grid at 30 m/s along it (a valid scene): 8 x 2 cells of
/// 5 mm, the rod 20 mm long, 5 mm in radius, on data/scenes/verification/elastic_base.json.
inline nlohmann::json axisymmetric_rod() {
  nlohmann::json doc = mpm::load_scene_document(std::string(IMPACT_SOURCE_DIR) +
                                                "/data/scenes/verification/elastic_base.json");
  doc.merge_patch({{"grid",
                    {{"geometry", "axisymmetric"},
                     {"lower", {0.0, 0.0}},
                     {"upper", {0.04, 0.01}},
                     {"cells", {8, 2}},
                     {"boundary", {{"x+", "free"}, {"y+", "free"}}}}},
                   {"objects",
                    {{"rod",
                      {{"material", "elastic_al"},
                       {"geometry",
                        {{"type", "cylinder"},
                         {"bottom", {0.0, 0.0, 0.0}},
                         {"top", {0.02, 0.0, 0.0}},
                         {"radius", 0.005}}},
                       {"velocity", {30.0, 0.0, 0.0}},
                       {"particles_per_cell", {2, 2}}}}}}});
  return doc;
}

}  // namespace impact::testing
