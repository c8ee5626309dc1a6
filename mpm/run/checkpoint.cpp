// DIR/checkpoint.bin (format in mpm/run/checkpoint.hpp) and the Simulation's part of it.
#include "mpm/run/checkpoint.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

#include "mpm/solver.hpp"
#include "support/atomic_file.hpp"

namespace impact::mpm {

namespace {

// The tags of the boxes' boundaries along x, y and z (format 6).
constexpr const char* kBoxTags[3] = {"boxes_x", "boxes_y", "boxes_z"};

constexpr char kMagic[16] = {'I', 'M', 'P', 'A', 'C', 'T', '-', 'M',
                             'P', 'M', '-', 'C', 'K', 'P', 'T', '\n'};
constexpr std::uint32_t kByteOrderMark = 0x01020304;

// A new PointState or Particles member must be added to save()/load() below (and the format
// version raised): these fail to compile until then.
static_assert(sizeof(PointState) == 3 * sizeof(Mat3) + 7 * sizeof(double) + 8,
              "PointState changed: update Simulation::save/load and kCheckpointVersion");
static_assert(sizeof(Particles) == 15 * sizeof(std::vector<double>),
              "Particles changed: update Simulation::save/load and kCheckpointVersion");
// Eigen's fixed-size Vec3 and Mat3 are plain arrays of doubles: written as stored.
static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Mat3) == 9 * sizeof(double));

// The PointState members, one record per particle (no padding bytes in the file).
constexpr std::uint32_t kStateRecord = 3 * sizeof(Mat3) + 7 * sizeof(double) + 5;

void write_header(CheckpointWriter& w, const CheckpointHeader& h) {
  w.bytes(kMagic, sizeof kMagic);
  w.value(h.version);
  w.value(kByteOrderMark);
  w.value(static_cast<std::uint32_t>(sizeof(double)));
  w.value(h.threads);
  w.value(h.ranks);
  w.value(h.rank);
  w.value(h.particles);
  w.value(h.step);
  w.value(h.time);
  w.value(h.scene_hash);
  w.text(h.working_directory);
}

CheckpointHeader read_header(CheckpointReader& r) {
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
  return h;
}

}  // namespace

