// The scene's named constants and its fields of three components, each a number or an
// expression (docs/scenes.md#expressions; mpm/scene/expression.hpp).
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
    const std::string key = "/constants/" + item.key();
    if (const auto why = check_constant_name(item.key())) {
      root.problems().add(key, *why);
    } else if (!item.value().is_number()) {
      root.problems().add(key, "expected a number, got " + item.value().dump());
    } else {
      out.emplace_back(item.key(), item.value().get<double>());
    }
  }
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
        const std::string where = problem->position == std::string::npos ? ""
                                  : problem->position >= text.size()
                                      ? " at its end"
                                      : " at character " + std::to_string(problem->position + 1);
        r.problems().add(path, "expression \"" + text + "\"" + where + ": " + problem->message);
      } else {
        e.text[d] = text;
      }
    } else {
      r.problems().add(path, "expected a number or an expression (a string), got " + v[d].dump());
    }
  }
  return e;
}

}  // namespace impact::mpm::scene_input
