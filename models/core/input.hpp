// Reading JSON input with errors a user can act on: every problem names the file, the JSON key path
// (RFC 6901 pointer) and what was expected, and all problems of a document are reported at once.
#pragma once

#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "models/core/input_keys.hpp"
#include "models/core/units_check.hpp"

namespace impact {

using Json = nlohmann::json;

/// A bad input: one or more problems, each "file: /key/path: expected ..., got ... (meaning)".
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

/// Problems found while reading one document; collected so the user sees all of them in one run.
/// A JSON document names a problem's place by key path (add), a line-based one by line
/// (add_at_line).
/// Warnings (admissible but suspicious values, e.g. a unit slip) are kept apart: they do not stop
/// the reader, and the loader hands them to its caller, which prints them.
class InputProblems {
 public:
  explicit InputProblems(std::string file) : file_(std::move(file)) {}
  void add(std::string_view key_path, std::string_view message);
  /// Records "file: /key/path: message" as a warning.
  void warn(std::string_view key_path, std::string_view message);
  /// Warns when `value` of quantity `q` looks typed in another unit (units_check.hpp).
  void check_units(std::string_view key_path, Quantity q, double value);
  /// The problems and warnings of a document this one refers to (a material file), each
  /// recorded at `key_path` (the referring key) as "prefix" + its own "file: /path: message".
  void add_nested(std::string_view key_path, std::string_view prefix, const InputError& error);
  void warn_nested(std::string_view key_path, std::string_view prefix,
                   const std::vector<std::string>& warnings);
  /// Records "file:line: message", for a line-based document (a CSV file) where a line, not a
  /// key path, says where; line 0 means the file as a whole ("file: message").
  void add_at_line(int line, std::string_view message);
  /// "file:line" ("file" for line 0): how add_at_line names a place, for a warning or a note
  /// the caller keeps itself.
  std::string line_location(int line) const;
  bool empty() const { return problems_.empty(); }
  std::size_t count() const { return problems_.size(); }
  /// Throws InputError with every problem collected so far, followed by the warnings (each
  /// "warning: file: ..."); does nothing when there are no problems.
  void throw_if_any() const;
  const std::string& file() const { return file_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// Every JsonReader of this document records the keys it reads into `keys` (nullptr: off, the
  /// default; a read then costs one pointer test more).
  void record_keys_to(InputKeyRecorder* keys) { keys_ = keys; }
  InputKeyRecorder* key_recorder() const { return keys_; }

 private:
  std::string file_;
  InputKeyRecorder* keys_ = nullptr;
  std::vector<std::string> problems_;
  std::vector<std::string> warnings_;
};

/// One reference token of a JSON pointer (RFC 6901, section 3): '~' written "~0" and '/' written
/// "~1", so a key that holds either still names its own place in a key path.
std::string pointer_token(std::string_view key);

/// An interval of admissible values, open or closed at each end.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;
  bool max_open = false;

  bool contains(double v) const;
  std::string describe() const;  ///< e.g. "(0, 1]"

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity()}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open_closed(double a, double b) { return {a, b, true, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }
};

/// A view of one JSON object at a key path. Reads record which keys were used, so that
/// reject_unknown_keys() can flag misspellings with a nearest-key suggestion. A failed read records
/// a problem and returns a quiet NaN or the fallback: call problems.throw_if_any() before using
/// them.
class JsonReader {
 public:
  JsonReader(const Json& node, std::string path, InputProblems& problems);

  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const { return path_ + "/" + pointer_token(key); }
  bool has(std::string_view key) const;
  InputProblems& problems() const { return *problems_; }

