// The key tables of the docs (docs/scenes.md, docs/models.md) read back for the tests that check
// them against the readers' recorded keys (mpm_scene_keys_test,
// models_material_material_keys_test): Markdown cells, backticked names, stated defaults and
// intervals.
#pragma once

#include <cmath>
#include <cstdlib>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace impact::test {

inline std::string trim(std::string s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

/// The cells of a Markdown table row (an escaped \| stays inside its cell).
inline std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (row[i] == '|') {
      out.push_back(trim(cell));
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return out;
}

/// The `backticked` words of a text.
inline std::vector<std::string> backticked(const std::string& text) {
  std::vector<std::string> out;
  static const std::regex code("`([^`]+)`");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), code); it != std::sregex_iterator();
       ++it)
    out.push_back((*it)[1]);
  return out;
}

/// The value a default column states: its first `code` span, else its text up to " (" or ";".
inline std::string stated_default(const std::string& text) {
  if (text.rfind('`', 0) == 0) return backticked(text).front();
  return trim(text.substr(0, std::min(text.find(" ("), text.find(';'))));
}

inline std::optional<double> number_of(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return *end == '\0' ? std::optional<double>(v) : std::nullopt;
}

/// An interval: bounds and whether each end is open.
struct Interval {
  double min, max;
  bool min_open, max_open;
  bool operator==(const Interval& o) const {
    // An infinite end is open whatever the notation.
    const auto same_end = [](double a, bool ao, double b, bool bo) {
      return a == b && (std::isinf(a) || ao == bo);
    };
    return same_end(min, min_open, o.min, o.min_open) && same_end(max, max_open, o.max, o.max_open);
  }
};

inline std::string text_of(const Interval& i) {
  std::ostringstream o;
  o << (i.min_open ? '(' : '[') << i.min << ", " << i.max << (i.max_open ? ')' : ']');
  return o.str();
}

/// The reader's Range::describe() text as an interval.
inline Interval reader_range(const std::string& text) {
  const auto comma = text.find(',');
  return {std::strtod(text.substr(1, comma - 1).c_str(), nullptr),
          std::strtod(text.substr(comma + 1).c_str(), nullptr), text.front() == '(',
          text.back() == ')'};
}

}  // namespace impact::test
