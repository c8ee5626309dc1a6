#include "models/core/input.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace impact {

namespace {

std::string join_problems(const std::vector<std::string>& problems) {
  std::string text;
  for (const auto& p : problems) {
    if (!text.empty()) text += '\n';
    text += p;
  }
  return text;
}

std::string json_type_name(const Json& v) {
  if (v.is_number()) return "a number " + v.dump();
  if (v.is_string()) return "the string " + v.dump();
  if (v.is_boolean()) return std::string("the boolean ") + (v.get<bool>() ? "true" : "false");
  if (v.is_null()) return "null";
  if (v.is_array()) return "an array";
  return "an object";
}

std::string with_meaning(std::string message, std::string_view meaning) {
  if (!meaning.empty()) message += " (" + std::string(meaning) + ")";
  return message;
}

std::string format_number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// A value as it was written, to every digit that tells it apart (the shortest text that reads
// back as the same double): 2.0000001 outside [1.05, 2] is not "got 2".
std::string exact_number(double v) {
  std::array<char, 32> text{};
  const auto end = std::to_chars(text.data(), text.data() + text.size(), v).ptr;
  return std::string(text.data(), end);
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const std::size_t cost = (std::tolower(a[i - 1]) == std::tolower(b[j - 1])) ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// SAX events of nlohmann::json that track the key path, to name where parsing stopped: the
/// value after the last key of an object, or after the last element of an array. The parse
/// stops at a number beyond the range of a double (1e999: nlohmann::json's own error), at one
/// below it (1e-400, which it reads as 0 without a word: `underflow`) and at a key that its
/// object already has (`duplicate`: nlohmann::json keeps the last silently, so `"time"` written
/// twice ran with the second and `"x-": 0.25, "x-": 99` reported only the 99).
class NumberLocator {
 public:
  std::string pointer;     ///< of the value that stopped the parse ("" for the top level)
  std::string token;       ///< its text, e.g. 1e999
  bool underflow = false;  ///< stopped at a number that is not 0 but reads as 0
  bool duplicate = false;  ///< stopped at a key its object already has

  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(Json::number_integer_t) { return value(); }
  bool number_unsigned(Json::number_unsigned_t) { return value(); }
  bool number_float(Json::number_float_t v, const Json::string_t& text) {
    const std::size_t exponent = text.find_first_of("eE");
    const bool zero_written =
        text.substr(0, exponent).find_first_of("123456789") == std::string::npos;
    if (v != 0.0 || zero_written) return value();
    underflow = true;
    return stop(text);
  }
  bool string(Json::string_t&) { return value(); }
  bool binary(Json::binary_t&) { return value(); }
  bool start_object(std::size_t) {
    value();
    frames_.push_back({false, "", -1, {}});
    return true;
  }
  bool key(Json::string_t& k) {
    frames_.back().key = k;
    if (frames_.back().keys.insert(k).second) return true;
    duplicate = true;
    return stop("\"" + k + "\"");
  }
  bool end_object() {
    frames_.pop_back();
    return true;
  }
  bool start_array(std::size_t) {
    value();
    frames_.push_back({true, "", -1, {}});
    return true;
  }
  bool end_array() {
    frames_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string& last_token, const Json::exception&) {
    return stop(last_token);
  }

 private:
  struct Frame {
    bool array;
    std::string key;
    long index;
    std::set<std::string> keys;  ///< an object's keys so far
  };
  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }
  bool stop(const std::string& at) {
    value();  // the value being read when the parse stopped
    for (const Frame& f : frames_) {
      pointer += '/';
      pointer += f.array ? std::to_string(f.index) : pointer_token(f.key);
    }
    token = at;
    return false;
  }
  std::vector<Frame> frames_;
};

}  // namespace

InputError::InputError(std::vector<std::string> problems)
    : std::runtime_error(join_problems(problems)), problems_(std::move(problems)) {}

std::string pointer_token(std::string_view key) {
  std::string token;
  token.reserve(key.size());
  for (const char c : key) {
    if (c == '~') {
      token += "~0";
    } else if (c == '/') {
      token += "~1";
    } else {
      token += c;
    }
  }
  return token;
}

