// The keys an input format has, as its reader asks for them: for each JSON key path the type,
// the admissible range, the default and the meaning that the reader's own calls carry (MOOSE's
// validParams, built from the reader instead of beside it). A JsonReader records into an
// InputKeyRecorder only when one is attached to its InputProblems; docs are checked against it
// (tests/mpm/input/scene_keys_test.cpp) and `mpm keys` prints it.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impact {

/// What a reader knows about one key at the call that reads it.
struct KeyDescription {
  std::string type;   ///< "number", "boolean", "string", "object", "one of: a, b", "[3 numbers]"
  std::string range;  ///< Range::describe() of a number ("(0, inf)"), else ""
  /// The value used when the key is absent; std::nullopt: the key is required; "": optional, no
  /// value (an optional block or observable).
  std::optional<std::string> default_value;
  std::string meaning;
};

/// One key: its JSON key path (RFC 6901 pointer, e.g. /time/max_time) and description.
struct InputKey {
  std::string path;
  KeyDescription description;
};

/// The keys recorded while reading one or more documents of a format, in the order first read.
class InputKeyRecorder {
 public:
  /// Keeps the first description of a path: a read that delegates (number_or to number) or a
  /// second document of the same format adds nothing.
  void record(std::string_view path, KeyDescription description);
  /// The recorded description of `path`, for a caller that knows more than the read it made
  /// (integers read through an array of numbers); nullptr when the path was not recorded.
  KeyDescription* find(std::string_view path);
  const std::vector<InputKey>& keys() const { return keys_; }

 private:
  std::vector<InputKey> keys_;
};

/// A key path in the dotted form the docs use: /objects/NAME/velocity with `wildcard` "NAME"
/// becomes objects.<name>.velocity (any member of a map of named entries).
std::string dotted_key(std::string_view pointer, std::string_view wildcard);

/// The keys as a Markdown table: key | type | range | default | meaning (dotted keys).
std::string keys_markdown(const std::vector<InputKey>& keys, std::string_view wildcard);
/// The keys as a JSON array of {key, pointer, type, range, required, default, meaning}.
nlohmann::json keys_json(const std::vector<InputKey>& keys, std::string_view wildcard);

}  // namespace impact
