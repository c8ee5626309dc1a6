// Expressions in scenes (docs/scenes.md#expressions): a component written as text over the
// reference coordinates X, Y, Z [m] and the time t [s], with the scene's named constants, for the
// fields a manufactured solution needs (Wallstedt & Guilkey 2008): a body force, an initial
// velocity. Parsed and compiled once by muParser (Debian's libmuparser-dev: maintained, bytecode
// evaluation without allocation, error positions); evaluated per particle.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "models/core/tensor.hpp"

namespace impact::mpm {

/// A scene's top-level "constants": name -> value [SI], in name order (as the JSON object reads).
using NamedConstants = std::vector<std::pair<std::string, double>>;

/// The variables every expression may use, and the constants every expression has.
inline constexpr std::array<const char*, 4> kExpressionVariables{"X", "Y", "Z", "t"};
inline constexpr std::array<const char*, 3> kBuiltInConstants{"pi", "_pi", "_e"};

/// Three components, each a number or an expression's text. A number stays a number: it costs
/// nothing to evaluate, and a scene without text behaves exactly as before.
struct VectorExpression {
  std::array<std::string, 3> text;  ///< empty: the component is value(d)
  Vec3 value = Vec3::Zero();

  bool has_text() const { return !text[0].empty() || !text[1].empty() || !text[2].empty(); }
  /// Whether any component reads the variable `name` (X, Y, Z or t).
  bool uses(const std::string& name, const NamedConstants& constants) const;
  /// The components that vary over X, Y, Z, t as 0, the others as the numbers they are (a text
  /// without a variable evaluated): what the checks of a field's uniform part read.
  Vec3 uniform_part(const NamedConstants& constants) const;
};

/// What is wrong with an expression: the 0-based character position (npos: the whole text; the
/// text's length or more: its end) and why.
struct ExpressionProblem {
  std::size_t position = std::string::npos;
  std::string message;
};

/// nullopt when `text` compiles over X, Y, Z, t, the built-in and the scene's constants, and yields
/// one finite-or-not number; otherwise where and why not. An unknown name lists the known ones.
std::optional<ExpressionProblem> check_expression(const std::string& text,
                                                  const NamedConstants& constants);

/// Whether `text` (one check_expression() accepts) reads none of X, Y, Z, t: a number written as
/// text, which the checks of a field treat as the number it is.
bool is_constant_expression(const std::string& text, const NamedConstants& constants);

/// Why a constant's name cannot be used, or nullopt: it must be a name muParser reads (a letter or
/// underscore, then at most 99 letters, digits, underscores) and not a variable, a built-in
/// constant or a function of muParser.
std::optional<std::string> check_constant_name(const std::string& name);

/// A VectorExpression compiled for one thread: muParser keeps its evaluation stack in the parser,
/// so each thread evaluates its own copy. Throws std::invalid_argument on an expression
/// check_expression() refuses (the scene reader has refused it before).
class VectorField {
 public:
  VectorField(const VectorExpression& e, const NamedConstants& constants);
  ~VectorField();
  VectorField(VectorField&&) noexcept;
  VectorField& operator=(VectorField&&) noexcept;
  VectorField(const VectorField&) = delete;
  VectorField& operator=(const VectorField&) = delete;

  /// The field at reference position X [m] and time t [s].
  Vec3 operator()(const Vec3& X, double t);

 private:
  struct Compiled;
  std::unique_ptr<Compiled> c_;
};

}  // namespace impact::mpm
