// `mpm run` and `mpm run --restart`: a Simulation driven to its end time with its outputs,
// checkpoints, signal handling, fault reports, progress line and summary, each a named piece of
// mpm/run/ (run.cpp is the loop that calls them).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "mpm/simulation/simulation.hpp"

namespace impact::mpm {

struct RunOptions {
  std::string out_dir;    ///< empty: the scene's output.directory
  int threads = 0;        ///< <= 0: OpenMP default (a restart: the checkpoint's)
  bool progress = false;  ///< a progress line on stderr
  /// SIGINT/SIGTERM write a checkpoint and stop the run cleanly (mpm run; not mpm study).
  bool handle_signals = false;
  /// Asked after every step when set: a signal number (SIGINT, SIGTERM) stops the run as that
  /// signal would (checkpoint, status "interrupted", 128 + signal); 0 goes on. The Python module
  /// polls its own signal handling with it (Ctrl-C in a notebook).
  std::function<int()> poll_interrupt;
  std::vector<FaultInjection> faults;  ///< --inject-fault
  /// A new run into a directory that holds an unfinished run's checkpoint replaces it (else
  /// refused, InputError: continue it with --restart); `mpm run --overwrite`.
  bool overwrite = false;
  /// The command line's own lines: the outcome line on stdout at the end of a completed run, and
  /// a note when a previous run's files were replaced (mpm run; not mpm study, not Python).
  bool report = false;
  /// A warning found after seeding ("FILE: /objects/...") as the command line names its source:
  /// the --set patch or base scene that set the key (support/patch_origins.hpp); unset, as it is.
  std::function<std::string(const std::string&)> attribute_warning;
  /// The ranks (docs/mpi.md); by default this process alone.
  std::reference_wrapper<const Communicator> comm = Communicator::one_rank();
};

/// Exit codes of `mpm run` (docs/mpm.md#exit-codes); 1 is a usage error, 2 bad input (also a
/// restart that is refused), 128 + N a stop by signal N (SIGINT 130, SIGTERM 143).
inline constexpr int kExitRunFailed = 3;  ///< a numerical fault or another failure
inline constexpr int kExitMemory = 4;     ///< refused to start: the memory or step estimate
inline constexpr int kExitSignalBase = 128;

/// Runs a scene to its end time writing history.csv, snapshots, summary.json, the resolved scene
/// and (output.checkpoint_interval_steps, or on SIGINT/SIGTERM with handle_signals) checkpoints.
/// The files of a previous run in the directory are removed first (output_directory.hpp); one
/// that can still be continued is refused (InputError) unless options.overwrite. Returns 0;
/// kExitRunFailed after a SolverFailure (reported on stderr, final snapshot written, status.json
/// "failed"); kExitMemory when the memory estimate exceeds the available memory or the step
/// estimate time.max_estimated_steps (start_refusal; nothing is allocated or written); 128 + signal
/// after a checkpoint on SIGINT/SIGTERM (status.json "interrupted").
int run(const Scene& scene, const RunOptions& options);

/// Continues the run in `dir` from dir/checkpoint.bin with dir/scene.json (mpm run --restart
/// DIR), writing into `dir`; options.out_dir is ignored. Throws InputError when the checkpoint is
/// missing, of another format version, corrupt, or does not belong to dir/scene.json, or when the
/// thread count it gets differs from the checkpoint's without options.threads asking for it
/// (then a warning: not bit-identical). Snapshots the checkpoint does not list (a killed run's
/// after it) are removed; every other file stays. Returns as run().
int restart(const std::string& dir, const RunOptions& options);

/// The thread count a run gets: `requested` if > 0, else OpenMP's default (at most kMaxThreads).
int run_threads(int requested);

}  // namespace impact::mpm
