// The ranks of a run and what they exchange (docs/mpi.md): MPI when the build has it (IMPACT_MPI)
// and the program was started by an MPI launcher (mpirun, srun), else one rank and no MPI call at
// all, so a plain `mpm run` costs nothing for it. Every reduction is reproducible: sums are taken
// in rank order on every rank (the same bits on every rank and in every run with the same rank
// count), maxima and minima are exact.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace impact::mpm {

/// MPI_Init and MPI_Finalize around a program's life, when a launcher started it; one per
/// process (main()). Without it, or without MPI in the build, a Communicator has one rank.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  /// Whether MPI was initialised (a launcher started this process and the build has MPI).
  bool active() const { return active_; }

 private:
  bool active_ = false;
};

/// Whether this build can run on several ranks (built with MPI).
bool mpi_available();
/// Whether an MPI launcher (mpirun, srun) started this process.
bool started_by_launcher();

/// The ranks of a run. There is always one: on one rank (no session, a build without MPI, or
/// `mpirun -np 1`) every call is the identity and makes no MPI call, so code that sums over the
/// ranks reads the same, and gives the same bits, on one rank and on many.
class Communicator {
 public:
  /// The world of an active MpiSession, or one rank.
  explicit Communicator(const MpiSession* session = nullptr);

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }
  /// More than one rank: the particles and the grid are split.
  bool several() const { return size_ > 1; }
  /// This process alone: a constant (no call on it changes it, so threads may share it).
  static const Communicator& one_rank();

  /// Element-wise sums over the ranks, taken in rank order on every rank.
  std::vector<double> sum(const std::vector<double>& values) const;
  double sum(double value) const { return sum(std::vector<double>{value})[0]; }
  std::int64_t sum(std::int64_t value) const;
  /// Element-wise sums of whole numbers (counts below 2^53, so exact in any order) by one
  /// reduction: unlike sum(), no rank receives every rank's table (a table of the box search
  /// on 4 096 ranks would take 1.2 GB per rank as every rank's copies).
  std::vector<double> sum_counts(const std::vector<double>& counts) const;
  double max(double value) const;
  /// Element-wise maxima over the ranks (exact).
  std::vector<double> max(const std::vector<double>& values) const;
  double min(double value) const;
  /// Whether any rank passes true.
  bool any(bool value) const;
  /// Every rank's value, in rank order.
  std::vector<double> gather_all(double value) const;
  /// Every rank's bytes (any length), concatenated in rank order, on every rank.
  std::vector<char> concatenate(const std::vector<char>& bytes) const;
  /// The same for records of plain values (numbers, flags, Eigen fixed-size matrices, PointState:
  /// no pointers), moved as their bytes.
  template <class T>
  std::vector<T> concatenate(const std::vector<T>& records) const {
    static_assert(std::is_standard_layout_v<T>);
    std::vector<char> bytes(records.size() * sizeof(T));
    if (!bytes.empty()) std::memcpy(static_cast<void*>(bytes.data()), records.data(), bytes.size());
    const std::vector<char> all = concatenate(bytes);
    std::vector<T> out(all.size() / sizeof(T));
    if (!out.empty()) std::memcpy(static_cast<void*>(out.data()), all.data(), all.size());
    return out;
  }
  /// The bytes `text` of rank `from`, on every rank.
  std::string broadcast(const std::string& text, int from) const;
  /// Sends to_send[i] to rank neighbours[i] and returns what each sent back (every neighbour calls
  /// this with this rank among its own). Every receive and send is posted before one wait, so a
  /// rank between two neighbours waits for neither's other exchange: no chain across the ranks.
  /// Each pair sends each other the same number of bytes (two neighbours' shared node layers are
  /// the same list on both, halo_exchange.cpp), so no size goes first; a neighbour's message of
  /// another length throws std::logic_error. `tag` tells exchanges in the same step apart.
  std::vector<std::vector<char>> exchange(const std::vector<int>& neighbours,
                                          const std::vector<std::vector<char>>& to_send,
                                          int tag) const;
  /// to_each[r] goes to rank r; returns what each rank sent here, indexed by sender.
  std::vector<std::vector<char>> all_to_all(const std::vector<std::vector<char>>& to_each) const;
  void barrier() const;

  /// Wall time spent in MPI calls so far [s]: waiting for the other ranks plus moving the data
  /// (the load balance shows in it: docs/mpi.md).
  double seconds_in_mpi() const { return seconds_; }
  /// Bytes and messages (one per neighbour and exchange) this rank sent by exchange() so far (the
  /// node sums with its neighbours: what docs/mpi.md's cost model predicts).
  std::uint64_t exchanged_bytes() const { return exchanged_bytes_; }
  std::uint64_t exchanged_messages() const { return exchanged_messages_; }

 private:
  /// Every rank's `values` (all the same length), concatenated in rank order.
  std::vector<double> every_ranks(const std::vector<double>& values) const;

  mutable double seconds_ = 0.0;
  mutable std::uint64_t exchanged_bytes_ = 0, exchanged_messages_ = 0;
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;  ///< several ranks under an active MpiSession: MPI calls are made
};

}  // namespace impact::mpm
