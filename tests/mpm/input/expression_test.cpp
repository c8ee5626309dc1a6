// Expressions in scenes, one binary for the library and the reader.
//
// (1) Expressions in scenes (mpm/scene/expression.hpp, docs/scenes.md#expressions): a compiled
// field against the same formula in C++ (to 2 ulp: muParser evaluates the same libm functions in
// bytecode), the variables X, Y, Z, t and the constants bound, each thread's copy independent;
// and every refusal with its 0-based position and reason: a syntax error, an unknown name (the
// known ones listed), an assignment, two results, an empty text, and the names a constant may
// not take.
//
// (2) The scene reader on expressions (docs/scenes.md#expressions): a valid body force and its
// constants are read as written; every wrong one is refused with the file, the key path, the
// character (1-based) and the reason, and an unknown name lists the known ones, constants included.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "helpers/scene_refusal.hpp"
#include "mpm/scene/expression.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

const NamedConstants kConstants{{"A", 1e-3}, {"c", 1500.0}, {"L", 0.25}};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_expression)

BOOST_AUTO_TEST_CASE(a_compiled_field_equals_its_formula) {
  VectorExpression e;
  e.text = {"-A*(2*pi/L)^2*c^2*sin(2*pi*X/L)*cos(2*pi*c*t/L)", "", "Y*Z + t"};
  e.value = Vec3(0.0, 7.5, 0.0);  // the number of the component without text
  VectorField f(e, kConstants);
  const double pi = std::numbers::pi, A = 1e-3, c = 1500.0, L = 0.25;
  for (const Vec3& X : {Vec3(0.01, 0.02, 0.03), Vec3(0.2, -0.1, 5.0), Vec3(-0.3, 0.0, 1e-9)})
    for (const double t : {0.0, 1e-6, 3.3e-5}) {
      const Vec3 b = f(X, t);
      const double bx = -A * std::pow(2 * pi / L, 2) * c * c * std::sin(2 * pi * X(0) / L) *
                        std::cos(2 * pi * c * t / L);
      BOOST_TEST(b(0) == bx, boost::test_tools::tolerance(1e-14));
      BOOST_TEST(b(1) == 7.5);
      BOOST_TEST(b(2) == X(1) * X(2) + t, boost::test_tools::tolerance(1e-15));
    }
  // Another copy (another thread's) evaluates on its own variables.
  VectorField g(e, kConstants);
  const Vec3 before = f(Vec3(0.1, 0.2, 0.3), 1e-5);
  g(Vec3(9.0, 9.0, 9.0), 1.0);
  BOOST_TEST((f(Vec3(0.1, 0.2, 0.3), 1e-5) - before).norm() == 0.0);
  BOOST_TEST(e.uses("t", kConstants));
  BOOST_TEST(e.uses("Z", kConstants));
  e.text[2] = "";
  BOOST_TEST(!e.uses("Z", kConstants));
  BOOST_TEST(e.has_text());
  BOOST_TEST(!VectorExpression{}.has_text());
}

