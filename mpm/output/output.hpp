// Writers: history.csv (the ledger, then the gauges, one row per output interval), binary (raw
// appended) VTU snapshots of the particles with a .pvd collection (ParaView), and summary.json.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "mpm/ledger/ledger.hpp"
#include "mpm/particles/particles.hpp"

namespace impact::mpm {

class HistoryCsv {
 public:
  /// The ledger's columns, then `extra_columns` (the gauges, `name [unit]`) after energy_error.
  HistoryCsv(const std::string& path, const Ledger& ledger,
             const std::vector<std::string>& extra_columns = {});
  /// `extra`: one value per extra column.
  void write(const LedgerRow& row, const std::vector<double>& extra = {});

 private:
  std::ofstream out_;
  bool with_external_;
  std::size_t extra_columns_ = 0;
};

class SnapshotWriter {
 public:
  /// Writes into DIR/particles/ and DIR/particles.pvd.
  SnapshotWriter(const std::string& directory, std::vector<std::string> fields);
  /// Writes particles/step_NNNNNN.vtu and rewrites the .pvd so it is valid after every call.
  void write(const Particles& P, long step, double time);

 private:
  std::string directory_;
  std::vector<std::string> fields_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace impact::mpm
