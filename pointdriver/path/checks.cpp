#include "pointdriver/path/checks.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace impact::pointdriver {

namespace {

namespace fs = std::filesystem;

// A CSV file as columns by header name.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  const std::vector<double>* column(const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? nullptr : &columns[std::size_t(it - names.begin())];
  }
};

// Only the `wanted` columns are kept: a long run's CSV read back costs 8 B per row for each
// (docs/pointdriver.md, "Refused runs").
Table read_table(const std::string& file, const std::vector<std::string>& wanted) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file);
  Table t;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file + ": empty");
  std::stringstream header(line);
  for (std::string cell; std::getline(header, cell, ',');) t.names.push_back(cell);
  t.columns.resize(t.names.size());
  std::vector<bool> keep(t.names.size());
  for (std::size_t c = 0; c < keep.size(); ++c)
    keep[c] = std::find(wanted.begin(), wanted.end(), t.names[c]) != wanted.end();
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::size_t c = 0;
    for (std::string cell; std::getline(row, cell, ',') && c < t.columns.size(); ++c) {
      if (keep[c]) t.columns[c].push_back(std::strtod(cell.c_str(), nullptr));
    }
  }
  return t;
}

// y(x) by linear interpolation in the increasing xs (held constant beyond the ends).
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (xs.empty()) return std::nan("");
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const auto k = std::size_t(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
  const double t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return ys[k - 1] + t * (ys[k] - ys[k - 1]);
}

std::string number(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}

}  // namespace

std::vector<ColumnCheck> read_checks(const Json& document, const std::string& file,
                                     InputProblems& problems) {
  std::vector<ColumnCheck> out;
  if (!document.contains("checks")) return out;
  const Json& list = document["checks"];
  if (!list.is_array()) {
    problems.add("/checks", "expected a list of checks");
    return out;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = "/checks/" + std::to_string(i);
    if (!list[i].is_object()) {
      problems.add(at, "expected a check object");
      continue;
    }
    JsonReader r(list[i], at, problems);
    ColumnCheck c;
    c.column = r.string("column", "the CSV column checked, e.g. \"von_mises [Pa]\"");
    c.name = r.string_or("name", c.column, "the check's name (JUnit test case)");
    c.rtol = r.number_or("rtol", c.rtol, Range::non_negative(), "relative tolerance [-]");
    c.atol = r.number_or("atol", c.atol, Range::non_negative(), "absolute tolerance [column unit]");
    if (r.has("value") == r.has("reference")) {
      problems.add(at, "give exactly one of \"value\" (at one row) and \"reference\" (a CSV)");
    } else if (r.has("value")) {
      c.value = r.number("value", Range::any(), "expected value [column unit]");
      if (list[i].contains("at") && list[i]["at"].is_object()) {
        if (auto a = r.optional_child("at", "the row: {\"time\": t} or \"end\"")) {
          c.at_time = a->number("time", Range::non_negative(), "time of the row [s]");
          a->reject_unknown_keys();
        }
      } else {
        r.choice("at", {"end"}, "the row: \"end\" or {\"time\": t}", "end");
      }
    } else {
      const std::string name = r.string("reference", "reference CSV (a run's output)");
      std::error_code ec;
      c.reference = fs::exists(name, ec) ? name : (fs::path(file).parent_path() / name).string();
      if (!fs::exists(c.reference, ec))
        problems.add(r.key_path("reference"),
                     "cannot find the reference CSV '" + name +
                         "' (looked in the working directory and beside the path file)");
    }
    r.reject_unknown_keys();
    out.push_back(c);
  }
  return out;
}

std::vector<std::string> checked_columns(const std::vector<ColumnCheck>& checks) {
  std::vector<std::string> out;
  if (checks.empty()) return out;
  out.push_back("time [s]");
  for (const ColumnCheck& c : checks) {
    if (std::find(out.begin(), out.end(), c.column) == out.end()) out.push_back(c.column);
  }
  return out;
}

std::vector<CheckOutcome> evaluate_checks(const std::vector<ColumnCheck>& checks,
                                          const std::string& csv_file) {
  std::vector<CheckOutcome> out;
  if (checks.empty()) return out;
  Table run;
  std::string unreadable;
  try {
    run = read_table(csv_file, checked_columns(checks));
  } catch (const std::runtime_error& e) {
    unreadable = e.what();
  }
  for (const ColumnCheck& c : checks) {
    CheckOutcome o{c.name, false, ""};
    const std::vector<double>* computed = run.column(c.column);
    const std::vector<double>* time = run.column("time [s]");
    if (!unreadable.empty()) {
      o.message = unreadable;
    } else if (computed == nullptr || computed->empty() || time == nullptr) {
      o.message = "no column '" + c.column + "' with rows in " + csv_file;
    } else if (c.value) {
      const double got = c.at_time ? interpolate(*time, *computed, *c.at_time) : computed->back();
      const double allowed = c.atol + c.rtol * std::abs(*c.value);
      o.passed = std::abs(got - *c.value) <= allowed;
      o.message = c.column + " at " + (c.at_time ? "t = " + number(*c.at_time) + " s" : "the end") +
                  ": " + number(got) + ", expected " + number(*c.value) + " (|difference| " +
                  number(std::abs(got - *c.value)) + ", allowed " + number(allowed) + ")";
    } else {
      try {
        const Table ref = read_table(c.reference, {"time [s]", c.column});
        const std::vector<double>* expected = ref.column(c.column);
        const std::vector<double>* ref_time = ref.column("time [s]");
        if (expected == nullptr || ref_time == nullptr) {
          o.message = "no column '" + c.column + "' (or time [s]) in " + c.reference;
        } else {
          double worst = -1.0, worst_time = 0.0, worst_got = 0.0, worst_want = 0.0;
          o.passed = true;
          for (std::size_t k = 0; k < computed->size(); ++k) {
            const double want = interpolate(*ref_time, *expected, (*time)[k]);
            const double excess =
                std::abs((*computed)[k] - want) - (c.atol + c.rtol * std::abs(want));
            if (!(excess <= 0.0)) o.passed = false;
            if (excess > worst || worst < 0.0 || std::isnan(excess)) {
              worst = std::isnan(excess) ? INFINITY : excess;
              worst_time = (*time)[k];
              worst_got = (*computed)[k];
              worst_want = want;
            }
          }
          o.message = c.column + " against " + c.reference + " at " +
                      std::to_string(computed->size()) +
                      " rows: worst at t = " + number(worst_time) + " s, " + number(worst_got) +
                      " against " + number(worst_want);
        }
      } catch (const std::runtime_error& e) {
        o.message = e.what();
      }
    }
    out.push_back(o);
  }
  return out;
}

}  // namespace impact::pointdriver
