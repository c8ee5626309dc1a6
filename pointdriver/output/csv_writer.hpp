// The run's CSV: one row per step, a header cell per column as `name [unit]` (SI units), columns
// listed in docs/pointdriver.md. Derived quantities (log strain, invariants, energies) are computed
// here from the row, not by the driver.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "models/material/elastic_plastic.hpp"
#include "pointdriver/driver/driver.hpp"

namespace impact {
class AtomicFile;
}

namespace impact::pointdriver {

/// Column names with units, in output order.
const std::vector<std::string>& csv_columns();

/// The values of one row, in the order of csv_columns() (flags as 0/1).
std::vector<double> csv_values(const Row& row, const ElasticPlasticParams& params);

/// Invariants used by the CSV and by the verification suite.
double triaxiality(const Mat3& stress);  ///< sigma_m / sigma_eq (0 for a purely hydrostatic state)
double lode_parameter(const Mat3& stress);  ///< (2 s2 - s1 - s3) / (s1 - s3), s1 >= s2 >= s3
Mat3 log_strain(const Mat3& F);             ///< Hencky strain ln V = ln(F F^T) / 2

/// The CSV of one run, written as `file.tmp` and put in place by close() (support/atomic_file.hpp):
/// a previous `file` stays whole until then, and a run whose writes fail leaves no partial file.
class CsvWriter {
 public:
  /// Opens the file and writes the header; std::runtime_error naming `file` when it cannot.
  CsvWriter(const std::string& file, ElasticPlasticParams params);
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  /// Without close(): the rows written are dropped (the temporary is removed).
  ~CsvWriter();
  /// One row; std::runtime_error naming the file as soon as a write fails (a full disk).
  void write(const Row& row);
  /// Flushes, closes and renames the file into place; std::runtime_error when it cannot.
  void close();

 private:
  std::unique_ptr<AtomicFile> out_;
  ElasticPlasticParams params_;
};

}  // namespace impact::pointdriver
