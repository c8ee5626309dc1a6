// Regression checks in a path file, the way MTest users write them (docs/pointdriver.md,
// "Checks"): a "checks" list, each a column of the run's CSV against a value at one row, or
// against the same column of a reference CSV at every row, with tolerances:
//   {"name": "...", "column": "von_mises [Pa]", "value": 3.2e8, "at": "end" | {"time": t},
//    "rtol": 1e-6, "atol": 0}
//   {"name": "...", "column": "von_mises [Pa]", "reference": "ref.csv", "rtol": 1e-3, "atol": 1e3}
// A check passes when |computed - expected| <= atol + rtol |expected| (at every row for a
// reference, which is interpolated linearly in time [s]). `pointdriver run` evaluates them
// after the run, prints each, exits 3 when one fails and writes them as JUnit with --junit.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "models/core/input.hpp"

namespace impact::pointdriver {

struct ColumnCheck {
  std::string name;
  std::string column;             ///< a CSV column header, e.g. "von_mises [Pa]"
  std::optional<double> value;    ///< expected value at `at_time` (or the last row)
  std::optional<double> at_time;  ///< [s]; absent: the last row
  std::string reference;          ///< a reference CSV (resolved), or empty
  double rtol = 1e-6;
  double atol = 0.0;
};

/// Reads the optional "checks" list of a path document (problems by key path); `file` resolves
/// reference CSVs (the working directory, then beside the path file).
std::vector<ColumnCheck> read_checks(const Json& document, const std::string& file,
                                     InputProblems& problems);

struct CheckOutcome {
  std::string name;
  bool passed = false;
  std::string message;  ///< what was compared, and the worst difference
};

/// The columns of the run's CSV that evaluate_checks reads back and holds (time [s] and each
/// checked column, once; none without checks).
std::vector<std::string> checked_columns(const std::vector<ColumnCheck>& checks);

/// Evaluates every check against the run's CSV `csv_file`; a missing column or an unreadable
/// reference is a failed check naming it.
std::vector<CheckOutcome> evaluate_checks(const std::vector<ColumnCheck>& checks,
                                          const std::string& csv_file);

}  // namespace impact::pointdriver
