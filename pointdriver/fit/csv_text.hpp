// The text of the fitting tools' CSV files (experiment curves, fracture strains): a line's cells
// and a cell's number, read the same way by every reader so that "0.1,,3" means the same thing
// (three cells, the second empty) in each.
#pragma once

#include <cstdlib>
#include <string>
#include <vector>

namespace impact::pointdriver::fit {

/// `s` without the blanks around it (spaces, tabs, a CR left by a Windows line end).
inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

/// The cells of a CSV line; empty cells are kept ("0.1," has two cells, the second empty).
inline std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  for (char c : line) {
    if (c == ',')
      cells.emplace_back();
    else
      cells.back() += c;
  }
  return cells;
}

/// Whether the whole of `text` (blanks around it aside) is a number, which goes to `value`; an
/// empty text is not. NaN and Inf are numbers here: the caller says whether it takes them.
inline bool parse_number(const std::string& text, double& value) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  value = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

}  // namespace impact::pointdriver::fit
