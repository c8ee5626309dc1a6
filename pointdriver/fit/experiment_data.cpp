#include "pointdriver/fit/experiment_data.hpp"
#include "pointdriver/fit/byte_order_mark.hpp"
#include "pointdriver/fit/csv_text.hpp"
#include "pointdriver/format/text_format.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <span>

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

std::string fmt(double v) {
  return format_number(v);
}

/// A header key with its unit, e.g. {"strain_rate", "1/s"}; the unit the format requires.
struct KeySpec {
  const char* name;
  const char* unit;  ///< "" for a key without a unit
};
constexpr KeySpec kKeys[] = {{"test_type", ""},      {"strain_rate", "1/s"},   {"temperature", "K"},
                             {"strain_measure", ""}, {"stress_measure", ""},   {"source", ""},
                             {"converted_from", ""}, {"conversion", ""},       {"thermal", ""},
                             {"weight", ""},         {"youngs_modulus", "Pa"}, {"description", ""}};

const KeySpec* find_key(std::string_view key) {
  for (const KeySpec& k : kKeys)
    if (key == k.name) return &k;
  return nullptr;
}

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

/// "name [unit]" -> (name, unit); no brackets: unit "".
std::pair<std::string, std::string> split_unit(const std::string& cell) {
  static const std::regex re(R"(^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\[([^\]]*)\])?\s*$)");
  std::smatch m;
  const std::string c = trim(cell);
  if (std::regex_match(c, m, re)) return {m[1].str(), m[2].matched ? trim(m[2].str()) : ""};
  return {c, ""};
}

/// One measured point as read (in the file's units), with its line for messages.
struct Point {
  double strain, stress;
  int line;
};

/// What the lines of a file say, before any check that needs more than one line: the header
/// keys, the column header and the data points.
struct ExperimentText {
  struct HeaderValue {
    std::string value;
    int line;
  };
  std::map<std::string, HeaderValue> header;
  std::map<std::string, const UnitConversion*> declared;  ///< key -> its unit, converted to SI
  int column_line = 0;                                    ///< 0: no column header (yet)
  std::vector<std::string> column_cells;
  int data_rows = 0;
  std::array<std::vector<int>, 2> empty_cells;  ///< lines with an empty cell, per column
  std::vector<Point> points;                    ///< the rows whose two cells are numbers

  /// The column's name in the column header ("true_stress [Pa]"), else "strain" or "stress".
  std::string column_label(int c) const {
    return c < static_cast<int>(column_cells.size()) ? trim(column_cells[c])
                                                     : std::string(c == 0 ? "strain" : "stress");
  }
  /// "2 (true_stress [Pa])": how a problem names a column.
  std::string column_name(int c) const {
    return std::to_string(c + 1) + " (" + column_label(c) + ")";
  }
};

/// A "# key [unit]: value" line of the header (`body` without the '#'); other comments are free
/// text. Unknown keys, units the format does not take and keys given twice are problems.
void read_header_line(const std::string& body, int line, ExperimentText& text,
                      InputProblems& problems) {
  static const std::regex key_re(R"(^([a-z_]+)\s*(?:\[([^\]]*)\])?\s*:(.*)$)");
  std::smatch m;
  if (!std::regex_match(body, m, key_re)) return;  // free-text comment
  const std::string key = m[1].str();
  const std::string unit = m[2].matched ? trim(m[2].str()) : "";
  const KeySpec* spec = find_key(key);
  if (spec == nullptr) {
    std::vector<std::string> names;
    for (const auto& k : kKeys) names.emplace_back(k.name);
    const auto near = nearest_name(key, names);
    problems.add_at_line(
        line, "unknown header key '" + key + "'" + (near ? " (did you mean " + *near + "?)" : ""));
    return;
  }
  auto& header = text.header;
  if (const UnitConversion* u = find_unit(units_of(key), unit); u && unit != spec->unit) {
    text.declared[key] = u;  // a unit labs use: converted to SI with the value
  } else if (unit != spec->unit) {
    const std::string want =
        std::string(spec->unit).empty()
            ? "without a unit"
            : "'" + key + " [" + spec->unit + "]' (SI" +
                  (units_of(key).empty() ? "" : "; or " + unit_list(units_of(key))) + ")";
    problems.add_at_line(
        line, unit.empty()
                  ? "header key '" + key + "' has no unit: write it " + want
                  : "header key '" + key + "' must be written " + want + ", got [" + unit + "]");
    // Kept, so that the key is not also reported missing.
    if (!header.count(key)) header[key] = {trim(m[3].str()), line};
    return;
  }
  if (header.count(key)) {
    problems.add_at_line(line, "header key '" + key + "' given twice (first on line " +
                                   std::to_string(header[key].line) + ")");
    return;
  }
  header[key] = {trim(m[3].str()), line};
}

