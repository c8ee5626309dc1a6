// history.csv: header cells `name [unit]` (definitions in docs/mpm.md#ledger),
// values at 17 significant digits so a reader can check the ledger closure to round-off.
#include <iomanip>

#include "models/core/input.hpp"
#include "mpm/output/output.hpp"

namespace impact::mpm {

HistoryCsv::HistoryCsv(const std::string& path, const Ledger& ledger)
    : out_(path), with_external_(ledger.with_external()) {
  if (!out_) throw std::runtime_error("cannot write " + path);
  const auto cols = ledger.columns();
  for (std::size_t i = 0; i < cols.size(); ++i) out_ << (i ? "," : "") << cols[i];
  out_ << '\n' << std::setprecision(17);
}

void HistoryCsv::write(const LedgerRow& row) {
  const auto v = Ledger::values(row, with_external_);
  for (std::size_t i = 0; i < v.size(); ++i) out_ << (i ? "," : "") << v[i];
  out_ << '\n';
  out_.flush();
}

}  // namespace impact::mpm
