#include "pointdriver/output/run_estimate.hpp"

#include <sstream>

#include "pointdriver/output/csv_writer.hpp"
#include "pointdriver/path/checks.hpp"

namespace impact::pointdriver {

RunEstimate estimate_run(const Path& path) {
  RunEstimate e;
  e.rows = 1.0;
  for (const Leg& leg : path.legs) e.rows += leg.steps;
  double header = 0.0;
  for (const std::string& c : csv_columns()) header += double(c.size()) + 1.0;
  e.csv_bytes = header + e.rows * RunEstimate::kCsvRowBytes;
  e.checked_columns = checked_columns(path.checks).size();
  e.memory_bytes = RunEstimate::kProgramBytes + e.rows * double(e.checked_columns) * 16.0;
  return e;
}

std::string run_refusal(const RunEstimate& e, const std::string& csv_file,
                        std::optional<double> output_available,
                        std::optional<double> memory_available) {
  const bool csv_too_big = output_available && e.csv_bytes > *output_available;
  const bool memory_too_big = memory_available && e.memory_bytes > *memory_available;
  if (!csv_too_big && !memory_too_big) return {};
  std::ostringstream m;
  m.precision(4);
  m << "refusing to start: ";
  if (csv_too_big) {
    m << "the CSV would take an estimated " << e.csv_bytes / 1e6 << " MB (" << e.rows
      << " rows of about " << RunEstimate::kCsvRowBytes << " B) but " << csv_file
      << " may take only " << *output_available / 1e6
      << " MB (the free space of its file system, or less under ulimit -f)";
  }
  if (memory_too_big) {
    m << (csv_too_big ? "; and " : "") << "the run would hold an estimated " << e.memory_bytes / 1e6
      << " MB (program " << RunEstimate::kProgramBytes / 1e6 << " MB + the checks reading back "
      << e.checked_columns << " columns of " << e.rows << " rows, 16 B a value) but "
      << *memory_available / 1e6
      << " MB are available (MemAvailable in /proc/meminfo, or less under the cgroup's "
         "memory.max, ulimit -v or ulimit -d)";
  }
  m << "; give the legs fewer steps (steps, max_strain_increment)";
  return m.str();
}

}  // namespace impact::pointdriver
