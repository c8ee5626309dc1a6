// The run's CSV: one row per step, a header cell per column as `name [unit]` (SI units), columns
// listed in docs/pointdriver.md. Derived quantities (log strain, invariants, energies) are computed
// here from the row, not by the driver.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "models/material/elastic_plastic.hpp"
#include "pointdriver/driver/driver.hpp"

namespace impact::pointdriver {

/// Column names with units, in output order.
const std::vector<std::string>& csv_columns();

/// The values of one row, in the order of csv_columns() (flags as 0/1).
std::vector<double> csv_values(const Row& row, const ElasticPlasticParams& params);

/// Invariants used by the CSV and by the verification suite.
double triaxiality(const Mat3& stress);  ///< sigma_m / sigma_eq (0 for a purely hydrostatic state)
double lode_parameter(const Mat3& stress);  ///< (2 s2 - s1 - s3) / (s1 - s3), s1 >= s2 >= s3
Mat3 log_strain(const Mat3& F);             ///< Hencky strain ln V = ln(F F^T) / 2

class CsvWriter {
 public:
  /// Opens `file` (throws std::runtime_error naming it when it cannot) and writes the header.
  CsvWriter(const std::string& file, ElasticPlasticParams params);
  void write(const Row& row);

 private:
  std::ofstream out_;
  ElasticPlasticParams params_;
};

}  // namespace impact::pointdriver
