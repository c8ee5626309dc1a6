// The scene reader on expressions (docs/scenes.md#expressions): a valid body force and its
// constants are read as written; every wrong one is refused with the file, the key path, the
// character (1-based) and the reason, and an unknown name lists the known ones, constants included.
#include <boost/test/unit_test.hpp>
#include <string>

#include "helpers/scene_error.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

using impact::testing::scene_error_of;

const std::string kScenes = std::string(IMPACT_SOURCE_DIR) + "/data/scenes/";

// The stress-free translating block with a body force `b` and constants `k`.
Json block_with(const Json& b, const Json& k = Json::object()) {
  Json doc = load_scene_document(kScenes + "verification/rigid_translation.json");
  doc["objects"]["block"]["body_force"] = b;
  if (!k.empty()) doc["constants"] = k;
  return doc;
}

void check_refused(const Json& doc, const std::vector<std::string>& parts) {
  const std::string e = scene_error_of(doc);
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("test.json: ") != std::string::npos);
  for (const std::string& part : parts)
    BOOST_TEST(e.find(part) != std::string::npos, "\"" << part << "\" in\n" << e);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_expression_refusals)

BOOST_AUTO_TEST_CASE(a_valid_body_force_is_read_as_written) {
  const Scene s = read_scene(block_with({"-A*sin(2*pi*X/L)*cos(w*t)", 0.5, "B"},
                                        {{"A", 2.0}, {"L", 0.1}, {"w", 1e5}, {"B", -3.0}}),
                             "test.json");
  const SceneObject& o = s.objects.at(0);
  BOOST_TEST(o.has_body_force());
  BOOST_TEST(s.has_body_force());
  BOOST_TEST(o.body_force.text[0] == "-A*sin(2*pi*X/L)*cos(w*t)");
  BOOST_TEST(o.body_force.text[1].empty());
  BOOST_TEST(o.body_force.value(1) == 0.5);
  BOOST_TEST(o.body_force.text[2] == "B");
  BOOST_TEST(s.constants.size() == 4u);
  BOOST_TEST(s.constants[1].first == "B");  // in name order
  BOOST_TEST(s.constants[1].second == -3.0);
  // Without the key, no body force.
  const Scene plain =
      read_scene(load_scene_document(kScenes + "verification/rigid_translation.json"), "test.json");
  BOOST_TEST(!plain.has_body_force());
}

BOOST_AUTO_TEST_CASE(a_wrong_expression_is_refused_at_its_character) {
  check_refused(block_with({"sin(2*pi*X", 0, 0}),
                {"/objects/block/body_force/0: expression \"sin(2*pi*X\" at its end: "
                 "missing parenthesis"});
  check_refused(block_with({0, "A*x", 0}, {{"A", 1.0}}),
                {"/objects/block/body_force/1: expression \"A*x\" at character 3: unknown name "
                 "\"x\"; known: X, Y, Z, t, pi, _pi, _e, A"});
  check_refused(block_with({0, 0, "X = 1"}), {"/objects/block/body_force/2:", "cannot assign"});
  check_refused(block_with({"1, 2", 0, 0}), {"/objects/block/body_force/0:", "one number"});
  check_refused(block_with({"", 0, 0}), {"/objects/block/body_force/0:", "empty expression"});
  check_refused(block_with({true, 0, 0}),
                {"/objects/block/body_force/0: expected a number or an expression"});
  check_refused(block_with({0, 0}), {"/objects/block/body_force: expected an array of 3"});
  check_refused(block_with("9.81"), {"/objects/block/body_force: expected an array of 3"});
}

BOOST_AUTO_TEST_CASE(a_wrong_constant_is_refused_by_name) {
  check_refused(block_with({"k", 0, 0}, {{"X", 1.0}, {"k", "one"}, {"sqrt", 2.0}, {"2b", 1.0}}),
                {"/constants/X: \"X\" is a variable", "/constants/k: expected a number",
                 "/constants/sqrt: \"sqrt\" is a function", "/constants/2b: a constant's name"});
  // A constant refused for its value is still declared: no second problem where it is used.
  BOOST_TEST(scene_error_of(block_with({"k", 0, 0}, {{"k", "one"}})).find("unknown name") ==
             std::string::npos);
  Json doc = block_with({0, 0, 0});
  doc["constants"] = Json::array({1, 2});
  check_refused(doc, {"/constants: expected an object of named numbers"});
}