/// A data row `t`: two cells, each a finite number, named by line and column in every problem.
/// Empty cells are only noted here (report_empty_cells words them).
void read_data_row(const std::string& t, int line, ExperimentText& text, InputProblems& problems) {
  ++text.data_rows;
  const std::vector<std::string> cells = split_cells(t);
  if (cells.size() != 2) {
    problems.add_at_line(line, std::string(cells.size() < 2 ? "short" : "long") +
                                   " row: expected 2 values (" + text.column_label(0) + ", " +
                                   text.column_label(1) + "), got " + std::to_string(cells.size()) +
                                   ": '" + t + "'");
    return;
  }
  Point p{0, 0, line};
  double* values[2] = {&p.strain, &p.stress};
  bool ok = true;
  for (int c = 0; c < 2; ++c) {
    const std::string cell = trim(cells[c]);
    if (cell.empty()) {
      text.empty_cells[c].push_back(line);
      ok = false;
    } else if (!parse_number(cell, *values[c])) {
      problems.add_at_line(line,
                           "column " + text.column_name(c) + ": not a number: '" + cell + "'");
      ok = false;
    } else if (!std::isfinite(*values[c])) {
      problems.add_at_line(line, "column " + text.column_name(c) +
                                     ": non-finite value (NaN or Inf): '" + cell + "'");
      ok = false;
    }
  }
  if (ok) text.points.push_back(p);
}

/// Every line of the file in order: the header ('#' lines before the column header), the column
/// header (the first other line), then data rows (comments among them are skipped).
ExperimentText read_lines(std::istream& in, InputProblems& problems) {
  ExperimentText text;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) {
      if (const auto wrong = strip_byte_order_mark(line)) {
        problems.add_at_line(1, *wrong);
        problems.throw_if_any();  // the rest would be a misleading error per line
      }
    }
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t.front() == '#') {
      if (!text.column_line) read_header_line(trim(t.substr(1)), number, text, problems);
      continue;  // comments among the data are allowed
    }
    if (!text.column_line) {
      text.column_line = number;
      text.column_cells = split_cells(t);
      continue;
    }
    read_data_row(t, number, text, problems);
  }
  return text;
}

/// Empty cells: one problem for a column that is empty on every row, else one per cell.
void report_empty_cells(const ExperimentText& text, InputProblems& problems) {
  for (int c = 0; c < 2; ++c) {
    if (text.data_rows > 1 && static_cast<int>(text.empty_cells[c].size()) == text.data_rows) {
      problems.add_at_line(text.column_line, "column " + text.column_name(c) +
                                                 " is empty (no value on any of the " +
                                                 std::to_string(text.data_rows) + " data rows)");
      continue;
    }
    for (int l : text.empty_cells[c])
      problems.add_at_line(l, "column " + text.column_name(c) + ": empty cell");
  }
}

/// The header's values as strings, names and numbers; a missing required key or a bad value is
/// a problem at its line, a declared non-SI unit is converted and noted in `conversions`.
class HeaderValues {
 public:
  HeaderValues(const ExperimentText& text, InputProblems& problems,
               std::vector<std::string>& conversions)
      : text_(text), problems_(problems), conversions_(conversions) {}

