// What `pointdriver run` will write and hold, from the path alone, before anything runs: a run
// whose CSV cannot fit where it goes, or whose memory exceeds what is available, is refused at
// once (exit 4, as mpm run refuses a scene for memory) instead of failing after hours.
//   rows:   1 + the legs' steps (cut-backs add no rows; the failure policy may stop sooner)
//   CSV:    the header + rows x kCsvRowBytes (the mean row of the shipped paths, measured:
//           docs/pointdriver.md, "Refused runs"); the summary and replay files are small
//   memory: kProgramBytes, plus with "checks" the CSV read back: rows x (time + each checked
//           column) x 16 B (8 B a value, a growing vector up to twice its size); a reference
//           CSV's columns are not counted
#pragma once

#include <optional>
#include <string>

#include "pointdriver/path/path.hpp"

namespace impact::pointdriver {

struct RunEstimate {
  static constexpr double kCsvRowBytes = 440.0;
  static constexpr double kProgramBytes = 16e6;

  double rows = 0.0;
  double csv_bytes = 0.0;
  double memory_bytes = 0.0;
  std::size_t checked_columns = 0;  ///< columns the checks read back (time included), or 0
};

RunEstimate estimate_run(const Path& path);

/// Why `pointdriver run` must not start: the CSV estimate exceeds `output_available` (bytes the
/// CSV `csv_file` may take: free space, ulimit -f), or the memory estimate `memory_available`;
/// both numbers in the message. Empty when it may run (also when a limit is unknown).
std::string run_refusal(const RunEstimate& estimate, const std::string& csv_file,
                        std::optional<double> output_available,
                        std::optional<double> memory_available);

}  // namespace impact::pointdriver
