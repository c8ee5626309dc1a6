// history.csv: header cells `name [unit]` (definitions in docs/mpm.md#ledger), the ledger's
// columns then the gauges' (mpm/output/observables.hpp), values at 17 significant digits so a
// reader can check the ledger closure to round-off.
#include <iomanip>
#include <stdexcept>

#include "models/core/input.hpp"
#include "mpm/output/output.hpp"

namespace impact::mpm {

HistoryCsv::HistoryCsv(const std::string& path, const Ledger& ledger,
                       const std::vector<std::string>& extra_columns)
    : out_(path), with_external_(ledger.with_external()), extra_columns_(extra_columns.size()) {
  if (!out_) throw std::runtime_error("cannot write " + path);
  auto cols = ledger.columns();
  cols.insert(cols.end(), extra_columns.begin(), extra_columns.end());
  for (std::size_t i = 0; i < cols.size(); ++i) out_ << (i ? "," : "") << cols[i];
  out_ << '\n' << std::setprecision(17);
}

void HistoryCsv::write(const LedgerRow& row, const std::vector<double>& extra) {
  if (extra.size() != extra_columns_) {
    throw std::logic_error("history.csv: " + std::to_string(extra.size()) + " extra values for " +
                           std::to_string(extra_columns_) + " extra columns");
  }
  const auto v = Ledger::values(row, with_external_);
  for (std::size_t i = 0; i < v.size(); ++i) out_ << (i ? "," : "") << v[i];
  for (const double x : extra) out_ << ',' << x;
  out_ << '\n';
  out_.flush();
}

}  // namespace impact::mpm
