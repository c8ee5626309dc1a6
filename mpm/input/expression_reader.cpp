// The scene's named constants and its fields of three components, each a number or an
// expression (docs/scenes.md#expressions; mpm/scene/expression.hpp).
#include <cctype>
#include <limits>
#include <sstream>

#include "mpm/input/block_readers.hpp"

namespace impact::mpm::scene_input {

void read_constants(JsonReader& root, const Json& doc, NamedConstants& out) {
  root.read_elsewhere("constants", [] {
    return KeyDescription{"object", "", "{}",
                          "named numbers [SI] the expressions may use, e.g. {\"A\": 1e-3}"};
  });
  const Json& n = at(doc, "constants");
  if (doc.is_object() && doc.contains("constants") && !n.is_object()) {
    root.problems().add("/constants", "expected an object of named numbers, got " + n.dump());
    return;
  }
  for (const auto& item : n.items()) {
    const std::string key = "/constants/" + pointer_token(item.key());
    if (const auto why = check_constant_name(item.key())) {
      root.problems().add(key, *why);
    } else if (!item.value().is_number()) {
      root.problems().add(key, "expected a number, got " + item.value().dump());
      // Declared all the same: an expression that uses it gets no second problem.
      out.emplace_back(item.key(), std::numeric_limits<double>::quiet_NaN());
    } else {
      out.emplace_back(item.key(), item.value().get<double>());
    }
  }
}

std::string expression_problem_message(const std::string& text, const ExpressionProblem& problem) {
  const std::string where = problem.position == std::string::npos ? ""
                            : problem.position >= text.size()
                                ? " at its end"
                                : " at character " + std::to_string(problem.position + 1);
  return "expression \"" + text + "\"" + where + ": " + problem.message;
}

VectorExpression read_vector_expression(JsonReader& r, const Json& node, std::string_view key,
                                        std::string_view meaning, const NamedConstants& constants,
                                        const std::optional<Vec3>& fallback) {
  r.read_elsewhere(key, [&] {
    std::string value;  // "": optional, no value (docs: none)
    if (fallback) {
      std::ostringstream text;
      text << '[' << (*fallback)(0) << ", " << (*fallback)(1) << ", " << (*fallback)(2) << ']';
      value = text.str();
    }
    return KeyDescription{"[3 numbers or expressions]", "", value,
                          std::string(meaning) +
                              "; an expression is text over X, Y, Z [m], t [s]"
                              " and /constants (docs/scenes.md#expressions)"};
  });
  VectorExpression e;
  e.value = fallback.value_or(Vec3::Zero());
  const std::string k(key);
  if (!node.is_object() || !node.contains(k)) return e;
  const Json& v = node[k];
  if (!v.is_array() || v.size() != 3) {
    r.problems().add(r.key_path(key), "expected an array of 3 numbers or expressions, got " +
                                          v.dump() + " (" + std::string(meaning) + ")");
    return e;
  }
  for (std::size_t d = 0; d < 3; ++d) {
    const std::string path = r.key_path(key) + "/" + std::to_string(d);
    if (v[d].is_number()) {
      e.value(d) = v[d].get<double>();
    } else if (v[d].is_string()) {
      const std::string text = v[d].get<std::string>();
      e.value(d) = 0.0;
      if (const auto problem = check_expression(text, constants)) {
        r.problems().add(path, expression_problem_message(text, *problem));
      } else {
        e.text[d] = text;
      }
    } else {
      r.problems().add(path, "expected a number or an expression (a string), got " + v[d].dump());
    }
  }
  return e;
}

namespace {

// Whether `text` names `name` as a whole word (an identifier of the expression).
bool names(const std::string& text, const std::string& name) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    const bool start = at == 0 || !word(text[at - 1]);
    const bool end = at + name.size() == text.size() || !word(text[at + name.size()]);
    if (start && end) return true;
  }
  return false;
}

}  // namespace

void warn_of_idle_expression_names(InputProblems& problems, const Scene& s) {
  std::vector<const VectorExpression*> fields;
  for (const SceneObject& o : s.objects)
    fields.insert(fields.end(), {&o.body_force, &o.velocity_field});
  if (s.output.exact_displacement) fields.push_back(&*s.output.exact_displacement);
  for (const auto& [name, value] : s.constants) {
    bool used = false;
    for (const VectorExpression* f : fields)
      for (const std::string& text : f->text) used = used || names(text, name);
    for (const FaceMotion& m : s.grid.face_velocity) used = used || names(m.text, name);
    if (!used) problems.warn("/constants/" + pointer_token(name), "not used by any expression");
  }
  for (const SceneObject& o : s.objects)  // a rigid object's expression is refused outright
    if (!o.rigid && o.velocity_field.uses("t", s.constants))
      problems.warn("/objects/" + pointer_token(o.name) + "/velocity",
                    "an initial velocity is evaluated at t = 0: its t is always 0");
}

}  // namespace impact::mpm::scene_input
