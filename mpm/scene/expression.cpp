#include "mpm/scene/expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <numbers>
#include <stdexcept>
#include <string_view>

namespace impact::mpm {

namespace {

// A parser with the variables bound to `vars` (X, Y, Z, t), the built-in constant pi (muParser
// has _pi and _e) and the scene's constants. Built-in operators only: an assignment "X = 1" in a
// scene would change a variable behind the evaluation's back.
void prepare(mu::Parser& p, std::array<double, 4>& vars, const NamedConstants& constants) {
  for (std::size_t i = 0; i < kExpressionVariables.size(); ++i)
    p.DefineVar(kExpressionVariables[i], &vars[i]);
  p.DefineConst("pi", std::numbers::pi);
  // A constant the reader refused (check_constant_name) is left out: its own problem names it.
  for (const auto& [name, value] : constants)
    if (!check_constant_name(name)) p.DefineConst(name, value);
}

std::string known_names(const NamedConstants& constants) {
  std::string s;
  for (const char* v : kExpressionVariables) s.append(s.empty() ? "" : ", ").append(v);
  for (const char* c : kBuiltInConstants) s.append(", ").append(c);
  for (const auto& c : constants) s.append(", ").append(c.first);
  return s;
}

bool is_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// The position of an assignment "=" (not part of ==, <=, >= or !=), or npos.
std::size_t assignment(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '=') continue;
    const bool after = i > 0 && std::string_view("<>!=").find(text[i - 1]) != std::string::npos;
    const bool before = i + 1 < text.size() && text[i + 1] == '=';
    if (!after && !before) return i;
    if (before) ++i;  // "==": both characters read
  }
  return std::string::npos;
}

// muParser's message without its own position (the reader gives it) and its full stop, in lower
// case; its "Internal error" (seen on "2*+") says only that the expression is incomplete.
std::string tidy(std::string m) {
  if (m == "Internal error") return "incomplete expression";
  for (const char* tail : {" at position ", " at expression position ", " (position: "})
    if (const std::size_t at = m.find(tail); at != std::string::npos) m.erase(at);
  while (!m.empty() && (m.back() == '.' || m.back() == ' ')) m.pop_back();
  if (!m.empty()) m[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(m[0])));
  return m;
}

// The first comma outside parentheses (what makes muParser return several results), or npos.
std::size_t top_level_comma(const std::string& text) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
    if (text[i] == ',' && depth == 0) return i;
  }
  return std::string::npos;
}

// Compiles `text` in `p` (muParser parses on the first evaluation) and says what is wrong.
std::optional<ExpressionProblem> compile(mu::Parser& p, const std::string& text,
                                         const NamedConstants& constants) {
  try {
    if (std::all_of(text.begin(), text.end(),
                    [](char c) { return std::isspace(static_cast<unsigned char>(c)); }))
      return ExpressionProblem{std::string::npos, "empty expression"};
    // A NUL or another control character would end or hide part of the text muParser reads.
    for (std::size_t i = 0; i < text.size(); ++i)
      if (std::iscntrl(static_cast<unsigned char>(text[i])) &&
          !std::isspace(static_cast<unsigned char>(text[i])))
        return ExpressionProblem{i, "a control character"};
    if (text.size() > std::size_t(mu::MaxLenExpression))
      return ExpressionProblem{
          std::string::npos, "longer than " + std::to_string(mu::MaxLenExpression) + " characters"};
    if (const std::size_t at = assignment(text); at != std::string::npos)
      return ExpressionProblem{at, "an expression cannot assign (\"=\"); compare with \"==\""};
    p.SetExpr(text);
    p.Eval();
    if (p.GetNumResults() != 1)
      return ExpressionProblem{top_level_comma(text), "one number expected, the comma makes " +
                                                          std::to_string(p.GetNumResults())};
  } catch (const mu::Parser::exception_type& e) {
    const std::size_t at = e.GetPos() >= 0 ? std::size_t(e.GetPos()) : std::string::npos;
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && is_name(e.GetToken()))
      return ExpressionProblem{at, "unknown name \"" + e.GetToken() +
                                       "\"; known: " + known_names(constants) +
                                       " (constants are declared in /constants)"};
    return ExpressionProblem{at, tidy(e.GetMsg())};
  }
  return std::nullopt;
}

}  // namespace