BOOST_AUTO_TEST_CASE(a_field_that_is_not_finite_at_a_seed_point_is_refused) {
  // The block's seed points run from X = 0.02125 to 0.03875 m: the root of a negative number
  // beyond 0.03, and 1/t at t = 0.
  Json doc = block_with({0, 0, 0});
  doc["objects"]["block"]["velocity"] = {"sqrt(0.03 - X)", 0, 0};
  check_refused(doc, {"/objects/block/velocity: not finite at the seed point X = [0.03125"});
  check_refused(block_with({"1/t", 0, 0}),
                {"/objects/block/body_force: not finite at the seed point X = [0.02125"});
  // A constant name muParser cannot hold is refused, not thrown.
  check_refused(block_with({0, 0, 0}, {{std::string(101, 'k'), 1.0}}),
                {"a constant's name has at most 100 characters"});
  // The units check reads an expression's largest value at the seed points: 1e6 X reaches 3.9e4.
  doc["objects"]["block"]["velocity"] = {"1e6*X", 0, 0};
  const Scene s = read_scene(doc, "test.json");
  BOOST_TEST(s.objects[0].velocity(0) == 1e6 * 0.03875, boost::test_tools::tolerance(1e-12));
  std::string warnings;
  for (const std::string& w : s.warnings) warnings += w + "\n";
  BOOST_TEST_MESSAGE(warnings);
  BOOST_TEST(warnings.find("/objects/block/velocity/0") != std::string::npos, warnings);
}

BOOST_AUTO_TEST_CASE(an_idle_name_is_warned_of) {
  // "Kx" is used, "K" only inside it; "w" nowhere; the velocity reads t, always 0 there.
  Json doc = block_with({"Kx*X", 0, 0}, {{"Kx", 1.0}, {"K", 2.0}, {"w", 3.0}});
  doc["objects"]["block"]["velocity"] = {"10*cos(t)", 0, 0};
  const Scene s = read_scene(doc, "test.json");
  std::string warnings;
  for (const std::string& w : s.warnings) warnings += w + "\n";
  BOOST_TEST_MESSAGE(warnings);
  BOOST_TEST(warnings.find("/constants/K: not used by any expression") != std::string::npos);
  BOOST_TEST(warnings.find("/constants/w: not used by any expression") != std::string::npos);
  BOOST_TEST(warnings.find("/constants/Kx") == std::string::npos);
  BOOST_TEST(warnings.find("/objects/block/velocity: an initial velocity is evaluated at t = 0") !=
             std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_2d_body_force_moves_as_its_grid_models) {
  // An axisymmetric rod: a radial field of revolution is fine, a uniform radial one is not, and
  // nothing along z.
  Json doc = load_scene_document(kScenes + "verification/elastic_base.json");
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
                       {"particles_per_cell", {2, 2}}}}}}});
  doc["objects"]["rod"]["body_force"] = {"1e3*X", "1e5*Y", 0};
  BOOST_TEST(scene_error_of(doc) == "");
  doc["objects"]["rod"]["body_force"] = {0, 10.0, 0};
  check_refused(doc, {"/objects/rod/body_force: body force [0, 10, 0] on grid.geometry "
                      "\"axisymmetric\": expected [v, 0, 0]"});
  // A text without a variable is the number it is: a uniform radial field still.
  doc["objects"]["rod"]["body_force"] = {0, "1e6", 0};
  check_refused(doc, {"/objects/rod/body_force: body force [0, 1e+06, 0]",
                      "a radial component may be an expression of X and Y"});
  doc["objects"]["rod"]["body_force"] = {0, 0, "Y"};
  check_refused(doc, {"/objects/rod/body_force/2: no expression along z"});
  // The initial velocity likewise: a radial field of revolution, nothing along z.
  doc["objects"]["rod"]["body_force"] = {0, 0, 0};
  doc["objects"]["rod"]["velocity"] = {"10*X", "100*Y", 0};
  BOOST_TEST(scene_error_of(doc) == "");
  doc["objects"]["rod"]["velocity"] = {0, 0, "X"};
  check_refused(doc, {"/objects/rod/velocity/2: no expression along z"});
  doc["objects"]["rod"]["velocity"] = {"X*", 0, 0};
  check_refused(doc, {"/objects/rod/velocity/0: expression \"X*\" at its end"});
}

BOOST_AUTO_TEST_SUITE_END()