void InputProblems::add(std::string_view key_path, std::string_view message) {
  std::string where = key_path.empty() ? "/" : std::string(key_path);
  problems_.push_back(file_ + ": " + where + ": " + std::string(message));
}

void InputProblems::warn(std::string_view key_path, std::string_view message) {
  std::string where = key_path.empty() ? "/" : std::string(key_path);
  warnings_.push_back(file_ + ": " + where + ": " + std::string(message));
}

void InputProblems::add_at_line(int line, std::string_view message) {
  problems_.push_back(line_location(line) + ": " + std::string(message));
}

std::string InputProblems::line_location(int line) const {
  return line > 0 ? file_ + ":" + std::to_string(line) : file_;
}

void InputProblems::check_units(std::string_view key_path, Quantity q, double value) {
  if (auto hint = unit_hint(q, value)) warn(key_path, *hint + "; the value is used as given");
}

void InputProblems::add_nested(std::string_view key_path, std::string_view prefix,
                               const InputError& error) {
  static constexpr std::string_view kWarning = "warning: ";
  for (const auto& p : error.problems()) {
    if (p.rfind(kWarning, 0) == 0) {
      warn(key_path, std::string(prefix) + p.substr(kWarning.size()));
    } else {
      add(key_path, std::string(prefix) + p);
    }
  }
}

void InputProblems::warn_nested(std::string_view key_path, std::string_view prefix,
                                const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) warn(key_path, std::string(prefix) + w);
}

void InputProblems::throw_if_any() const {
  if (problems_.empty()) return;
  // The warnings go with the problems: a unit slip often explains an error elsewhere.
  std::vector<std::string> all = problems_;
  for (const auto& w : warnings_) all.push_back("warning: " + w);
  throw InputError(all);
}

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  const bool above = min_open ? v > min : v >= min;
  const bool below = max_open ? v < max : v <= max;
  return above && below;
}

std::string Range::describe() const {
  const auto bound = [](double v) {
    if (std::isinf(v)) return std::string(v > 0 ? "inf" : "-inf");
    return format_number(v);
  };
  return std::string(min_open || std::isinf(min) ? "(" : "[") + bound(min) + ", " + bound(max) +
         (max_open || std::isinf(max) ? ")" : "]");
}

const Json& empty_json_object() {
  static const Json empty = Json::object();
  return empty;
}

JsonReader::JsonReader(const Json& node, std::string path, InputProblems& problems)
    : node_(&node), path_(std::move(path)), problems_(&problems) {}

const Json* JsonReader::find(std::string_view key) {
  used_.insert(std::string(key));
  if (!node_->is_object()) return nullptr;
  const auto it = node_->find(std::string(key));
  return it == node_->end() ? nullptr : &*it;
}

void JsonReader::record(std::string_view key, std::string_view type, const Range* range,
                        std::optional<std::string_view> default_value,
                        std::string_view meaning) const {
  InputKeyRecorder* keys = problems_->key_recorder();
  if (keys == nullptr) return;
  std::optional<std::string> fallback;
  if (default_value) fallback = std::string(*default_value);
  keys->record(key_path(key), {std::string(type), range ? range->describe() : std::string(),
                               std::move(fallback), std::string(meaning)});
}

void JsonReader::record_number(std::string_view key, const Range& range,
                               std::optional<double> fallback, std::string_view meaning) const {
  if (problems_->key_recorder() == nullptr) return;
  const std::string text = fallback ? format_number(*fallback) : std::string();
  record(key, "number", &range, fallback ? std::optional<std::string_view>(text) : std::nullopt,
         meaning);
}

bool JsonReader::has(std::string_view key) const {
  return node_->is_object() && node_->contains(std::string(key));
}

double JsonReader::number(std::string_view key, Range range, std::string_view meaning) {
  return read_number(key, range, meaning, std::nullopt);
}

double JsonReader::quantity(std::string_view key, Quantity q, Range range,
                            std::string_view meaning) {
  return read_number(key, range, meaning, q);
}

double JsonReader::quantity_or(std::string_view key, double fallback, Quantity q, Range range,
                               std::string_view meaning) {
  record_number(key, range, fallback, meaning);
  if (!has(key)) {
    used_.insert(std::string(key));
    return fallback;
  }
  return quantity(key, q, range, meaning);
}

