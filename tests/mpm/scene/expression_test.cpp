// Expressions in scenes (mpm/scene/expression.hpp, docs/scenes.md#expressions): a compiled field
// against the same formula in C++ (to 2 ulp: muParser evaluates the same libm functions in
// bytecode), the variables X, Y, Z, t and the constants bound, each thread's copy independent;
// and every refusal with its 0-based position and reason: a syntax error, an unknown name (the
// known ones listed), an assignment, two results, an empty text, and the names a constant may
// not take.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

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