std::filesystem::path checkpoint_file(const std::filesystem::path& dir, int rank) {
  return rank == 0 ? dir / kCheckpointFile
                   : dir / ("checkpoint.rank" + std::to_string(rank) + ".bin");
}

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= b[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

void CheckpointWriter::bytes(const void* data, std::size_t size) {
  hash_ = fnv1a(data, size, hash_);
  out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}

void CheckpointWriter::text(const std::string& s) {
  value(static_cast<std::uint64_t>(s.size()));
  bytes(s.data(), s.size());
}

void CheckpointWriter::section(const std::string& tag, std::uint64_t count,
                               std::uint32_t element_size) {
  text(tag);
  value(count);
  value(element_size);
}

void CheckpointWriter::finish() {
  const std::uint64_t h = hash_;
  out_.write(reinterpret_cast<const char*>(&h), sizeof h);
}

void CheckpointReader::fail(const std::string& why) const {
  throw CheckpointError(file_ + ": " + why);
}

void CheckpointReader::bytes(void* data, std::size_t size) {
  if (!in_.read(static_cast<char*>(data), static_cast<std::streamsize>(size)))
    fail("truncated (corrupt checkpoint)");
  hash_ = fnv1a(data, size, hash_);
}

std::string CheckpointReader::text() {
  const auto n = value<std::uint64_t>();
  if (n > (1u << 20)) fail("corrupt checkpoint (a text of " + std::to_string(n) + " bytes)");
  std::string s(n, '\0');
  bytes(s.data(), n);
  return s;
}

std::uint64_t CheckpointReader::section(const std::string& tag, std::uint32_t element_size,
                                        std::uint64_t expected_count) {
  const std::string got = text();
  if (got != tag)
    fail("section \"" + got + "\" where \"" + tag + "\" belongs (corrupt checkpoint)");
  const auto count = value<std::uint64_t>();
  const auto size = value<std::uint32_t>();
  if (size != element_size) {
    fail("section \"" + tag + "\": elements of " + std::to_string(size) + " bytes, expected " +
         std::to_string(element_size));
  }
  if (expected_count != npos && count != expected_count) {
    fail("section \"" + tag + "\": " + std::to_string(count) + " elements, expected " +
         std::to_string(expected_count));
  }
  return count;
}

void CheckpointReader::finish() {
  const std::uint64_t computed = hash_;
  std::uint64_t stored = 0;
  if (!in_.read(reinterpret_cast<char*>(&stored), sizeof stored))
    fail("truncated (no trailer: corrupt checkpoint)");
  if (stored != computed) fail("checksum mismatch (corrupt checkpoint)");
  if (in_.peek() != std::char_traits<char>::eof()) fail("bytes after the trailer");
}

void Simulation::save(CheckpointWriter& out) const {
  const Particles& P = particles_;
  out.array("x", P.x);
  out.array("v", P.v);
  out.array("mass", P.mass);
  out.array("volume0", P.volume0);
  out.array("volume", P.volume);
  out.array("L", P.L);
  out.section("state", P.size(), kStateRecord);
  for (const PointState& s : P.state) {
    out.value(s.stress);
    out.value(s.F);
    out.value(s.R);
    for (const double d : {s.plastic_strain, s.plastic_strain_rate, s.temperature,
                           s.internal_energy, s.damage, s.porosity, s.flow_internal})
      out.value(d);
    out.value(static_cast<std::uint8_t>(s.melted));
    out.value(static_cast<std::uint8_t>(s.failed));
    out.value(static_cast<std::uint8_t>(s.failure_cause));
    out.value(s.instability);
    out.value(static_cast<std::uint8_t>(s.failed_in_tension));
  }
  out.array("wave_speed", P.wave_speed);
  out.array("material", P.material);
  out.array("object", P.object);
  out.array("field", P.field);
  out.array("q", P.q);
  out.array("fault", P.fault);
  out.array("removed", P.removed);
  out.array("id", P.id);
  for (int d = 0; d < 3; ++d) out.array(kBoxTags[d], boxes_.axis(d).first_cells());
  out.value(static_cast<std::int64_t>(rebalances_));
  out.section("simulation", 1, 3 * sizeof(double) + 4 * sizeof(std::int64_t));
  out.value(time_);
  out.value(static_cast<std::int64_t>(steps_));
  out.value(max_signal_speed_);
  out.value(static_cast<std::int64_t>(failed_));
  out.value(static_cast<std::int64_t>(converted_));
  out.value(static_cast<std::int64_t>(faulted_));
  out.value(static_cast<std::int64_t>(removed_));
  const Ledger::State& l = ledger_.state();
  const std::vector<double> record = all_fields(l);  // Ledger::State::kFields order
  out.section("ledger", 1, std::uint32_t(record.size() * sizeof(double)));
  for (const double d : record) out.value(d);
  out.array("ledger_sinks", l.sinks);
}

void Simulation::load(CheckpointReader& in) {
  Particles& P = particles_;
  const std::uint64_t n = P.size();
  in.array("x", P.x, n);
  in.array("v", P.v, n);
  in.array("mass", P.mass, n);
  in.array("volume0", P.volume0, n);
  in.array("volume", P.volume, n);
  in.array("L", P.L, n);
  in.section("state", kStateRecord, n);
  for (PointState& s : P.state) {
    in.bytes(&s.stress, sizeof s.stress);
    in.bytes(&s.F, sizeof s.F);
    in.bytes(&s.R, sizeof s.R);
    for (double* d : {&s.plastic_strain, &s.plastic_strain_rate, &s.temperature, &s.internal_energy,
                      &s.damage, &s.porosity, &s.flow_internal})
      *d = in.value<double>();
    s.melted = in.value<std::uint8_t>() != 0;
    s.failed = in.value<std::uint8_t>() != 0;
    const auto cause = in.value<std::uint8_t>();
    if (cause > static_cast<std::uint8_t>(FailureCause::becker))
      in.fail("failure cause out of range");
    s.failure_cause = static_cast<FailureCause>(cause);
    s.instability = in.value<std::uint8_t>();
    s.failed_in_tension = in.value<std::uint8_t>() != 0;
  }
  in.array("wave_speed", P.wave_speed, n);
  in.array("material", P.material, n);
  in.array("object", P.object, n);
  in.array("field", P.field, n);
  in.array("q", P.q, P.q.size());
  in.array("fault", P.fault, P.fault.size());
  in.array("removed", P.removed, P.removed.size());
  in.array("id", P.id, P.id.size());
  std::array<SlabDecomposition, 3> axes;
  for (int d = 0; d < 3; ++d) {
    std::vector<int> first_cells;
    in.array(kBoxTags[d], first_cells, std::uint64_t(boxes_.axis(d).ranks()) + 1);
    if (first_cells.front() != 0 || first_cells.back() != scene_.grid.cells[std::size_t(d)] ||
        !std::is_sorted(first_cells.begin(), first_cells.end()))
      in.fail(std::string(kBoxTags[d]) + ": box boundaries out of order (corrupt checkpoint)");
    axes[std::size_t(d)] = SlabDecomposition(std::move(first_cells));
  }
  boxes_ = BoxDecomposition(std::move(axes));
  if (comm_) rebuild_grid();  // the nodes of the restored box
  rebalances_ = static_cast<long>(in.value<std::int64_t>());
  for (std::size_t p = 0; p < n; ++p) {
    if (P.material[p] >= scene_.materials.size() || P.object[p] >= scene_.objects.size() ||
        P.field[p] >= static_cast<std::size_t>(grid_.fields()))
      in.fail("particle " + std::to_string(p) + ": material, object or field out of range");
  }
  in.section("simulation", 3 * sizeof(double) + 4 * sizeof(std::int64_t), 1);
  time_ = in.value<double>();
  steps_ = static_cast<long>(in.value<std::int64_t>());
  max_signal_speed_ = in.value<double>();
  failed_ = static_cast<long>(in.value<std::int64_t>());
  converted_ = static_cast<long>(in.value<std::int64_t>());
  faulted_ = static_cast<long>(in.value<std::int64_t>());
  removed_ = static_cast<long>(in.value<std::int64_t>());
  Ledger::State l;
  std::vector<double> record(field_count<Ledger::State>());
  in.section("ledger", std::uint32_t(record.size() * sizeof(double)), 1);
  for (double& d : record) d = in.value<double>();
  set_all_fields(l, record);
  in.array("ledger_sinks", l.sinks, ledger_.sink_names().size());
  ledger_.restore(l);
}

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const RunState& run,
                      std::uint64_t scene_hash) {
  CheckpointHeader h;
  h.threads = sim.threads();
  h.ranks = sim.ranks();
  h.rank = sim.rank();
  h.particles = sim.particles().size();
  h.step = sim.steps();
  h.time = sim.time();
  h.scene_hash = scene_hash;
  h.working_directory = std::filesystem::current_path().string();
  write_file_atomically(file, [&](std::ostream& o) {
    CheckpointWriter w(o);
    write_header(w, h);
    sim.save(w);
    w.section("run", 1, 2 * sizeof(double) + 2 * sizeof(std::uint64_t));
    w.value(run.next_output);
    w.value(run.wall_time);
    w.value(run.history_bytes);
    w.value(run.history_rows);
    w.array("observables", run.observables);
    w.section("snapshots", run.snapshots.size(), 0);
    for (const auto& [t, name] : run.snapshots) {
      w.value(t);
      w.text(name);
    }
    w.finish();
  });
}

CheckpointHeader read_checkpoint_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CheckpointError(file.string() + ": cannot open (no checkpoint here?)");
  CheckpointReader r(in, file.string());
  return read_header(r);
}

namespace {

// The trailer is checked before any field is parsed: a flipped bit must read as corruption,
// not as whichever field check it happens to land on.
void verify_checksum(const std::filesystem::path& file) {
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

}  // namespace

RunState read_checkpoint(const std::filesystem::path& file, Simulation& sim) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CheckpointError(file.string() + ": cannot open (no checkpoint here?)");
  CheckpointReader r(in, file.string());
  const CheckpointHeader h = read_header(r);  // magic and version first: their own messages
  verify_checksum(file);
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
  const std::uint64_t snapshots = r.section("snapshots", 0);
  for (std::uint64_t i = 0; i < snapshots; ++i) {
    const double t = r.value<double>();
    run.snapshots.emplace_back(t, r.text());
  }
  r.finish();
  return run;
}

}  // namespace impact::mpm