double JsonReader::read_number(std::string_view key, Range range, std::string_view meaning,
                               std::optional<Quantity> q) {
  record_number(key, range, std::nullopt, meaning);
  const Json* v = find(key);
  if (v == nullptr) {
    problems_->add(key_path(key),
                   with_meaning("missing required number in " + range.describe(), meaning));
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (!v->is_number()) {
    problems_->add(key_path(key), with_meaning("expected a number in " + range.describe() +
                                                   ", got " + json_type_name(*v),
                                               meaning));
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double x = v->get<double>();
  if (!range.contains(x)) {
    std::string message = with_meaning(
        "expected a number in " + range.describe() + ", got " + exact_number(x), meaning);
    if (q) {
      if (auto hint = unit_hint(*q, x)) message += ": " + *hint;
    }
    problems_->add(key_path(key), message);
  } else if (q) {
    problems_->check_units(key_path(key), *q, x);
  }
  return x;
}

double JsonReader::number_or(std::string_view key, double fallback, Range range,
                             std::string_view meaning) {
  record_number(key, range, fallback, meaning);
  if (!has(key)) {
    used_.insert(std::string(key));
    return fallback;
  }
  return number(key, range, meaning);
}

bool JsonReader::boolean_or(std::string_view key, bool fallback, std::string_view meaning) {
  record(key, "boolean", nullptr, fallback ? "true" : "false", meaning);
  const Json* v = find(key);
  if (v == nullptr) return fallback;
  if (!v->is_boolean()) {
    problems_->add(key_path(key),
                   with_meaning("expected true or false, got " + json_type_name(*v), meaning));
    return fallback;
  }
  return v->get<bool>();
}

std::string JsonReader::string(std::string_view key, std::string_view meaning) {
  record(key, "string", nullptr, std::nullopt, meaning);
  const Json* v = find(key);
  if (v == nullptr) {
    problems_->add(key_path(key), with_meaning("missing required string", meaning));
    return {};
  }
  if (!v->is_string()) {
    problems_->add(key_path(key),
                   with_meaning("expected a string, got " + json_type_name(*v), meaning));
    return {};
  }
  return v->get<std::string>();
}

std::string JsonReader::string_or(std::string_view key, std::string_view fallback,
                                  std::string_view meaning) {
  record(key, "string", nullptr, fallback, meaning);
  if (!has(key)) {
    used_.insert(std::string(key));
    return std::string(fallback);
  }
  return string(key, meaning);
}

std::string JsonReader::choice(std::string_view key, std::initializer_list<std::string_view> known,
                               std::string_view meaning, std::optional<std::string_view> fallback) {
  return choice(key, std::vector<std::string_view>(known), meaning, fallback);
}

std::string JsonReader::choice(std::string_view key, const std::vector<std::string_view>& known,
                               std::string_view meaning, std::optional<std::string_view> fallback) {
  std::string known_list;
  std::vector<std::string> candidates;
  for (auto k : known) {
    known_list += (known_list.empty() ? "" : ", ") + std::string(k);
    candidates.emplace_back(k);
  }
  if (problems_->key_recorder() != nullptr)
    record(key, "one of: " + known_list, nullptr, fallback, meaning);
  if (!has(key) && fallback) {
    used_.insert(std::string(key));
    return std::string(*fallback);
  }
  if (!has(key)) {
    used_.insert(std::string(key));
    problems_->add(key_path(key), with_meaning("missing; expected one of: " + known_list, meaning));
    return {};
  }
  const bool valid_string = has(key) && (*node_)[std::string(key)].is_string();
  const std::string value = string(key, meaning);  // reports a missing key or a wrong type
  if (!valid_string) return fallback ? std::string(*fallback) : std::string();
  if (std::find(candidates.begin(), candidates.end(), value) == candidates.end()) {
    std::string message = "unknown name \"" + value + "\"; known: " + known_list;
    if (auto near = nearest_name(value, candidates)) message += " (did you mean " + *near + "?)";
    problems_->add(key_path(key), with_meaning(message, meaning));
    return fallback ? std::string(*fallback) : std::string();
  }
  return value;
}

JsonReader JsonReader::child(std::string_view key, std::string_view meaning) {
  record(key, "object", nullptr, std::nullopt, meaning);
  const Json* v = find(key);
  if (v == nullptr) {
    problems_->add(key_path(key), with_meaning("missing required object", meaning));
    return JsonReader(empty_json_object(), key_path(key), *problems_);
  }
  if (!v->is_object()) {
    problems_->add(key_path(key),
                   with_meaning("expected an object, got " + json_type_name(*v), meaning));
    return JsonReader(empty_json_object(), key_path(key), *problems_);
  }
  return JsonReader(*v, key_path(key), *problems_);
}

std::optional<JsonReader> JsonReader::optional_child(std::string_view key,
                                                     std::string_view meaning) {
  record(key, "object", nullptr, "", meaning);
  if (!has(key)) {
    used_.insert(std::string(key));
    return std::nullopt;
  }
  return child(key, meaning);
}

void JsonReader::ignore(std::string_view key) {
  used_.insert(std::string(key));
}

// An unknown key with no near name lists the keys its place reads, up to this many (an
// object's handful; the root of a scene reads more, and a long list would bury the message).
constexpr std::size_t kListedKnownKeys = 12;

void JsonReader::reject_unknown_keys() {
  if (!node_->is_object()) return;
  std::vector<std::string> known(used_.begin(), used_.end());
  for (const auto& item : node_->items()) {
    if (used_.count(item.key()) != 0) continue;
    std::string message = "unknown key";
    if (auto near = nearest_name(item.key(), known)) {
      message += " (did you mean " + *near + "?)";
    } else if (!known.empty() && known.size() <= kListedKnownKeys) {
      // Nothing near ("x_minus" for "x-", "friction" for "mu"): the few keys this place reads.
      message += "; known here: ";
      for (std::size_t k = 0; k < known.size(); ++k) message += (k == 0 ? "" : ", ") + known[k];
    }
    problems_->add(key_path(item.key()), message);
  }
}

std::optional<std::string> not_a_regular_file(const std::string& file) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status) || std::filesystem::is_regular_file(status))
    return std::nullopt;
  if (std::filesystem::is_directory(status)) return "is a directory";
  return "is not a regular file (a FIFO, socket or device)";
}

