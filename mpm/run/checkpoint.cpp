// DIR/checkpoint.bin (format in mpm/run/checkpoint.hpp): the header and the run loop's state around
// the Simulation's part (mpm/simulation/simulation_checkpoint.cpp).
#include "mpm/run/checkpoint.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

#include "mpm/simulation/simulation.hpp"
#include "support/atomic_file.hpp"

namespace impact::mpm {

namespace {

constexpr char kMagic[16] = {'I', 'M', 'P', 'A', 'C', 'T', '-', 'M',
                             'P', 'M', '-', 'C', 'K', 'P', 'T', '\n'};
constexpr std::uint32_t kByteOrderMark = 0x01020304;
// The magic, version, byte-order mark, double size and length: what a file must hold for its
// length to be known.
constexpr std::uintmax_t kHeaderPrefix = sizeof kMagic + 3 * sizeof(std::uint32_t) + 16;

void write_header(CheckpointWriter& w, const CheckpointHeader& h) {
  w.bytes(kMagic, sizeof kMagic);
  w.value(h.version);
  w.value(kByteOrderMark);
  w.value(static_cast<std::uint32_t>(sizeof(double)));
  w.value(h.file_bytes);
  w.value(~h.file_bytes);  // a flipped bit in the length reads as corruption, not truncation
  w.value(h.threads);
  w.value(h.ranks);
  w.value(h.rank);
  w.value(h.particles);
  w.value(h.step);
  w.value(h.time);
  w.value(h.scene_hash);
  w.text(h.working_directory);
  w.text(h.scene_file);
}

// The prefix: magic, version, byte order, double size and the file's length (what a file must
// hold for its length to be known); `size` the file's actual length (nullopt: unknown). A file
// shorter than the length it states is truncated, whatever field the cut runs through.
CheckpointHeader read_prefix(CheckpointReader& r, std::optional<std::uintmax_t> size) {
  if (size && *size < kHeaderPrefix) {
    r.fail("truncated: " + std::to_string(*size) +
           " bytes, shorter than a checkpoint's header (the file was cut short)");
  }
  char magic[sizeof kMagic];
  r.bytes(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, sizeof magic) != 0) r.fail("not an mpm checkpoint (magic)");
  CheckpointHeader h;
  h.version = r.value<std::uint32_t>();
  if (h.version != kCheckpointVersion) {
    r.fail("checkpoint format version " + std::to_string(h.version) + ", this mpm reads version " +
           std::to_string(kCheckpointVersion));
  }
  if (r.value<std::uint32_t>() != kByteOrderMark) r.fail("written with another byte order");
  if (r.value<std::uint32_t>() != sizeof(double)) r.fail("written with another double size");
  h.file_bytes = r.value<std::uint64_t>();
  if (r.value<std::uint64_t>() != ~h.file_bytes) r.fail("corrupt checkpoint (its length field)");
  if (size && *size < h.file_bytes) {
    r.fail("truncated: " + std::to_string(*size) + " of " + std::to_string(h.file_bytes) +
           " bytes (the file was cut short after it was written, e.g. by a copy or a full disk; "
           "it cannot be continued)");
  }
  if (size && *size > h.file_bytes) {
    r.fail(std::to_string(*size - h.file_bytes) + " bytes after the end of the checkpoint (" +
           std::to_string(h.file_bytes) + " bytes; corrupt checkpoint)");
  }
  return h;
}

CheckpointHeader read_header(CheckpointReader& r, std::optional<std::uintmax_t> size) {
  CheckpointHeader h = read_prefix(r, size);
  h.threads = r.value<std::int32_t>();
  h.ranks = r.value<std::int32_t>();
  h.rank = r.value<std::int32_t>();
  if (h.ranks < 1 || h.rank < 0 || h.rank >= h.ranks)
    r.fail("rank out of range (corrupt checkpoint)");
  h.particles = r.value<std::uint64_t>();
  h.step = r.value<std::int64_t>();
  h.time = r.value<double>();
  h.scene_hash = r.value<std::uint64_t>();
  h.working_directory = r.text();
  h.scene_file = r.text();
  return h;
}

// The file's length, nullopt when the file system cannot say (a pipe).
std::optional<std::uintmax_t> length_of(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  return ec ? std::nullopt : std::optional<std::uintmax_t>(size);
}

}  // namespace