BOOST_AUTO_TEST_CASE(a_wrong_expression_names_where_and_why) {
  BOOST_TEST(!check_expression("A*sin(2*pi*X/L) + _e^t - _pi", kConstants));
  BOOST_TEST(!check_expression("X <= Y ? 1 : (X == Z ? 2 : 3)", kConstants));

  const auto unclosed = check_expression("sin(2*pi*X", kConstants);
  BOOST_TEST_REQUIRE(unclosed.has_value());
  BOOST_TEST(unclosed->position >= 10u);  // at its end
  BOOST_TEST(unclosed->message == "missing parenthesis");

  const auto unknown = check_expression("A*sin(2*pi*x)", kConstants);  // x, not X
  BOOST_TEST_REQUIRE(unknown.has_value());
  BOOST_TEST(unknown->position == 11u);
  BOOST_TEST(
      contains(unknown->message, "unknown name \"x\"; known: X, Y, Z, t, pi, _pi, _e, A, c, L"),
      unknown->message);

  const auto assigns = check_expression("X = 2*Y", kConstants);
  BOOST_TEST_REQUIRE(assigns.has_value());
  BOOST_TEST(assigns->position == 2u);
  BOOST_TEST(contains(assigns->message, "cannot assign"));

  const auto two = check_expression("X, Y", kConstants);
  BOOST_TEST_REQUIRE(two.has_value());
  BOOST_TEST(two->position == 1u);
  BOOST_TEST(contains(two->message, "one number expected"));

  const auto empty = check_expression("  ", kConstants);
  BOOST_TEST_REQUIRE(empty.has_value());
  BOOST_TEST(empty->message == "empty expression");

  const auto incomplete = check_expression("sin(X)*", kConstants);
  BOOST_TEST_REQUIRE(incomplete.has_value());
  BOOST_TEST(incomplete->position >= 7u);  // at its end

  const auto comma = check_expression("min(X, Y), 2", kConstants);
  BOOST_TEST_REQUIRE(comma.has_value());
  BOOST_TEST(comma->position == 9u);  // the comma outside the parentheses

  const auto nul = check_expression(std::string("X\0+100", 6), kConstants);
  BOOST_TEST_REQUIRE(nul.has_value());
  BOOST_TEST(nul->position == 1u);
  BOOST_TEST(nul->message == "a control character");

  const auto huge = check_expression(std::string(20001, '1'), kConstants);
  BOOST_TEST_REQUIRE(huge.has_value());
  BOOST_TEST(contains(huge->message, "longer than 20000 characters"));

  // A compiled field refuses what the check refuses.
  VectorExpression bad;
  bad.text[0] = "sin(";
  BOOST_CHECK_THROW(VectorField(bad, kConstants), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(a_constant_takes_a_free_name) {
  BOOST_TEST(!check_constant_name("A"));
  BOOST_TEST(!check_constant_name("rho_0"));
  BOOST_TEST(!check_constant_name("_k2"));
  BOOST_TEST(contains(check_constant_name("X").value_or(""), "is a variable"));
  BOOST_TEST(contains(check_constant_name("t").value_or(""), "is a variable"));
  BOOST_TEST(contains(check_constant_name("pi").value_or(""), "built-in constant"));
  BOOST_TEST(contains(check_constant_name("_e").value_or(""), "built-in constant"));
  BOOST_TEST(contains(check_constant_name("sin").value_or(""), "is a function"));
  BOOST_TEST(contains(check_constant_name("2a").value_or(""), "letter or '_'"));
  BOOST_TEST(contains(check_constant_name("a b").value_or(""), "letter or '_'"));
  BOOST_TEST(contains(check_constant_name("").value_or(""), "letter or '_'"));
  // muParser's longest name is 100 characters: a longer one is refused, not thrown.
  BOOST_TEST(!check_constant_name(std::string(100, 'a')));
  BOOST_TEST(contains(check_constant_name(std::string(101, 'a')).value_or(""), "at most 100"));
  BOOST_TEST(!check_expression("X", {{std::string(101, 'a'), 1.0}}));  // left out, no throw
}

BOOST_AUTO_TEST_CASE(the_uniform_part_of_a_field_is_its_numbers) {
  VectorExpression e;
  e.text = {"2*A*1e3", "X*Y", ""};
  e.value = Vec3(0.0, 0.0, -4.0);
  BOOST_TEST(is_constant_expression("2*A*1e3", kConstants));
  BOOST_TEST(!is_constant_expression("X*Y", kConstants));
  const Vec3 u = e.uniform_part(kConstants);
  BOOST_TEST(u(0) == 2.0);
  BOOST_TEST(u(1) == 0.0);
  BOOST_TEST(u(2) == -4.0);
}

BOOST_AUTO_TEST_SUITE_END()

namespace {

using impact::testing::axisymmetric_rod;
using impact::testing::check_refused;
using impact::testing::scene_error_of;

const std::string kScenes = std::string(IMPACT_SOURCE_DIR) + "/data/scenes/";

// The stress-free translating block with a body force `b` and constants `k`.
Json block_with(const Json& b, const Json& k = Json::object()) {
  Json doc = load_scene_document(kScenes + "verification/rigid_translation.json");
  doc["objects"]["block"]["body_force"] = b;
  if (!k.empty()) doc["constants"] = k;
  return doc;
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
  Json doc = axisymmetric_rod();
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