  std::optional<std::string> value(const std::string& key, bool required) const {
    const auto it = text_.header.find(key);
    if (it != text_.header.end()) return it->second.value;
    if (required) {
      const KeySpec* spec = find_key(key);
      const std::string unit =
          std::string(spec->unit).empty() ? "" : std::string(" [") + spec->unit + "]";
      problems_.add_at_line(0, "missing header line '# " + key + unit + ": ...'");
    }
    return std::nullopt;
  }

  int line_of(const std::string& key) const {
    const auto it = text_.header.find(key);
    return it == text_.header.end() ? 0 : it->second.line;
  }

  /// The index of the value in `known`; -1 when absent or not one of them.
  int choice(const std::string& key, const std::vector<std::string>& known, bool required) const {
    const auto v = value(key, required);
    if (!v) return -1;
    for (std::size_t i = 0; i < known.size(); ++i)
      if (*v == known[i]) return static_cast<int>(i);
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    problems_.add_at_line(line_of(key), key + ": expected one of " + list + ", got '" + *v + "'");
    return -1;
  }

  /// A finite number in SI units.
  std::optional<double> number(const std::string& key, bool required) const {
    const auto v = value(key, required);
    if (!v) return std::nullopt;
    double x = 0;
    if (!parse_number(*v, x) || !std::isfinite(x)) {
      problems_.add_at_line(line_of(key), key + ": expected a number, got '" + *v + "'");
      return std::nullopt;
    }
    if (const auto d = text_.declared.find(key); d != text_.declared.end()) {
      const UnitConversion& u = *d->second;
      const double si = u.scale * x + u.offset;
      conversions_.push_back(key + " " + fmt(x) + " " + u.unit + " -> " + fmt(si) + " " +
                             units_of(key).front().unit);
      return si;
    }
    return x;
  }

 private:
  const ExperimentText& text_;
  InputProblems& problems_;
  std::vector<std::string>& conversions_;
};

/// The header's keys into `e`, each checked (a temperature that looks like degC is a warning).
void read_header_values(const HeaderValues& header, Experiment& e, InputProblems& problems) {
  if (const int c = header.choice("test_type", {"uniaxial_compression", "uniaxial_tension"}, true);
      c >= 0)
    e.type = static_cast<TestType>(c);
  if (const int c = header.choice("strain_measure",
                                  {"true_plastic", "true_total", "engineering_total"}, true);
      c >= 0)
    e.strain_measure = static_cast<StrainMeasure>(c);
  if (const int c = header.choice("stress_measure", {"true", "engineering"}, true); c >= 0)
    e.stress_measure = static_cast<StressMeasure>(c);
  if (const int c = header.choice("thermal", {"automatic", "isothermal", "adiabatic"}, false);
      c >= 0)
    e.thermal = static_cast<ThermalMode>(c);
  if (const auto v = header.value("source", true)) e.source = *v;
  if (const auto v = header.value("converted_from", false)) e.converted_from = *v;
  if (const auto rate = header.number("strain_rate", true)) {
    if (*rate <= 0)
      problems.add_at_line(header.line_of("strain_rate"),
                           "strain_rate must be positive (a magnitude) [1/s]");
    e.strain_rate = *rate;
  }
  if (const auto temp = header.number("temperature", true)) {
    const auto hint = unit_hint(Quantity::temperature, *temp);
    const int line = header.line_of("temperature");
    if (*temp <= 0) {
      problems.add_at_line(
          line, "temperature must be positive [K]" + (hint ? ": " + *hint : std::string()));
    } else if (hint) {
      // A test at 4 or 20 K is real (cryogenic tests), so a low value is a warning, not an error.
      e.warnings.push_back(problems.line_location(line) + ": temperature " + *hint +
                           "; the value is used as given");
    }
    e.temperature = *temp;
  }
  if (const auto w = header.number("weight", false)) {
    if (*w <= 0) problems.add_at_line(header.line_of("weight"), "weight must be positive");
    e.weight = *w;
  }
  if (const auto E = header.number("youngs_modulus", false)) {
    if (*E < 1e8) {
      const auto hint = unit_hint(Quantity::elastic_modulus, *E);
      problems.add_at_line(header.line_of("youngs_modulus"),
                           "youngs_modulus " + fmt(*E) + " is below 1e8 Pa: " +
                               (hint ? *hint : "it looks like MPa or GPa; the format takes Pa"));
    }
    e.youngs_modulus = *E;
  }
}