std::filesystem::path checkpoint_file(const std::filesystem::path& dir, int rank) {
  return rank == 0 ? dir / kCheckpointFile
                   : dir / ("checkpoint.rank" + std::to_string(rank) + ".bin");
}

namespace {

void write_body(CheckpointWriter& w, const CheckpointHeader& h, const Simulation& sim,
                const RunState& run) {
  write_header(w, h);
  sim.save(w);
  w.section("run", 1, 2 * sizeof(double) + 2 * sizeof(std::uint64_t));
  w.value(run.next_output);
  w.value(run.wall_time);
  w.value(run.history_bytes);
  w.value(run.history_rows);
  w.array("observables", run.observables);
  w.array("gauge_extrema", run.gauge_extrema);
  w.array("faces_reached", run.faces_reached);
  w.section("snapshots", run.snapshots.size(), 0);
  for (const auto& [t, name] : run.snapshots) {
    w.value(t);
    w.text(name);
  }
  w.finish();
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const RunState& run,
                      const RunOrigin& origin) {
  CheckpointHeader h;
  h.threads = sim.threads();
  h.ranks = sim.ranks();
  h.rank = sim.rank();
  h.particles = sim.particles().size();
  h.step = sim.steps();
  h.time = sim.time();
  h.scene_hash = origin.scene_hash;
  h.working_directory = origin.working_directory;
  h.scene_file = origin.scene_file;
  // The length first (a pass that only counts), so that the header can state it.
  CheckpointWriter counter = CheckpointWriter::counting();
  write_body(counter, h, sim, run);
  h.file_bytes = counter.size();
  write_file_atomically(file, [&](std::ostream& o) {
    CheckpointWriter w(o);
    write_body(w, h, sim, run);
  });
}

CheckpointHeader read_checkpoint_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CheckpointError(file.string() + ": cannot open (no checkpoint here?)");
  CheckpointReader r(in, file.string());
  return read_header(r, length_of(file));
}

// The trailer is checked before any field is parsed: a flipped bit must read as corruption,
// not as whichever field check it happens to land on.
void verify_checkpoint_checksum(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::uint64_t stored = 0;
  if (bytes.size() < sizeof stored)
    throw CheckpointError(file.string() + ": truncated (no trailer: corrupt checkpoint)");
  const std::size_t payload = bytes.size() - sizeof stored;
  std::memcpy(&stored, bytes.data() + payload, sizeof stored);
  if (stored != fnv1a(bytes.data(), payload, kHashSeed))
    throw CheckpointError(file.string() + ": checksum mismatch (corrupt checkpoint)");
}

RunState read_checkpoint(const std::filesystem::path& file, Simulation& sim) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CheckpointError(file.string() + ": cannot open (no checkpoint here?)");
  CheckpointReader r(in, file.string());
  // Magic, version and length first: their own messages.
  const CheckpointHeader h = read_header(r, length_of(file));
  verify_checkpoint_checksum(file);
  if (h.ranks != sim.ranks() || h.rank != sim.rank()) {
    r.fail("written by rank " + std::to_string(h.rank) + " of " + std::to_string(h.ranks) +
           ", read by rank " + std::to_string(sim.rank()) + " of " + std::to_string(sim.ranks()) +
           " (restart on the rank count of the run)");
  }
  // One rank holds the seeded particles; on several, particles have moved between the boxes.
  if (h.ranks == 1 && h.particles != sim.particles().size()) {
    r.fail(std::to_string(h.particles) + " particles, the scene seeds " +
           std::to_string(sim.particles().size()));
  }
  if (h.particles > (std::uint64_t(1) << 40)) r.fail("corrupt checkpoint (particle count)");
  sim.resize_particles(h.particles);
  sim.load(r);
  RunState run;
  r.section("run", 2 * sizeof(double) + 2 * sizeof(std::uint64_t), 1);
  run.next_output = r.value<double>();
  run.wall_time = r.value<double>();
  run.history_bytes = r.value<std::uint64_t>();
  run.history_rows = r.value<std::uint64_t>();
  r.array("observables", run.observables);
  r.array("gauge_extrema", run.gauge_extrema);
  r.array("faces_reached", run.faces_reached);
  const std::uint64_t snapshots = r.section("snapshots", 0);
  for (std::uint64_t i = 0; i < snapshots; ++i) {
    const double t = r.value<double>();
    run.snapshots.emplace_back(t, r.text());
  }
  r.finish();
  return run;
}

}  // namespace impact::mpm