std::optional<ExpressionProblem> check_expression(const std::string& text,
                                                  const NamedConstants& constants) {
  mu::Parser p;
  std::array<double, 4> vars{};
  prepare(p, vars, constants);
  return compile(p, text, constants);
}

bool is_constant_expression(const std::string& text, const NamedConstants& constants) {
  mu::Parser p;
  std::array<double, 4> vars{};
  prepare(p, vars, constants);
  try {
    p.SetExpr(text);
    return p.GetUsedVar().empty();
  } catch (const mu::Parser::exception_type&) {
    return false;
  }
}

std::optional<std::string> check_constant_name(const std::string& name) {
  if (!is_name(name))
    return "a constant's name is a letter or '_' followed by letters, digits or '_'";
  if (name.size() > std::size_t(mu::MaxLenIdentifier))
    return "a constant's name has at most " + std::to_string(mu::MaxLenIdentifier) + " characters";
  for (const char* v : kExpressionVariables)
    if (name == v) return "\"" + name + "\" is a variable (X, Y, Z, t)";
  for (const char* c : kBuiltInConstants)
    if (name == c) return "\"" + name + "\" is a built-in constant";
  const mu::Parser p;
  if (p.GetFunDef().count(name)) return "\"" + name + "\" is a function of the expressions";
  return std::nullopt;
}

bool VectorExpression::uses(const std::string& name, const NamedConstants& constants) const {
  for (const std::string& t : text) {
    if (t.empty()) continue;
    mu::Parser p;
    std::array<double, 4> vars{};
    prepare(p, vars, constants);
    p.SetExpr(t);
    try {
      if (p.GetUsedVar().count(name)) return true;
    } catch (const mu::Parser::exception_type&) {
      return true;  // refused by the reader before: say yes, the safe answer
    }
  }
  return false;
}

Vec3 VectorExpression::uniform_part(const NamedConstants& constants) const {
  Vec3 out = value;
  for (int d = 0; d < 3; ++d) {
    if (text[d].empty()) continue;
    out(d) = 0.0;
    if (!is_constant_expression(text[d], constants)) continue;
    VectorExpression one;
    one.text[d] = text[d];
    out(d) = VectorField(one, constants)(Vec3::Zero(), 0.0)(d);
  }
  return out;
}

struct VectorField::Compiled {
  std::array<double, 4> vars{};  // X, Y, Z, t: the parsers read them through pointers
  std::array<mu::Parser, 3> parsers;
  std::array<bool, 3> is_text{};
  Vec3 value = Vec3::Zero();
};

VectorField::VectorField(const VectorExpression& e, const NamedConstants& constants)
    : c_(std::make_unique<Compiled>()) {
  c_->value = e.value;
  for (int d = 0; d < 3; ++d) {
    if (e.text[d].empty()) continue;
    c_->is_text[d] = true;
    prepare(c_->parsers[d], c_->vars, constants);
    if (const auto problem = compile(c_->parsers[d], e.text[d], constants))
      throw std::invalid_argument("expression \"" + e.text[d] + "\": " + problem->message);
  }
}

VectorField::~VectorField() = default;
VectorField::VectorField(VectorField&&) noexcept = default;
VectorField& VectorField::operator=(VectorField&&) noexcept = default;

Vec3 VectorField::operator()(const Vec3& X, double t) {
  Compiled& c = *c_;
  c.vars = {X(0), X(1), X(2), t};
  Vec3 out = c.value;
  for (int d = 0; d < 3; ++d)
    if (c.is_text[d]) out(d) = c.parsers[d].Eval();
  return out;
}

}  // namespace impact::mpm