/// The units of the two columns (nullptr where the column header is wrong).
struct ColumnUnits {
  const UnitConversion* strain = nullptr;
  const UnitConversion* stress = nullptr;
};

/// The column header: the names the header's measures call for, each with a unit the format
/// takes.
ColumnUnits read_column_header(const ExperimentText& text, const Experiment& e,
                               InputProblems& problems) {
  const char* strain_column[] = {"true_plastic_strain", "true_strain", "engineering_strain"};
  const char* stress_column[] = {"true_stress", "engineering_stress"};
  ColumnUnits units;
  const int line = text.column_line;
  if (!line) {
    problems.add_at_line(0,
                         "no column header line (e.g. 'true_plastic_strain [-],true_stress [Pa]')");
    return units;
  }
  const auto& cells = text.column_cells;
  if (cells.size() != 2) {
    problems.add_at_line(
        line, "expected 2 columns (strain, stress), got " + std::to_string(cells.size()));
    return units;
  }
  const auto [sname, sunit] = split_unit(cells[0]);
  const auto [tname, tunit] = split_unit(cells[1]);
  const std::string want_strain = strain_column[static_cast<int>(e.strain_measure)];
  const std::string want_stress = stress_column[static_cast<int>(e.stress_measure)];
  if (sname != want_strain)
    problems.add_at_line(line, "first column must be '" + want_strain + " [-]' (strain_measure " +
                                   to_string(e.strain_measure) + "), got '" + trim(cells[0]) + "'");
  else if (sunit.empty())
    problems.add_at_line(
        line, "column 1 '" + sname + "' has no unit: write '" + want_strain + " [-]' (a fraction)");
  else if (!(units.strain = find_unit(kStrainUnits, sunit)))
    problems.add_at_line(line, "strain must be a fraction '" + want_strain + " [-]' or in " +
                                   "percent '" + want_strain + " [%]', got [" + sunit + "]");
  if (tname != want_stress)
    problems.add_at_line(line, "second column must be '" + want_stress + " [Pa]' (stress_measure " +
                                   to_string(e.stress_measure) + "), got '" + trim(cells[1]) + "'");
  else if (tunit.empty())
    problems.add_at_line(
        line, "column 2 '" + tname + "' has no unit: write '" + want_stress + " [Pa]' (SI)");
  else if (!(units.stress = find_unit(kStressUnits, tunit)))
    problems.add_at_line(line, "stress unit [" + tunit + "] unknown: write '" + want_stress +
                                   " [Pa]' (SI) or one of " + unit_list(kStressUnits));
  return units;
}

/// Declared units other than SI: the values converted as read, and reported.
void convert_column_units(const ColumnUnits& units, std::vector<Point>& points,
                          std::vector<std::string>& conversions) {
  if (units.strain && units.strain->scale != 1.0) {
    for (Point& p : points) p.strain *= units.strain->scale;
    conversions.push_back(std::string("strain column in ") + units.strain->unit +
                          " -> fraction (x " + fmt(units.strain->scale) + ")");
  }
  if (units.stress && units.stress->scale != 1.0) {
    for (Point& p : points) p.stress *= units.stress->scale;
    conversions.push_back(std::string("stress column in ") + units.stress->unit + " -> Pa (x " +
                          fmt(units.stress->scale) + ")");
  }
}