Json load_json_file(const std::string& file) {
  // Only a regular file (or a link to one): a FIFO or a device would block the run or stream
  // forever, a directory cannot be parsed.
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw InputError({file + ": cannot open the file (does it exist, and is it readable?)"});
  if (const auto kind = not_a_regular_file(file))
    throw InputError({file + ": " + *kind + "; expected a JSON file"});
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError({file + ": cannot open the file (does it exist, and is it readable?)"});
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError({file + ": cannot read the file"});
  return parse_json_text(text.str(), file);
}

Json parse_json_text(const std::string& text, const std::string& what) {
  Json parsed;
  bool beyond = false;
  try {
    parsed = Json::parse(text, nullptr, true, /*ignore_comments=*/false);
  } catch (const Json::parse_error& e) {
    throw InputError({what + ": JSON syntax error at byte " + std::to_string(e.byte) + ": " +
                      std::string(e.what())});
  } catch (const Json::out_of_range&) {  // a number beyond the double range (1e999)
    beyond = true;
  }
  // Parsed again, without building it: a key written twice, or where the number is.
  NumberLocator locator;
  Json::sax_parse(text, &locator);
  if (locator.duplicate)
    throw InputError({what + ": " + locator.pointer + ": the key " + locator.token +
                      " appears twice in its object (JSON would keep only the last); write it "
                      "once"});
  if (!beyond && !locator.underflow) return parsed;
  std::string number = locator.token;
  if (number.size() > 32)
    number = number.substr(0, 16) + "... (" + std::to_string(number.size()) + " characters)";
  throw InputError({what + ": " + (locator.pointer.empty() ? "/" : locator.pointer) +
                    ": the number " + (number.empty() ? "" : number + " ") +
                    (locator.underflow ? "is below the range of a double (magnitude at least "
                                         "4.9e-324) and would read as 0; write 0 if 0 is meant"
                                       : "is beyond the range of a double (magnitude at most "
                                         "1.8e308)")});
}

std::optional<std::string> nearest_name(std::string_view word,
                                        const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

}  // namespace impact
