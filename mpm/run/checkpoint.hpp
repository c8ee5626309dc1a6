// Checkpoints of `mpm run` (docs/mpm.md#checkpoint-and-restart): DIR/checkpoint.bin holds
// everything the next steps depend on, so that `mpm run --restart DIR` continues bit for bit as
// the uninterrupted run would (same thread count):
//   - every particle array (x, v, mass, volumes, L, the whole PointState, wave speed, material,
//     object, velocity field, artificial-viscosity q, numerical-fault flags),
//   - the Simulation's time, step, signal speed (the next dt), failure/conversion/fault counters,
//   - every ledger accumulator,
//   - the run loop's next output time, the bytes and rows of history.csv written so far, the
//     observables' running maxima and the gauges' extrema, the .pvd entries, the wall time so far.
// The grid holds nothing across steps (it is rebuilt from the particles every step), nor do the
// stencils.
// Format (little-endian, native doubles): the 16-byte magic "IMPACT-MPM-CKPT\n", u32 format
// version, u32 byte-order mark 0x01020304, u32 sizeof(double), u64 the file's length in bytes and
// its bitwise complement (a file cut short reads as truncated, a flipped bit there as corrupt), the
// header (thread count, particle count, step, time, FNV-1a hash of DIR/scene.json, the working
// directory of the first run, the scene file it was started from: a restart writes them as it read
// them, so that it can be repeated), then tagged sections (u32 tag length, tag, u64 element count,
// u32 element size, the elements), and last the u64 FNV-1a hash of every byte before it. Written
// through write_file_atomically (checkpoint.bin.tmp, then a rename): a kill while writing leaves
// the previous checkpoint.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "mpm/output/checkpoint_stream.hpp"

namespace impact::mpm {

class Simulation;

// 2: outflow, no face work; 3: failure cause; 4: particle ids (ranks); 5: the flow-stress law's
// internal variable (PointState::flow_internal); 6: the boxes of the domain decomposition (three
// axes' boundaries, was the slabs along x); 7: the gauges' extrema and the scene file's path;
// 8: the file's length, the faces material reached; 9: the ledger's peak energy input; 10: the
// particles' reference positions (Particles::X, for body forces); 11: the particles' uGIMP
// half-widths on a graded grid (Particles::half_width; an empty section on a uniform one); 12:
// the anchors of friction at the particles (Particles::friction_anchor; empty without it); 13:
// the velocities the dashpots at the particles damp (Particles::damper_velocity; likewise)
inline constexpr std::uint32_t kCheckpointVersion = 13;
inline constexpr const char* kCheckpointFile = "checkpoint.bin";
/// Rank r's checkpoint in DIR: checkpoint.bin for rank 0 (and a one-rank run),
/// checkpoint.rank<r>.bin for the others.
std::filesystem::path checkpoint_file(const std::filesystem::path& dir, int rank);

/// The header: what a restart checks before building anything.
struct CheckpointHeader {
  std::uint32_t version = kCheckpointVersion;
  std::uint64_t file_bytes = 0;  ///< the whole file's length, the trailer included
  std::int32_t threads = 0;
  std::int32_t ranks = 1;  ///< of the run (docs/mpi.md): one file per rank
  std::int32_t rank = 0;   ///< whose particles this file holds
  std::uint64_t particles = 0;
  std::int64_t step = 0;
  double time = 0.0;
  std::uint64_t scene_hash = 0;  ///< fnv1a of DIR/scene.json as written
  /// Of the first run (material paths in scene.json are relative to it); restarts keep it.
  std::string working_directory;
  /// The scene file the run was started from, absolute (its ladder table is looked for beside
  /// it, mpm/run/discretization_error.hpp); empty when the run had none.
  std::string scene_file;
};

/// The run loop's state beside the Simulation's.
struct RunState {
  double next_output = 0.0;         ///< next history row / snapshot time [s]
  std::uint64_t history_bytes = 0;  ///< history.csv so far (header included)
  std::uint64_t history_rows = 0;
  std::vector<double> observables;                        ///< Observables::state()
  std::vector<double> gauge_extrema;                      ///< GaugeExtrema::state()
  std::vector<double> faces_reached;                      ///< FaceReach::state()
  std::vector<std::pair<double, std::string>> snapshots;  ///< .pvd entries
  double wall_time = 0.0;                                 ///< [s] of the step loop so far, all runs
};

/// Where a run comes from, the same in every checkpoint of it however often it is restarted:
/// the hash of DIR/scene.json, the working directory of the first run and the scene file it was
/// started from (CheckpointHeader).
struct RunOrigin {
  std::uint64_t scene_hash = 0;
  std::string working_directory;
  std::string scene_file;
};

/// Writes `file` atomically from the Simulation and the run state.
void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const RunState& run,
                      const RunOrigin& origin);
/// Reads the header only (magic, version, byte order first) and checks the file's length against
/// it; throws CheckpointError ("truncated: N of M bytes" for a file cut short).
CheckpointHeader read_checkpoint_header(const std::filesystem::path& file);
/// Checks `file`'s trailer (a checksum of every byte before it); throws CheckpointError
/// ("checksum mismatch (corrupt checkpoint)"). A header field that refuses a restart is only
/// believed once this passes: a flipped bit must read as corruption.
void verify_checkpoint_checksum(const std::filesystem::path& file);
/// Loads `file` into `sim` (built from the same scene with the checkpoint's thread count, on the
/// same rank count: each rank its own file) and returns the run state; throws CheckpointError
/// (the Simulation is then unusable).
RunState read_checkpoint(const std::filesystem::path& file, Simulation& sim);

}  // namespace impact::mpm