/// The data in SI units: positive stress, non-negative strictly increasing strain, and
/// magnitudes that do not look like another unit.
void check_points(const ExperimentText& text, InputProblems& problems) {
  const std::vector<Point>& points = text.points;
  if (text.data_rows == 0 && text.column_line)
    problems.add_at_line(0, "no data rows (empty curve)");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (p.stress <= 0)
      problems.add_at_line(
          p.line, "stress " + fmt(p.stress) + " is not positive (give compression as a magnitude)");
    if (p.strain < 0) problems.add_at_line(p.line, "strain " + fmt(p.strain) + " is negative");
    if (i > 0 && p.strain <= points[i - 1].strain)
      problems.add_at_line(p.line, "strain " + fmt(p.strain) + " does not increase (line " +
                                       std::to_string(points[i - 1].line) + " has " +
                                       fmt(points[i - 1].strain) +
                                       "): strain must increase strictly");
  }
  if (points.empty()) return;
  const auto smax = std::max_element(points.begin(), points.end(),
                                     [](auto& a, auto& b) { return a.stress < b.stress; });
  const auto emax = std::max_element(points.begin(), points.end(),
                                     [](auto& a, auto& b) { return a.strain < b.strain; });
  if (smax->stress < 1e5)
    problems.add_at_line(smax->line, "the largest stress is " + fmt(smax->stress) +
                                         " Pa: the values look like MPa; the format takes Pa "
                                         "(multiply by 1e6)");
  else if (smax->stress > 1e11)
    problems.add_at_line(smax->line, "the largest stress is " + fmt(smax->stress) +
                                         " Pa (over 100 GPa): wrong unit?");
  if (emax->strain > 2.0)
    problems.add_at_line(emax->line,
                         "the largest strain is " + fmt(emax->strain) +
                             ": it looks like percent; the format takes a fraction [-]");
}

/// The checked points to true plastic strain and true stress (the header comment's formulas),
/// into e.plastic_strain and e.stress, each step noted in e.conversions. `E` [Pa] removes the
/// elastic strain of a total-strain curve.
void convert_to_true_plastic(const std::vector<Point>& points, std::optional<double> E,
                             Experiment& e) {
  const bool needs_modulus = e.strain_measure != StrainMeasure::true_plastic;
  const bool tension = e.type == TestType::uniaxial_tension;
  std::vector<double> eps, sig, eng_stress;
  for (const Point& p : points) {
    double strain = p.strain, stress = p.stress;
    eng_stress.push_back(p.stress);
    if (e.strain_measure == StrainMeasure::engineering_total) {
      if (!tension && p.strain >= 1.0) {
        InputProblems q(e.file);
        q.add_at_line(p.line,
                      "engineering compressive strain " + fmt(p.strain) + " must be below 1");
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
    InputProblems q(e.file);
    q.add_at_line(0, "fewer than 2 points with positive plastic strain remain (" +
                         std::to_string(e.plastic_strain.size()) + ")");
    q.throw_if_any();
  }
}

}  // namespace

// The steps in the order their problems are reported: the lines, the header's values, the
// column header, the data; all problems of the file at once, before any conversion.
Experiment parse_experiment(std::istream& in, const std::string& file,
                            std::optional<double> youngs_modulus) {
  InputProblems problems(file);
  Experiment e;
  e.file = file;
  e.name = std::filesystem::path(file).stem().string();

  ExperimentText text = read_lines(in, problems);
  report_empty_cells(text, problems);
  const HeaderValues header(text, problems, e.conversions);
  read_header_values(header, e, problems);
  convert_column_units(read_column_header(text, e, problems), text.points, e.conversions);
  check_points(text, problems);
  const bool needs_modulus = e.strain_measure != StrainMeasure::true_plastic;
  const std::optional<double> E = e.youngs_modulus ? e.youngs_modulus : youngs_modulus;
  if (needs_modulus && !E)
    problems.add_at_line(header.line_of("strain_measure"),
                         "a total-strain curve needs Young's modulus to remove the elastic "
                         "strain: add '# youngs_modulus [Pa]: ...' or fit with a material");
  problems.throw_if_any();

  convert_to_true_plastic(text.points, E, e);
  return e;
}

Experiment read_experiment(const std::string& file, std::optional<double> youngs_modulus) {
  std::ifstream in(file);
  if (!in) throw InputError({file + ": cannot open the experiment file"});
  return parse_experiment(in, file, youngs_modulus);
}

}  // namespace impact::pointdriver::fit
