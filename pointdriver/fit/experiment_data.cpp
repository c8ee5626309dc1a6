#include "pointdriver/fit/experiment_data.hpp"
#include "pointdriver/fit/byte_order_mark.hpp"
#include "pointdriver/format/text_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <span>
#include <sstream>

namespace impact::pointdriver::fit {

std::string to_string(TestType t) {
  return t == TestType::uniaxial_tension ? "uniaxial_tension" : "uniaxial_compression";
}
std::string to_string(StrainMeasure m) {
  switch (m) {
    case StrainMeasure::true_plastic:
      return "true_plastic";
    case StrainMeasure::true_total:
      return "true_total";
    case StrainMeasure::engineering_total:
      return "engineering_total";
  }
  return "?";
}
std::string to_string(StressMeasure m) {
  return m == StressMeasure::engineering ? "engineering" : "true";
}
std::string to_string(ThermalMode m) {
  switch (m) {
    case ThermalMode::automatic:
      return "automatic";
    case ThermalMode::isothermal:
      return "isothermal";
    case ThermalMode::adiabatic:
      return "adiabatic";
  }
  return "?";
}

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string fmt(double v) {
  return format_number(v);
}

/// Collects problems as "file:line: message" and throws them together.
class Problems {
 public:
  explicit Problems(std::string file) : file_(std::move(file)) {}
  void add(int line, const std::string& message) {
    problems_.push_back(file_ + (line > 0 ? ":" + std::to_string(line) : "") + ": " + message);
  }
  void throw_if_any() const {
    if (!problems_.empty()) throw InputError(problems_);
  }
  bool empty() const { return problems_.empty(); }

 private:
  std::string file_;
  std::vector<std::string> problems_;
};

/// A header key with its unit, e.g. {"strain_rate", "1/s"}; the unit the format requires.
struct KeySpec {
  const char* name;
  const char* unit;  ///< "" for a key without a unit
};
constexpr KeySpec kKeys[] = {{"test_type", ""},      {"strain_rate", "1/s"},   {"temperature", "K"},
                             {"strain_measure", ""}, {"stress_measure", ""},   {"source", ""},
                             {"converted_from", ""}, {"conversion", ""},       {"thermal", ""},
                             {"weight", ""},         {"youngs_modulus", "Pa"}, {"description", ""}};

/// A declared unit the reader converts to SI: value_SI = scale * value + offset.
struct UnitConversion {
  const char* unit;
  double scale;
  double offset = 0.0;
};
/// The units labs write, per quantity; the first is the SI unit (no conversion).
constexpr UnitConversion kStressUnits[] = {{"Pa", 1.0},
                                           {"kPa", 1e3},
                                           {"MPa", 1e6},
                                           {"GPa", 1e9},
                                           {"psi", 6894.757293168361},
                                           {"ksi", 6894757.293168361}};
constexpr UnitConversion kStrainUnits[] = {{"-", 1.0}, {"%", 0.01}};
constexpr UnitConversion kTemperatureUnits[] = {
    {"K", 1.0}, {"degC", 1.0, 273.15}, {"C", 1.0, 273.15}};

/// The units a header key may be declared in (SI first); empty for a key without a unit.
std::span<const UnitConversion> units_of(std::string_view key) {
  if (key == "temperature") return kTemperatureUnits;
  if (key == "youngs_modulus") return {kStressUnits, 4};  // Pa .. GPa
  return {};
}

const UnitConversion* find_unit(std::span<const UnitConversion> units, std::string_view unit) {
  for (const UnitConversion& u : units)
    if (unit == u.unit) return &u;
  return nullptr;
}

std::string unit_list(std::span<const UnitConversion> units) {
  std::string out;
  for (const UnitConversion& u : units) out += (out.empty() ? "" : ", ") + std::string(u.unit);
  return out;
}

bool parse_number(const std::string& text, double& value) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  char* end = nullptr;
  value = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

/// The cells of a CSV line; empty cells are kept ("0.1," has two cells, the second empty).
std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  for (char c : line) {
    if (c == ',')
      cells.emplace_back();
    else
      cells.back() += c;
  }
  return cells;
}

/// "name [unit]" -> (name, unit); no brackets: unit "".
std::pair<std::string, std::string> split_unit(const std::string& cell) {
  static const std::regex re(R"(^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\[([^\]]*)\])?\s*$)");
  std::smatch m;
  const std::string c = trim(cell);
  if (std::regex_match(c, m, re)) return {m[1].str(), m[2].matched ? trim(m[2].str()) : ""};
  return {c, ""};
}

}  // namespace

