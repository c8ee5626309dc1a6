// The point driver's verification suite (`pointdriver verify`): named cases, each of
// which runs the driver on paths built in code and compares what it computes with a reference
// derived independently (closed_forms.hpp, or an integral of the driver's own rows computed here),
// with a stated tolerance. A case returns its checks and may write figure data (CSV) into an
// output directory. Cases and the measured numbers are listed in docs/verification.md (point
// driver verification).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace impact::pointdriver {

/// One comparison: `error` is |got - expected| / scale (scale = |expected| unless the check says
/// otherwise in its quantity, e.g. "relative to max |sigma|"); it passes when error <= tolerance.
struct Check {
  std::string case_name;
  std::string quantity;
  double expected = 0.0;
  double got = 0.0;
  double error = 0.0;
  double tolerance = 0.0;
  bool pass = false;
};

/// Where a case finds its inputs and writes its figure data.
struct SuiteContext {
  std::string material_file;  ///< data/materials/al6061_t6.json (absolute)
  /// Measured aluminium compression points (data/experiments/al6061_t6_hugoniot/hugoniot.csv),
  /// drawn beside the closed-form Hugoniot; "" = skip.
  std::string hugoniot_file;
  std::string out_dir;  ///< figure CSVs go here ("" = write none)
};

struct VerificationCase {
  std::string name;
  std::string description;
  std::function<std::vector<Check>(const SuiteContext&)> run;
};

/// The cases, in the order docs/verification.md lists them.
const std::vector<VerificationCase>& verification_cases();

/// The default context: the material and the Hugoniot data found from the source tree or the
/// current directory.
SuiteContext default_suite_context(const std::string& out_dir);

/// Runs one case and turns an exception (input error, unsolved step) into one failed check, so a
/// broken case is reported in the table rather than aborting the suite.
std::vector<Check> run_case(const VerificationCase& c, const SuiteContext& context);

}  // namespace impact::pointdriver