  double number(std::string_view key, Range range, std::string_view meaning);
  double number_or(std::string_view key, double fallback, Range range, std::string_view meaning);
  /// A number of quantity `q` in SI units: as number(), and units plausibility on top
  /// (units_check.hpp): outside `range` (physically impossible) the problem also names the likely
  /// unit; inside `range` but implausible for `q`, a warning names it and the value is used.
  double quantity(std::string_view key, Quantity q, Range range, std::string_view meaning);
  double quantity_or(std::string_view key, double fallback, Quantity q, Range range,
                     std::string_view meaning);
  bool boolean_or(std::string_view key, bool fallback, std::string_view meaning);
  std::string string(std::string_view key, std::string_view meaning);
  std::string string_or(std::string_view key, std::string_view fallback, std::string_view meaning);
  /// A string that must be one of `known`; the error lists the known names.
  std::string choice(std::string_view key, std::initializer_list<std::string_view> known,
                     std::string_view meaning, std::optional<std::string_view> fallback = {});
  /// The same with the names in a vector (a catalogue's).
  std::string choice(std::string_view key, const std::vector<std::string_view>& known,
                     std::string_view meaning, std::optional<std::string_view> fallback = {});
  /// The object at `key`; a missing or non-object value is a problem and yields an empty object.
  JsonReader child(std::string_view key, std::string_view meaning);
  /// The object at `key` if present (a present non-object is a problem).
  std::optional<JsonReader> optional_child(std::string_view key, std::string_view meaning);
  /// Marks a key as handled elsewhere (documentation-only keys such as "source").
  void ignore(std::string_view key);
  /// As ignore(), for a key that other code reads (an array, a block read later): when keys are
  /// recorded, records it with `description`, which is built only then.
  template <class Describe>
  void read_elsewhere(std::string_view key, Describe&& description) {
    ignore(key);
    if (InputKeyRecorder* keys = problems_->key_recorder())
      keys->record(key_path(key), description());
  }
  /// Lets `amend` change the recorded description of `key` (a KeyDescription&), when keys are
  /// recorded and the key was: a caller that knows more than the read it made.
  template <class Amend>
  void amend_description(std::string_view key, Amend&& amend) {
    if (InputKeyRecorder* keys = problems_->key_recorder()) {
      if (KeyDescription* d = keys->find(key_path(key))) amend(*d);
    }
  }
  /// Records "unknown key (did you mean ...?)" for every key that no read touched.
  void reject_unknown_keys();

 private:
  const Json* find(std::string_view key);
  /// Records `key` when keys are recorded (InputProblems::record_keys_to); `default_value` as in
  /// KeyDescription.
  void record(std::string_view key, std::string_view type, const Range* range,
              std::optional<std::string_view> default_value, std::string_view meaning) const;
  void record_number(std::string_view key, const Range& range, std::optional<double> fallback,
                     std::string_view meaning) const;
  double read_number(std::string_view key, Range range, std::string_view meaning,
                     std::optional<Quantity> q);
  const Json* node_;
  std::string path_;
  InputProblems* problems_;
  std::set<std::string, std::less<>> used_;
};

/// What keeps `file` from being read as a file: "is a directory", "is not a regular file (a
/// FIFO, socket or device)"; nothing when it is a regular file (or a link to one) or is missing.
std::optional<std::string> not_a_regular_file(const std::string& file);

/// Parses a JSON file; a missing file or a syntax error becomes an InputError naming the file and,
/// for syntax errors, the byte position (a number beyond the range of a double: its key path, as
/// parse_json_text).
Json load_json_file(const std::string& file);

/// Parses JSON text that messages call `what` (a file name, "--set patch 2"). A syntax error is an
/// InputError "what: JSON syntax error at byte N: ..."; a number no double can hold (1e999, a
/// 400-digit integer) is one naming its key path: "what: /density: the number 1e999 is beyond
/// the range of a double (magnitude at most 1.8e308)"; so is one below it that would read as 0
/// (1e-400).
Json parse_json_text(const std::string& text, const std::string& what);

/// The candidate closest to `word` by edit distance, if it is close enough to be a likely typo.
std::optional<std::string> nearest_name(std::string_view word,
                                        const std::vector<std::string>& candidates);

/// The empty object used as a stand-in where a child is missing.
const Json& empty_json_object();

/// A count read as a double (already range-checked, the problem recorded) as an int without
/// undefined behaviour: NaN (a failed read) gives `lo`, values outside [lo, hi] are clamped.
inline int clamped_int(double v, int lo, int hi) {
  if (!(v >= lo)) return lo;
  return v > hi ? hi : static_cast<int>(v);
}

}  // namespace impact