Experiment parse_experiment(std::istream& in, const std::string& file,
                            std::optional<double> youngs_modulus) {
  Problems problems(file);
  Experiment e;
  e.file = file;
  e.name = std::filesystem::path(file).stem().string();

  std::map<std::string, std::pair<std::string, int>> header;  // key -> (value, line)
  std::map<std::string, const UnitConversion*> declared;      // key -> its converted unit
  static const std::regex key_re(R"(^([a-z_]+)\s*(?:\[([^\]]*)\])?\s*:(.*)$)");
  std::string line;
  int number = 0;
  int column_line = 0;
  std::vector<std::string> column_cells;
  int data_rows = 0;
  std::array<std::vector<int>, 2> empty_cells;  // lines with an empty cell, per column
  // The column's name in the column header; column_name: "2 (true_stress [Pa])".
  const auto column_label = [&](int c) {
    return c < static_cast<int>(column_cells.size()) ? trim(column_cells[c])
                                                     : std::string(c == 0 ? "strain" : "stress");
  };
  const auto column_name = [&](int c) {
    return std::to_string(c + 1) + " (" + column_label(c) + ")";
  };
  struct Point {
    double strain, stress;
    int line;
  };
  std::vector<Point> points;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) {
      if (const auto wrong = strip_byte_order_mark(line)) {
        problems.add(1, *wrong);
        problems.throw_if_any();  // the rest would be a misleading error per line
      }
    }
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t.front() == '#') {
      if (column_line) {
        continue;  // comments among the data are allowed
      }
      const std::string body = trim(t.substr(1));
      std::smatch m;
      if (!std::regex_match(body, m, key_re)) continue;  // free-text comment
      const std::string key = m[1].str();
      const std::string unit = m[2].matched ? trim(m[2].str()) : "";
      const auto spec = std::find_if(std::begin(kKeys), std::end(kKeys),
                                     [&](const KeySpec& k) { return key == k.name; });
      if (spec == std::end(kKeys)) {
        std::vector<std::string> names;
        for (const auto& k : kKeys) names.emplace_back(k.name);
        const auto near = nearest_name(key, names);
        problems.add(number, "unknown header key '" + key + "'" +
                                 (near ? " (did you mean " + *near + "?)" : ""));
        continue;
      }
      if (const UnitConversion* u = find_unit(units_of(key), unit); u && unit != spec->unit) {
        declared[key] = u;  // a unit labs use: converted to SI below
      } else if (unit != spec->unit) {
        const std::string want =
            std::string(spec->unit).empty()
                ? "without a unit"
                : "'" + key + " [" + spec->unit + "]' (SI" +
                      (units_of(key).empty() ? "" : "; or " + unit_list(units_of(key))) + ")";
        problems.add(number, unit.empty() ? "header key '" + key + "' has no unit: write it " + want
                                          : "header key '" + key + "' must be written " + want +
                                                ", got [" + unit + "]");
        // Kept, so that the key is not also reported missing.
        if (!header.count(key)) header[key] = {trim(m[3].str()), number};
        continue;
      }
      if (header.count(key)) {
        problems.add(number, "header key '" + key + "' given twice (first on line " +
                                 std::to_string(header[key].second) + ")");
        continue;
      }
      header[key] = {trim(m[3].str()), number};
      continue;
    }
    if (!column_line) {
      column_line = number;
      column_cells = split_cells(t);
      continue;
    }
    // Data row: every cell is named by its line and its column (the header's name for it).
    ++data_rows;
    const std::vector<std::string> cells = split_cells(t);
    if (cells.size() != 2) {
      problems.add(number, std::string(cells.size() < 2 ? "short" : "long") +
                               " row: expected 2 values (" + column_label(0) + ", " +
                               column_label(1) + "), got " + std::to_string(cells.size()) + ": '" +
                               t + "'");
      continue;
    }
    Point p{0, 0, number};
    double* values[2] = {&p.strain, &p.stress};
    bool ok = true;
    for (int c = 0; c < 2; ++c) {
      const std::string cell = trim(cells[c]);
      if (cell.empty()) {
        empty_cells[c].push_back(number);
        ok = false;
      } else if (!parse_number(cell, *values[c])) {
        problems.add(number, "column " + column_name(c) + ": not a number: '" + cell + "'");
        ok = false;
      } else if (!std::isfinite(*values[c])) {
        problems.add(
            number, "column " + column_name(c) + ": non-finite value (NaN or Inf): '" + cell + "'");
        ok = false;
      }
    }
    if (ok) points.push_back(p);
  }
  // Empty cells: one problem for a column that is empty on every row, else one per cell.
  for (int c = 0; c < 2; ++c) {
    if (data_rows > 1 && static_cast<int>(empty_cells[c].size()) == data_rows) {
      problems.add(column_line, "column " + column_name(c) + " is empty (no value on any of the " +
                                    std::to_string(data_rows) + " data rows)");
      continue;
    }
    for (int l : empty_cells[c]) problems.add(l, "column " + column_name(c) + ": empty cell");
  }

  // Header values.
  auto value = [&](const std::string& key, bool required) -> std::optional<std::string> {
    const auto it = header.find(key);
    if (it != header.end()) return it->second.first;
    if (required) {
      const auto spec = std::find_if(std::begin(kKeys), std::end(kKeys),
                                     [&](const KeySpec& k) { return key == k.name; });
      const std::string unit =
          std::string(spec->unit).empty() ? "" : std::string(" [") + spec->unit + "]";
      problems.add(0, "missing header line '# " + key + unit + ": ...'");
    }
    return std::nullopt;
  };
  auto line_of = [&](const std::string& key) {
    const auto it = header.find(key);
    return it == header.end() ? 0 : it->second.second;
  };
  auto choice = [&](const std::string& key, const std::vector<std::string>& known,
                    bool required) -> int {
    const auto v = value(key, required);
    if (!v) return -1;
    for (std::size_t i = 0; i < known.size(); ++i)
      if (*v == known[i]) return static_cast<int>(i);
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    problems.add(line_of(key), key + ": expected one of " + list + ", got '" + *v + "'");
    return -1;
  };
  auto number_of = [&](const std::string& key, bool required) -> std::optional<double> {
    const auto v = value(key, required);
    if (!v) return std::nullopt;
    double x = 0;
    if (!parse_number(*v, x) || !std::isfinite(x)) {
      problems.add(line_of(key), key + ": expected a number, got '" + *v + "'");
      return std::nullopt;
    }
    if (const auto d = declared.find(key); d != declared.end()) {
      const UnitConversion& u = *d->second;
      const double si = u.scale * x + u.offset;
      e.conversions.push_back(key + " " + fmt(x) + " " + u.unit + " -> " + fmt(si) + " " +
                              units_of(key).front().unit);
      return si;
    }
    return x;
  };

  if (const int c = choice("test_type", {"uniaxial_compression", "uniaxial_tension"}, true); c >= 0)
    e.type = static_cast<TestType>(c);
  if (const int c =
          choice("strain_measure", {"true_plastic", "true_total", "engineering_total"}, true);
      c >= 0)
    e.strain_measure = static_cast<StrainMeasure>(c);
  if (const int c = choice("stress_measure", {"true", "engineering"}, true); c >= 0)
    e.stress_measure = static_cast<StressMeasure>(c);
  if (const int c = choice("thermal", {"automatic", "isothermal", "adiabatic"}, false); c >= 0)
    e.thermal = static_cast<ThermalMode>(c);
  if (const auto v = value("source", true)) e.source = *v;
  if (const auto v = value("converted_from", false)) e.converted_from = *v;
  if (const auto rate = number_of("strain_rate", true)) {
    if (*rate <= 0)
      problems.add(line_of("strain_rate"), "strain_rate must be positive (a magnitude) [1/s]");
    e.strain_rate = *rate;
  }
  if (const auto temp = number_of("temperature", true)) {
    const auto hint = unit_hint(Quantity::temperature, *temp);
    if (*temp <= 0) {
      problems.add(line_of("temperature"),
                   "temperature must be positive [K]" + (hint ? ": " + *hint : std::string()));
    } else if (hint) {
      // A test at 4 or 20 K is real (cryogenic tests), so a low value is a warning, not an error.
      e.warnings.push_back(file + ":" + std::to_string(line_of("temperature")) + ": temperature " +
                           *hint + "; the value is used as given");
    }
    e.temperature = *temp;
  }
  if (const auto w = number_of("weight", false)) {
    if (*w <= 0) problems.add(line_of("weight"), "weight must be positive");
    e.weight = *w;
  }
  if (const auto E = number_of("youngs_modulus", false)) {
    if (*E < 1e8) {
      const auto hint = unit_hint(Quantity::elastic_modulus, *E);
      problems.add(line_of("youngs_modulus"),
                   "youngs_modulus " + fmt(*E) + " is below 1e8 Pa: " +
                       (hint ? *hint : "it looks like MPa or GPa; the format takes Pa"));
    }
    e.youngs_modulus = *E;
  }

  // Columns.
  const char* strain_column[] = {"true_plastic_strain", "true_strain", "engineering_strain"};
  const char* stress_column[] = {"true_stress", "engineering_stress"};
  const UnitConversion* strain_unit = nullptr;
  const UnitConversion* stress_unit = nullptr;
  if (!column_line) {
    problems.add(0, "no column header line (e.g. 'true_plastic_strain [-],true_stress [Pa]')");
  } else if (column_cells.size() != 2) {
    problems.add(column_line,
                 "expected 2 columns (strain, stress), got " + std::to_string(column_cells.size()));
  } else {
    const auto [sname, sunit] = split_unit(column_cells[0]);
    const auto [tname, tunit] = split_unit(column_cells[1]);
    const std::string want_strain = strain_column[static_cast<int>(e.strain_measure)];
    const std::string want_stress = stress_column[static_cast<int>(e.stress_measure)];
    if (sname != want_strain)
      problems.add(column_line, "first column must be '" + want_strain + " [-]' (strain_measure " +
                                    to_string(e.strain_measure) + "), got '" +
                                    trim(column_cells[0]) + "'");
    else if (sunit.empty())
      problems.add(column_line, "column 1 '" + sname + "' has no unit: write '" + want_strain +
                                    " [-]' (a fraction)");
    else if (!(strain_unit = find_unit(kStrainUnits, sunit)))
      problems.add(column_line, "strain must be a fraction '" + want_strain + " [-]' or in " +
                                    "percent '" + want_strain + " [%]', got [" + sunit + "]");
    if (tname != want_stress)
      problems.add(column_line, "second column must be '" + want_stress +
                                    " [Pa]' (stress_measure " + to_string(e.stress_measure) +
                                    "), got '" + trim(column_cells[1]) + "'");
    else if (tunit.empty())
      problems.add(column_line,
                   "column 2 '" + tname + "' has no unit: write '" + want_stress + " [Pa]' (SI)");
    else if (!(stress_unit = find_unit(kStressUnits, tunit)))
      problems.add(column_line, "stress unit [" + tunit + "] unknown: write '" + want_stress +
                                    " [Pa]' (SI) or one of " + unit_list(kStressUnits));
  }
  // Declared units other than SI: the values converted as read, and reported.
  if (strain_unit && strain_unit->scale != 1.0) {
    for (Point& p : points) p.strain *= strain_unit->scale;
    e.conversions.push_back(std::string("strain column in ") + strain_unit->unit +
                            " -> fraction (x " + fmt(strain_unit->scale) + ")");
  }
  if (stress_unit && stress_unit->scale != 1.0) {
    for (Point& p : points) p.stress *= stress_unit->scale;
    e.conversions.push_back(std::string("stress column in ") + stress_unit->unit + " -> Pa (x " +
                            fmt(stress_unit->scale) + ")");
  }

  // Data rows.
  if (data_rows == 0 && column_line) problems.add(0, "no data rows (empty curve)");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (p.stress <= 0)
      problems.add(
          p.line, "stress " + fmt(p.stress) + " is not positive (give compression as a magnitude)");
    if (p.strain < 0) problems.add(p.line, "strain " + fmt(p.strain) + " is negative");
    if (i > 0 && p.strain <= points[i - 1].strain)
      problems.add(p.line, "strain " + fmt(p.strain) + " does not increase (line " +
                               std::to_string(points[i - 1].line) + " has " +
                               fmt(points[i - 1].strain) + "): strain must increase strictly");
  }
  if (!points.empty()) {
    const auto smax = std::max_element(points.begin(), points.end(),
                                       [](auto& a, auto& b) { return a.stress < b.stress; });
    const auto emax = std::max_element(points.begin(), points.end(),
                                       [](auto& a, auto& b) { return a.strain < b.strain; });
    if (smax->stress < 1e5)
      problems.add(smax->line, "the largest stress is " + fmt(smax->stress) +
                                   " Pa: the values look like MPa; the format takes Pa "
                                   "(multiply by 1e6)");
    else if (smax->stress > 1e11)
      problems.add(smax->line, "the largest stress is " + fmt(smax->stress) +
                                   " Pa (over 100 GPa): wrong unit?");
    if (emax->strain > 2.0)
      problems.add(emax->line, "the largest strain is " + fmt(emax->strain) +
                                   ": it looks like percent; the format takes a fraction [-]");
  }
  const bool needs_modulus = e.strain_measure != StrainMeasure::true_plastic;
  const std::optional<double> E = e.youngs_modulus ? e.youngs_modulus : youngs_modulus;
  if (needs_modulus && !E)
    problems.add(line_of("strain_measure"),
                 "a total-strain curve needs Young's modulus to remove the elastic strain: add "
                 "'# youngs_modulus [Pa]: ...' or fit with a material");
  problems.throw_if_any();

  // Conversions to true plastic strain and true stress.
  const bool tension = e.type == TestType::uniaxial_tension;
  std::vector<double> eps, sig, eng_stress;
  for (const Point& p : points) {
    double strain = p.strain, stress = p.stress;
    eng_stress.push_back(p.stress);
    if (e.strain_measure == StrainMeasure::engineering_total) {
      if (!tension && p.strain >= 1.0) {
        Problems q(file);
        q.add(p.line, "engineering compressive strain " + fmt(p.strain) + " must be below 1");
        q.throw_if_any();
      }
      strain = tension ? std::log1p(p.strain) : -std::log1p(-p.strain);
      if (e.stress_measure == StressMeasure::engineering)
        stress = tension ? p.stress * (1.0 + p.strain) : p.stress * (1.0 - p.strain);
    } else if (e.stress_measure == StressMeasure::engineering) {
      // Engineering stress with a true strain: the engineering strain is exp(eps) - 1.
      const double eng = tension ? std::expm1(p.strain) : -std::expm1(-p.strain);
      stress = tension ? p.stress * (1.0 + eng) : p.stress * (1.0 - eng);
    }
    eps.push_back(strain);
    sig.push_back(stress);
  }
  if (e.strain_measure == StrainMeasure::engineering_total)
    e.conversions.push_back(tension ? "engineering -> true strain: eps = ln(1 + e)"
                                    : "engineering -> true strain: eps = -ln(1 - e)");
  if (e.stress_measure == StressMeasure::engineering)
    e.conversions.push_back(tension ? "engineering -> true stress: sigma = s (1 + e)"
                                    : "engineering -> true stress: sigma = s (1 - e)");
  std::size_t end = eps.size();
  if (tension) {
    const auto& criterion = e.stress_measure == StressMeasure::engineering ? eng_stress : sig;
    const std::size_t imax = static_cast<std::size_t>(
        std::max_element(criterion.begin(), criterion.end()) - criterion.begin());
    if (imax + 1 < end) {
      e.conversions.push_back(
          "tension: stopped at the maximum " +
          std::string(e.stress_measure == StressMeasure::engineering ? "engineering" : "true") +
          " stress (necking), line " + std::to_string(points[imax].line) + "; " +
          std::to_string(end - imax - 1) + " points dropped");
      end = imax + 1;
    }
  }
  int elastic = 0, not_increasing = 0;
  for (std::size_t i = 0; i < end; ++i) {
    double ep = eps[i];
    if (needs_modulus) ep -= sig[i] / *E;
    if (ep <= 0) {
      ++elastic;
      continue;
    }
    if (!e.plastic_strain.empty() && ep <= e.plastic_strain.back()) {
      ++not_increasing;
      continue;
    }
    e.plastic_strain.push_back(ep);
    e.stress.push_back(sig[i]);
  }
  if (needs_modulus)
    e.conversions.push_back("total -> plastic strain: eps_p = eps - sigma / E, E = " + fmt(*E) +
                            " Pa");
  if (elastic)
    e.conversions.push_back(std::to_string(elastic) +
                            " points with plastic strain <= 0 dropped (elastic part)");
  if (not_increasing)
    e.conversions.push_back(std::to_string(not_increasing) +
                            " points dropped: plastic strain not increasing after removing the "
                            "elastic strain");
  if (e.plastic_strain.size() < 2) {
    Problems q(file);
    q.add(0, "fewer than 2 points with positive plastic strain remain (" +
                 std::to_string(e.plastic_strain.size()) + ")");
    q.throw_if_any();
  }
  return e;
}

Experiment read_experiment(const std::string& file, std::optional<double> youngs_modulus) {
  std::ifstream in(file);
  if (!in) throw InputError({file + ": cannot open the experiment file"});
  return parse_experiment(in, file, youngs_modulus);
}

}  // namespace impact::pointdriver::fit
