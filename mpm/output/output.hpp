// Writers: history.csv (the ledger, one row per output interval), binary (raw appended) VTU
// snapshots of the particles with a .pvd collection (ParaView), and summary.json.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "mpm/ledger/ledger.hpp"
#include "mpm/particles/particles.hpp"

namespace impact::mpm {

class HistoryCsv {
 public:
  HistoryCsv(const std::string& path, const Ledger& ledger);
  void write(const LedgerRow& row);

 private:
  std::ofstream out_;
  bool with_external_;
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
