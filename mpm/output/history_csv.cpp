// history.csv: header cells `name [unit]` (definitions in docs/mpm.md#ledger), the ledger's
// columns then the gauges' (mpm/output/observables.hpp), values at 17 significant digits so a
// reader can check the ledger closure to round-off.
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <stdexcept>

#include "models/core/input.hpp"
#include "mpm/output/output.hpp"

namespace impact::mpm {

namespace {

std::string header_line(const Ledger& ledger, const std::vector<std::string>& extra_columns) {
  auto cols = ledger.columns();
  cols.insert(cols.end(), extra_columns.begin(), extra_columns.end());
  std::string line;
  for (std::size_t i = 0; i < cols.size(); ++i) line += (i ? "," : "") + cols[i];
  return line + '\n';
}

}  // namespace

HistoryCsv::HistoryCsv(const std::string& path, const Ledger& ledger,
                       const std::vector<std::string>& extra_columns)
    : out_(path), path_(path), extra_columns_(extra_columns.size()) {
  if (!out_) throw std::runtime_error("cannot write " + path);
  const std::string header = header_line(ledger, extra_columns);
  out_ << header << std::setprecision(17);
  bytes_ = header.size();
}

HistoryCsv::HistoryCsv(const std::string& path, const Ledger& ledger,
                       const std::vector<std::string>& extra_columns, std::uint64_t bytes,
                       std::uint64_t rows)
    : path_(path), extra_columns_(extra_columns.size()), bytes_(bytes), rows_(rows) {
  namespace fs = std::filesystem;
  const auto fail = [&](const std::string& why) {
    throw std::runtime_error(path + ": " + why + ": not the history.csv of this checkpoint");
  };
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) fail("cannot read it (" + ec.message() + ")");
  if (size < bytes) {
    fail(std::to_string(size) + " bytes, the checkpoint recorded " + std::to_string(bytes));
  }
  std::string kept(bytes, '\0');
  {
    std::ifstream in(path, std::ios::binary);
    if (!in.read(kept.data(), static_cast<std::streamsize>(bytes))) fail("cannot read it");
  }
  const std::string header = header_line(ledger, extra_columns);
  if (kept.compare(0, header.size(), header) != 0) fail("another header");
  const auto lines = static_cast<std::uint64_t>(std::count(kept.begin(), kept.end(), '\n'));
  if (lines != rows + 1 || (bytes > 0 && kept.back() != '\n')) {
    fail(std::to_string(lines) + " lines in the first " + std::to_string(bytes) +
         " bytes, the checkpoint recorded a header and " + std::to_string(rows) + " rows");
  }
  fs::resize_file(path, bytes, ec);  // drop what a killed run wrote after the checkpoint
  if (ec) fail("cannot truncate it (" + ec.message() + ")");
  out_.open(path, std::ios::binary | std::ios::app);
  if (!out_) throw std::runtime_error("cannot write " + path);
  out_ << std::setprecision(17);
}

void HistoryCsv::write(const Ledger& ledger, const std::vector<double>& extra) {
  if (extra.size() != extra_columns_) {
    throw std::logic_error("history.csv: " + std::to_string(extra.size()) + " extra values for " +
                           std::to_string(extra_columns_) + " extra columns");
  }
  const auto v = ledger.values(ledger.row());
  for (std::size_t i = 0; i < v.size(); ++i) out_ << (i ? "," : "") << v[i];
  for (const double x : extra) out_ << ',' << x;
  out_ << '\n';
  errno = 0;
  out_.flush();
  if (!out_) {
    const int error = errno;
    throw std::runtime_error("cannot write " + path_ + ": write failed" +
                             (error != 0 ? " (" + std::string(std::strerror(error)) + ")" : ""));
  }
  bytes_ = static_cast<std::uint64_t>(out_.tellp());
  ++rows_;
}

}  // namespace impact::mpm
