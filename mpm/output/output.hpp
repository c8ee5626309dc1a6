// Writers: history.csv (the ledger, then the gauges, one row per output interval), binary (raw
// appended) VTU snapshots of the particles with a .pvd collection (ParaView), one piece per rank
// with a .pvtu on several ranks, and summary.json.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/ledger/ledger.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"

namespace impact::mpm {

class HistoryCsv {
 public:
  /// The ledger's columns, then `extra_columns` (the gauges, `name [unit]`) after energy_error.
  HistoryCsv(const std::string& path, const Ledger& ledger,
             const std::vector<std::string>& extra_columns = {});
  /// Continues an existing file (mpm run --restart): keeps its first `bytes` (the header and the
  /// rows a checkpoint recorded, `rows` of them), drops the rest (rows a killed run wrote after
  /// the checkpoint) and appends. Throws std::runtime_error when the file is shorter, has another
  /// header or another number of rows in those bytes.
  HistoryCsv(const std::string& path, const Ledger& ledger,
             const std::vector<std::string>& extra_columns, std::uint64_t bytes,
             std::uint64_t rows);
  /// The ledger's current row; `extra`: one value per extra column.
  void write(const Ledger& ledger, const std::vector<double>& extra = {});
  /// Bytes and rows written so far (header included in the bytes), for a checkpoint.
  std::uint64_t bytes() const { return bytes_; }
  std::uint64_t rows() const { return rows_; }

 private:
  std::ofstream out_;
  std::string path_;
  std::size_t extra_columns_ = 0;
  std::uint64_t bytes_ = 0, rows_ = 0;
};

class SnapshotWriter {
 public:
  /// Writes into DIR/particles/ and DIR/particles.pvd. With `comm` of several ranks every rank
  /// constructs one and calls write() at the same steps (collective).
  SnapshotWriter(const std::string& directory, std::vector<std::string> fields,
                 const Communicator& comm);
  /// Writes particles/step_NNNNNN.vtu (one rank) or each rank's particles/step_NNNNNN_rankR.vtu
  /// and rank 0's particles/step_NNNNNN.pvtu naming them (several ranks), and rewrites the .pvd
  /// so it is valid after every call. P: the particles this rank holds.
  void write(const Particles& P, long step, double time);
  /// The .pvd entries (time, file) so far, and a restart's: the collection continues from them.
  const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }
  void restore(std::vector<std::pair<double, std::string>> entries) {
    entries_ = std::move(entries);
  }

 private:
  bool pieces() const { return comm_.several(); }
  bool root() const { return comm_.root(); }

  std::string directory_;
  std::vector<std::string> fields_;
  const Communicator& comm_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace impact::mpm
