#include "mpm/parallel/communicator.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#ifdef IMPACT_MPI
#include <mpi.h>
#endif

namespace impact::mpm {

namespace {

// Adds the wall time of its scope to a counter (MPI_Wtime: the MPI calls' own clock).
class MpiTimer {
 public:
  explicit MpiTimer([[maybe_unused]] double& seconds) : seconds_(seconds) {
#ifdef IMPACT_MPI
    start_ = MPI_Wtime();
#endif
  }
  ~MpiTimer() {
#ifdef IMPACT_MPI
    seconds_ += MPI_Wtime() - start_;
#endif
  }

 private:
  double& seconds_;
  double start_ = 0.0;
};

}  // namespace

// Environment variables an MPI launcher sets in every process it starts (Open MPI's mpirun,
// MPICH's Hydra, Slurm's srun with PMI or PMIx).
bool started_by_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

bool mpi_available() {
#ifdef IMPACT_MPI
  return true;
#else
  return false;
#endif
}

MpiSession::MpiSession([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
#ifdef IMPACT_MPI
  if (!started_by_launcher()) return;
  // Threads call no MPI function: OpenMP runs inside a rank, the exchanges between its loops.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  active_ = true;
#endif
}

MpiSession::~MpiSession() {
#ifdef IMPACT_MPI
  if (active_) MPI_Finalize();
#endif
}

Communicator::Communicator([[maybe_unused]] const MpiSession* session) {
#ifdef IMPACT_MPI
  if (session == nullptr || !session->active()) return;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  mpi_ = size_ > 1;  // one rank (mpirun -np 1 too): the identity, no MPI call
#endif
}

const Communicator& Communicator::one_rank() {
  static const Communicator alone;
  return alone;
}

std::vector<double> Communicator::every_ranks(
    [[maybe_unused]] const std::vector<double>& values) const {
  std::vector<double> all;
#ifdef IMPACT_MPI
  const MpiTimer timer(seconds_);
  const int n = static_cast<int>(values.size());
  all.resize(values.size() * static_cast<std::size_t>(size_));
  MPI_Allgather(values.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, MPI_COMM_WORLD);
#endif
  return all;
}

std::vector<double> Communicator::sum(const std::vector<double>& values) const {
  if (!mpi_) return values;
  const std::vector<double> all = every_ranks(values);
  std::vector<double> total(values.size(), 0.0);
  for (int r = 0; r < size_; ++r)
    for (std::size_t i = 0; i < values.size(); ++i)
      total[i] += all[static_cast<std::size_t>(r) * values.size() + i];
  return total;
}

std::vector<double> Communicator::sum_counts(const std::vector<double>& counts) const {
  if (!mpi_) return counts;
  std::vector<double> total(counts.size(), 0.0);
#ifdef IMPACT_MPI
  const MpiTimer timer(seconds_);
  MPI_Allreduce(counts.data(), total.data(), static_cast<int>(counts.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
#endif
  return total;
}

std::int64_t Communicator::sum(std::int64_t value) const {
  std::int64_t total = value;
  if (!mpi_) return total;
#ifdef IMPACT_MPI
  const MpiTimer timer(seconds_);
  MPI_Allreduce(&value, &total, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
#endif
  return total;
}

double Communicator::max(double value) const {
  // Every rank's value, then the largest: exact, and no MPI_Op to pass around.
  const std::vector<double> all = gather_all(value);
  return *std::max_element(all.begin(), all.end());
}

std::vector<double> Communicator::max(const std::vector<double>& values) const {
  if (!mpi_) return values;
  const std::vector<double> all = every_ranks(values);
  std::vector<double> largest = values;
  for (int r = 0; r < size_; ++r)
    for (std::size_t i = 0; i < values.size(); ++i)
      largest[i] = std::max(largest[i], all[static_cast<std::size_t>(r) * values.size() + i]);
  return largest;
}

double Communicator::min(double value) const {
  const std::vector<double> all = gather_all(value);
  return *std::min_element(all.begin(), all.end());
}

bool Communicator::any(bool value) const {
  int result = value ? 1 : 0;
  if (!mpi_) return result != 0;
#ifdef IMPACT_MPI
  const int mine = result;
  const MpiTimer timer(seconds_);
  MPI_Allreduce(&mine, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
#endif
  return result != 0;
}

std::vector<double> Communicator::gather_all(double value) const {
  std::vector<double> all(static_cast<std::size_t>(size_), value);
  if (!mpi_) return all;
#ifdef IMPACT_MPI
  const MpiTimer timer(seconds_);
  MPI_Allgather(&value, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, MPI_COMM_WORLD);
#endif
  return all;
}

std::vector<char> Communicator::concatenate(const std::vector<char>& bytes) const {
  const std::vector<std::vector<char>> from =
      all_to_all(std::vector<std::vector<char>>(static_cast<std::size_t>(size_), bytes));
  std::vector<char> all;
  for (const std::vector<char>& b : from) all.insert(all.end(), b.begin(), b.end());
  return all;
}

std::string Communicator::broadcast(const std::string& text, [[maybe_unused]] int from) const {
  std::string out = text;
#ifdef IMPACT_MPI
  if (!mpi_) return out;
  const MpiTimer timer(seconds_);
  long long n = static_cast<long long>(text.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, from, MPI_COMM_WORLD);
  out.resize(static_cast<std::size_t>(n));
  MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, from, MPI_COMM_WORLD);
#endif
  return out;
}

std::vector<std::vector<char>> Communicator::exchange(
    const std::vector<int>& neighbours,
    [[maybe_unused]] const std::vector<std::vector<char>>& to_send,
    [[maybe_unused]] int tag) const {
  std::vector<std::vector<char>> received(neighbours.size());
#ifdef IMPACT_MPI
  if (!mpi_) return received;
  const MpiTimer timer(seconds_);
  const std::size_t n = neighbours.size();
  for (std::size_t i = 0; i < n; ++i) received[i].resize(to_send[i].size());
  // The receives first, so that a neighbour's message finds its buffer.
  std::vector<MPI_Request> requests(2 * n, MPI_REQUEST_NULL);
  for (std::size_t i = 0; i < n; ++i)
    MPI_Irecv(received[i].data(), static_cast<int>(received[i].size()), MPI_BYTE, neighbours[i],
              tag, MPI_COMM_WORLD, &requests[i]);
  for (std::size_t i = 0; i < n; ++i) {
    MPI_Isend(to_send[i].data(), static_cast<int>(to_send[i].size()), MPI_BYTE, neighbours[i], tag,
              MPI_COMM_WORLD, &requests[n + i]);
    exchanged_bytes_ += static_cast<std::uint64_t>(to_send[i].size());
    ++exchanged_messages_;
  }
  std::vector<MPI_Status> statuses(2 * n);
  MPI_Waitall(static_cast<int>(2 * n), requests.data(), statuses.data());
  for (std::size_t i = 0; i < n; ++i) {
    int count = 0;
    MPI_Get_count(&statuses[i], MPI_BYTE, &count);
    if (static_cast<std::size_t>(count) != received[i].size())
      throw std::logic_error("halo exchange: rank " + std::to_string(neighbours[i]) + " sent " +
                             std::to_string(count) + " B to rank " + std::to_string(rank_) +
                             ", which sent it " + std::to_string(received[i].size()) + " B");
  }
#endif
  return received;
}

std::vector<std::vector<char>> Communicator::all_to_all(
    const std::vector<std::vector<char>>& to_each) const {
  if (!mpi_) return to_each;  // one rank: to itself
  std::vector<std::vector<char>> from(static_cast<std::size_t>(size_));
#ifdef IMPACT_MPI
  const MpiTimer timer(seconds_);
  const std::size_t n = static_cast<std::size_t>(size_);
  std::vector<int> send_counts(n), recv_counts(n), send_offsets(n), recv_offsets(n);
  std::vector<char> send;
  for (std::size_t r = 0; r < n; ++r) {
    send_counts[r] = static_cast<int>(to_each[r].size());
    send_offsets[r] = static_cast<int>(send.size());
    send.insert(send.end(), to_each[r].begin(), to_each[r].end());
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int total = 0;
  for (std::size_t r = 0; r < n; ++r) {
    recv_offsets[r] = total;
    total += recv_counts[r];
  }
  std::vector<char> received(static_cast<std::size_t>(total));
  MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, received.data(),
                recv_counts.data(), recv_offsets.data(), MPI_BYTE, MPI_COMM_WORLD);
  for (std::size_t r = 0; r < n; ++r)
    from[r].assign(received.begin() + recv_offsets[r],
                   received.begin() + recv_offsets[r] + recv_counts[r]);
#endif
  return from;
}

void Communicator::barrier() const {
  if (!mpi_) return;
#ifdef IMPACT_MPI
  const MpiTimer timer(seconds_);
  MPI_Barrier(MPI_COMM_WORLD);
#endif
}

}  // namespace impact::mpm
