#include "mpm/run/run.hpp"
#include "mpm/input/scene_reader.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "models/core/input.hpp"
#include "mpm/run/checkpoint.hpp"
#include "mpm/run/discretization_error.hpp"
#include "mpm/run/interrupt.hpp"
#include "mpm/run/memory.hpp"
#include "mpm/run/output_directory.hpp"
#include "mpm/run/output_times.hpp"
#include "mpm/run/progress.hpp"
#include "mpm/run/run_outputs.hpp"
#include "mpm/run/run_status.hpp"
#include "mpm/run/scene_fingerprint.hpp"
#include "mpm/run/seeding_check.hpp"
#include "mpm/run/step_estimate.hpp"
#include "mpm/run/summary.hpp"
#include "mpm/threads/threads.hpp"
#include "support/atomic_file.hpp"

namespace impact::mpm {

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError({file.string() + ": cannot open"});
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// `file` made absolute against the working directory (empty stays empty).
std::string absolute_path(const std::string& file) {
  if (file.empty()) return file;
  std::error_code ec;
  const fs::path absolute = fs::absolute(file, ec);
  return ec ? std::string() : absolute.lexically_normal().string();
}

// Fewer steps than this in a completed run are warned about (above).
constexpr long kFewSteps = 10;

// The mass of the particles still in play, over every rank (removed particles have none).
double mass_in_play(const Particles& P, const Communicator& comm) {
  double mass = 0.0;
  for (const double m : P.mass) mass += m;
  return comm.sum(mass);
}

// A scene warning that names a likely unit slip ("... looks like mm ...").
bool mentions_a_unit_slip(const std::vector<std::string>& warnings) {
  return std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
    return w.find(" looks like ") != std::string::npos;
  });
}

bool is_signal(const FaultInjection& f) {
  return f.kind == FaultInjection::Kind::sigterm || f.kind == FaultInjection::Kind::sigint;
}

// Wall time of the step loop over every run of a restarted one.
class WallClock {
 public:
  void restart(double before) {
    before_ = before;
    start_ = std::chrono::steady_clock::now();
  }
  double seconds() const {
    return before_ +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  double before_ = 0.0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// What every step of a run shares: the scene, where it was started from, the options, the
// directory, whether it resumes, and the ranks (null on one: no collective call).
struct RunContext {
  const Scene& scene;
  const RunOrigin& origin;
  const RunOptions& options;
  fs::path dir;
  bool resume;
  const Communicator& comm;  ///< one rank: the identity
  bool root;
  int threads;
};

// How the step loop ended: "completed", "interrupted" or "failed", the message and exit code.
struct RunEnd {
  std::string status = "completed";
  std::string message;
  int code = 0;
};

// Before anything is allocated or written: the thread warning and the start refusal
// (kExitMemory; 0: none).
int refuse_start(const RunContext& run) {
  // More threads than cores: each barrier waits for a descheduled thread (the rod at --threads
  // 256 on 2 cores took 24 s against 0.6 s).
  if (const int cores = omp_get_num_procs(); run.threads > cores && run.options.threads > 0) {
    std::cerr << "mpm: warning: --threads " << run.threads << " on " << cores
              << " cores: the threads take turns, which is slower than " << cores
              << " threads, not faster\n";
  }
  // Refuse before anything is allocated or written.
  if (const std::string refusal = start_refusal(run.scene); !refusal.empty()) {
    if (run.root) std::cerr << "mpm: " << refusal << '\n';
    return kExitMemory;
  }
  return 0;
}

// For a new run the directory made ready (an unfinished run refused, the previous run's files
// removed, scene.json written); for a restart, only there.
void ready_directory(const RunContext& run, const std::string& scene_text) {
  if (!run.resume) {
    // Every rank looks, and they agree (a collective call: none looks after rank 0 removed).
    std::string unfinished = run.options.overwrite ? "" : unfinished_run(run.dir);
    if (run.comm.max(unfinished.empty() ? 0.0 : 1.0) > 0.0 && unfinished.empty())
      unfinished = run.dir.string() + ": holds an unfinished run (rank 0 says which)";
    if (!unfinished.empty()) throw InputError({unfinished});
    // The previous run's files go before the Simulation's first collective call, so no other
    // rank writes into the directory before they are gone.
    const std::size_t removed = run.root ? clear_previous_run(run.dir) : 0;
    if (removed > 0 && run.options.report) {
      std::cerr << "mpm: replacing the previous run in " << run.dir.string() << " (" << removed
                << " file(s) removed)\n";
    }
  }
  if (run.root) {
    create_output_directory(run.dir);
    if (!run.resume)
      write_file_atomically(run.dir / "scene.json", [&](std::ostream& o) { o << scene_text; });
  }
}

// The planted faults that are not signals, by seed index on any number of ranks (1: a particle
// that does not exist; 0: none).
int inject_faults(const RunContext& run, Simulation& sim) {
  for (const FaultInjection& f : run.options.faults) {
    if (is_signal(f)) continue;
    try {
      sim.inject(f);
    } catch (const std::out_of_range& e) {
      if (run.root) std::cerr << "mpm: --inject-fault: " << e.what() << '\n';
      return 1;
    }
  }
  return 0;
}

// A restart: each rank's checkpoint loaded, the ranks agreeing on its step, the snapshots a killed
// run wrote after it removed. Returns the outputs' state at the checkpoint.
RunState resume_from_checkpoint(const RunContext& run, Simulation& sim, RunStatus& status_file) {
  const RunState resumed = read_checkpoint(checkpoint_file(run.dir, sim.rank()), sim);
  if (run.comm.min(double(sim.steps())) != run.comm.max(double(sim.steps()))) {
    throw InputError({(run.dir / kCheckpointFile).string() +
                      ": the ranks' checkpoint files are of different steps (a run stopped "
                      "while writing them)"});
  }
  if (run.root) {
    std::cerr << "mpm: restarting " << run.dir.string() << " from step " << sim.steps() << ", time "
              << sim.time() << " s (" << sim.threads() << " threads";
    if (run.comm.several()) std::cerr << ", " << run.comm.size() << " ranks";
    std::cerr << ")\n";
  }
  status_file.checkpointed(sim.steps(), sim.time());
  // Snapshots a killed run wrote after the checkpoint: the continued .pvd will not name them.
  if (run.root) remove_unlisted_snapshots(run.dir, resumed.snapshots);
  run.comm.barrier();  // gone before any rank writes a piece of the same name
  return resumed;
}

// What the step loop writes as it goes: the history row and status, a snapshot, a checkpoint.
class RunWriter {
 public:
  RunWriter(const RunContext& run, Simulation& sim, RunOutputs& outputs, RunStatus& status_file,
            const WallClock& wall, ProgressLine& progress)
      : run_(run),
        sim_(sim),
        outputs_(outputs),
        status_file_(status_file),
        wall_(wall),
        progress_(progress) {}

  void outputs(bool snapshot, long index) {
    for (const int face : outputs_.write_history(sim_, sim_.particles()))
      if (run_.root)
        std::cerr << progress_.break_line()
                  << "mpm: warning: " << outputs_.face_reach().warning(face) << '\n';
    if (run_.root) status_file_.write(sim_, wall_.seconds(), "running");
    if (snapshot) outputs_.write_snapshot(sim_.particles(), index, sim_.time());
  }

  // Every rank writes its own file; rank 0's also holds the outputs' positions.
  void checkpoint(double next_output) {
    const RunState state = outputs_.state(next_output, wall_.seconds());
    write_checkpoint(checkpoint_file(run_.dir, sim_.rank()), sim_, state, run_.origin);
    run_.comm.barrier();  // every file in place before the status names it
    status_file_.checkpointed(sim_.steps(), sim_.time());
  }

 private:
  const RunContext& run_;
  Simulation& sim_;
  RunOutputs& outputs_;
  RunStatus& status_file_;
  const WallClock& wall_;
  ProgressLine& progress_;
};

// The signal that stops every rank after this step (0: none): a pending SIGINT or SIGTERM, or one
// an injected fault raises now. A signal reaches every rank (mpirun forwards it); they stop at the
// same step.
int agreed_interrupt(const RunContext& run, const Simulation& sim) {
  for (const FaultInjection& f : run.options.faults) {
    if (is_signal(f) && f.step == sim.steps())
      raise_signal(f.kind == FaultInjection::Kind::sigint ? sigint_number() : sigterm_number());
  }
  int signal = pending_interrupt();
  if (signal == 0 && run.options.poll_interrupt) signal = run.options.poll_interrupt();
  signal = static_cast<int>(run.comm.max(double(signal)));
  return signal;
}

// Steps to the end time, writing the outputs at each interval and the checkpoints at theirs;
// stops after the step a signal arrived in (checkpoint written) or on a solver failure (final
// snapshot and history row written).
RunEnd step_loop(const RunContext& run, Simulation& sim, RunOutputs& outputs,
                 RunStatus& status_file, RunWriter& writer, double next_output,
                 ProgressLine& progress, const WallClock& wall) {
  const Scene& scene = run.scene;
  const long every = scene.output.checkpoint_interval_steps;
  FaultReport faults(progress);
  const bool removal = scene.grid.outflow == Outflow::remove;
  bool grid_emptied = false;  // warned once
  RunEnd end;
  try {
    while (!sim.finished()) {
      const double t_before = sim.time();
      outputs.before_step(sim.particles());
      const long removed = sim.step().particles.removed;
      outputs.after_step(sim.particles(), sim.time(), sim.time() - t_before);
      if (removal && !grid_emptied && run.comm.max(double(removed)) > 0.0 &&
          mass_in_play(sim.particles(), run.comm) == 0.0) {
        // A valid end (grid.outflow = remove lets bodies go), but what follows is an empty grid.
        grid_emptied = true;
        if (run.root)
          std::cerr << progress.break_line() << "mpm: warning: every particle has left the grid "
                    << "(grid.outflow = remove) by step " << sim.steps() << ", t = " << sim.time()
                    << " s; the run goes on to time.max_time " << scene.time.max_time
                    << " s with nothing left to move\n";
      }
      faults.report(sim);
      if (sim.time() >= next_output * (1.0 - 1e-12) || sim.finished()) {
        writer.outputs(true, sim.steps());
        next_output = next_output_after(next_output, sim.time(), scene.output.interval);
      }
      if (every > 0 && sim.steps() % every == 0 && !sim.finished()) writer.checkpoint(next_output);
      const int signal = agreed_interrupt(run, sim);
      if (signal != 0 && !sim.finished()) {
        std::ostringstream m;
        m.precision(9);
        m << "interrupted by " << signal_name(signal) << " after step " << sim.steps() << ", time "
          << sim.time() << " s";
        if (status_file.checkpoint_step() != sim.steps()) writer.checkpoint(next_output);
        m << ": checkpoint " << (run.dir / kCheckpointFile).string() << "; continue with: "
          << (run.comm.several() ? "mpirun -np " + std::to_string(run.comm.size()) + " " : "")
          << "mpm run --restart " << run.dir.string();
        end = {"interrupted", m.str(), kExitSignalBase + signal};
        if (run.root) std::cerr << progress.break_line() << "mpm: " << end.message << '\n';
        break;
      }
      progress.update(sim);
    }
  } catch (const SolverFailure& e) {  // on every rank alike: the ranks agree on a failure
    end = {"failed", e.what(), kExitRunFailed};
    if (run.root) std::cerr << progress.break_line() << "mpm: run failed: " << end.message << '\n';
    outputs.write_snapshot(sim.particles(), sim.steps() + 1, sim.time());
    outputs.write_history(sim, sim.particles());  // a face reached now: in the summary
    if (run.root) status_file.write(sim, wall.seconds(), "running");
  } catch (const std::exception& e) {  // e.g. an output that cannot be written: say so, re-throw
    try {
      if (run.root) status_file.write(sim, wall.seconds(), "failed", e.what());
    } catch (const std::exception&) {  // keep the original error
    }
    throw;
  }
  return end;
}

// Each phase's seconds (per rank with several), and on several ranks the load of each: the
// particles it holds at the end, its time in MPI calls (waiting for the others and moving data),
// its memory, its halo traffic per step since `first_step`, and the boxes (docs/mpi.md).
// Collective.
std::pair<Json, Json> phases_and_load(const RunContext& run, const Simulation& sim,
                                      long first_step) {
  Json phases = Json::object();
  for (const auto& [name, phase] : PhaseTimes::kPhases) {
    const double mine = sim.phase_totals().*phase;
    phases[name] = run.comm.several() ? Json(run.comm.gather_all(mine)) : Json(mine);
  }
  if (!run.comm.several()) return {phases, Json()};
  const Communicator& comm = run.comm;
  const double steps = double(std::max(sim.steps() - first_step, 1L));
  const std::vector<double> held = comm.gather_all(double(sim.particles().size()));
  const std::vector<double> in_mpi = comm.gather_all(comm.seconds_in_mpi());
  const std::vector<double> peak = comm.gather_all(peak_resident_memory().value_or(0.0) / 1e6);
  const std::vector<double> bytes = comm.gather_all(double(comm.exchanged_bytes()) / steps);
  const std::vector<double> messages = comm.gather_all(double(comm.exchanged_messages()) / steps);
  Json load = {{"particles_at_end", held},
               {"seconds_in_mpi [s]", in_mpi},
               {"peak_resident_memory [MB]", peak},
               {"halo_bytes_sent_per_step [B]", bytes},
               {"halo_messages_sent_per_step", messages},
               {"rebalances", sim.rebalances()},
               {"boxes",
                {{"ranks_per_axis", sim.boxes().ranks_per_axis()},
                 {"x", sim.boxes().axis(0).first_cells()},
                 {"y", sim.boxes().axis(1).first_cells()},
                 {"z", sim.boxes().axis(2).first_cells()}}}};
  return {phases, load};
}

// The lines a run ends with on the terminal: a warning when it completed in too few steps to
// resolve anything, and the outcome line (steps, wall time, energy error, failed particles).
void report_end(const RunContext& run, const Simulation& sim, const Json& summary,
                const RunEnd& end, double seconds) {
  const Scene& scene = run.scene;
  // A run that ends in a handful of steps resolves nothing: almost always lengths or times typed
  // in other units (a grid in mm makes the stable step a thousand times too long).
  if (run.root && end.status == "completed" && sim.steps() < kFewSteps) {
    std::cerr << "mpm: warning: the run completed in " << sim.steps()
              << " step(s) to t = " << sim.time() << " s (time.max_time " << scene.time.max_time
              << " s): too few to resolve a wave or an impact; check the scene's units (SI: "
                 "lengths in m, times in s, speeds in m/s)"
              << (mentions_a_unit_slip(scene.warnings) ? ", as the warnings above suggest" : "")
              << '\n';
  }
  // A graded grid's particle seeded in a coarse cell, among finer ones: its box was narrowed to
  // the two cells about it (shape/tartan.hpp; docs/scenes.md#graded-grids). Said, never silent.
  if (run.root && sim.narrowed_particle_steps() > 0)
    std::cerr << "mpm: warning: " << sim.narrowed_particle_steps()
              << " particle-steps narrowed a particle's uGIMP box to the finer cells it had "
                 "entered (grid.refine: coarse-seeded material inside the refined box; "
                 "summary.json narrowed_particle_steps); widen the refined box to hold the "
                 "material from the start\n";
  if (!run.options.report || end.status != "completed") return;
  std::ostringstream line;
  line.precision(4);
  line << "mpm run: completed " << sim.steps() << " steps to t = " << sim.time() << " s in "
       << seconds << " s wall, energy_error " << sim.ledger().row().energy_error;
  // Failed particles change what the run measures (a Taylor rod with 480 of 672 failed said
  // only "completed"): named here, their causes in summary.json.
  const long failed = summary.value("failed_particles", 0L);
  if (failed > 0)
    line << ", " << failed << " of " << summary.value("particles", 0L)
         << " particles failed (summary.json failed_by_cause)";
  line << "; results in " << run.dir.string() << " (summary.json, history.csv"
       << (scene.output.snapshots ? ", particles.pvd" : "") << ")\n";
  std::cout << line.str() << std::flush;
}

// The run of run() and restart() (`resume`: from dir/checkpoint.bin): refuse or ready the
// directory, (resume,) the step
// loop with its outputs, checkpoints, signals and reports, then the summary. On several ranks
// every rank steps its box and writes its snapshot piece and checkpoint; the gauges, observables
// and the summary are reduced over the ranks, and rank 0 writes history.csv, the .pvtu/.pvd and
// the summary. No rank ever holds another's particles. `scene_text`: DIR/scene.json as the first
// run wrote it (a new run writes it); `origin`: its hash, working directory and the scene file it
// was started from (empty: none, else absolute), whose ladder table gives the summary's error
// bar. Every checkpoint carries `origin` unchanged, so a restarted run can be restarted again.
int run_in(const Scene& scene, const std::string& scene_text, const RunOrigin& origin,
           const RunOptions& options, const fs::path& dir, bool resume) {
  const Communicator& comm = options.comm;
  const RunContext run{scene,  origin, options,     dir,
                       resume, comm,   comm.root(), run_threads(options.threads)};
  if (const int code = refuse_start(run)) return code;
  // Before the directory is cleared (a material file may lie in it): the material files as the
  // run reads them.
  const std::string fingerprint = scene_fingerprint(scene.resolved);
  ready_directory(run, scene_text);
  WallClock wall;
  Simulation sim(scene, run.threads, comm);
  if (resume && sim.threads() != run.threads) {
    throw InputError({(dir / kCheckpointFile).string() + ": needs " + std::to_string(run.threads) +
                      " threads, this process gets " + std::to_string(sim.threads())});
  }
  if (!resume)  // collective: every rank's particles summed
    for (const std::string& w : seeding_warnings(scene, sim.particles(), comm))
      if (run.root)
        std::cerr << "mpm: warning: "
                  << (run.options.attribute_warning ? run.options.attribute_warning(w) : w) << '\n';
  if (const int code = inject_faults(run, sim)) return code;
  // Every rank keeps its outputs: on several ranks the gauges, observables and snapshots read the
  // particles each rank holds (collective calls), rank 0 writes history.csv and the .pvd.
  RunOutputs outputs(scene, sim.particles(), sim.communicator());
  RunStatus status_file(dir,
                        scene.physics.on_numerical_fault == NumericalFaultAction::fail_particle);
  const RunState resumed = resume ? resume_from_checkpoint(run, sim, status_file) : RunState{};
  const double paths_start = resume ? sim.time() : 0.0;  // after a restart the paths begin there
  outputs.open(scene, dir, sim.particles(), sim.ledger(), resume ? &resumed : nullptr);
  ProgressLine progress(options.progress && run.root);
  RunWriter writer(run, sim, outputs, status_file, wall, progress);
  if (!resume) writer.outputs(true, sim.steps());
  const InterruptHandlers handlers(
      options.handle_signals ||
      std::any_of(options.faults.begin(), options.faults.end(), is_signal));
  wall.restart(resume ? resumed.wall_time : 0.0);
  const long first_step = sim.steps();  // this process's steps: the halo traffic's divisor
  progress.start();
  const RunEnd end =
      step_loop(run, sim, outputs, status_file, writer,
                resume ? resumed.next_output : scene.output.interval, progress, wall);
  if (end.status != "interrupted") progress.end();
  if (sim.faulted_particles() > 0 && run.root) {
    std::cerr << "mpm: " << sim.faulted_particles()
              << " particle(s) flagged failed by numerical faults (physics.on_numerical_fault = "
                 "fail_particle)\n";
  }
  auto [phases, load] = phases_and_load(run, sim, first_step);
  const double seconds = wall.seconds();
  Json summary = run_summary(sim, sim.particles(), end.status, end.message, seconds,
                             outputs.observables(), outputs.gauge_extrema(), &outputs.paths());
  summary["scene_fingerprint"] = fingerprint;
  summary["material_reached_faces"] = outputs.face_reach().summary();
  if (!run.root) return end.code;
  outputs.write_paths(dir, scene, paths_start);  // also after a failure: the path up to it
  summary["phase_seconds [s]"] = phases;
  if (comm.several()) summary["ranks_load"] = load;
  // Last: the ladder's pointers read the summary as written.
  if (auto error = discretization_error(origin.scene_file, fingerprint, summary))
    summary["discretization_error"] = std::move(*error);
  write_file_atomically(dir / "summary.json",
                        [&](std::ostream& o) { o << summary.dump(2) << '\n'; });
  status_file.write(sim, seconds, end.status, end.message);  // last: every file is then in place
  report_end(run, sim, summary, end, seconds);
  return end.code;
}

}  // namespace

int run_threads(int requested) {
  return std::min(requested > 0 ? requested : omp_get_max_threads(), kMaxThreads);
}

int run(const Scene& scene, const RunOptions& options) {
  const std::string scene_text = scene.resolved.dump(2) + '\n';
  RunOrigin origin;
  origin.scene_hash = fnv1a(scene_text.data(), scene_text.size());
  origin.working_directory = fs::current_path().string();
  origin.scene_file = absolute_path(scene.file);
  return run_in(
      scene, scene_text, origin, options,
      options.out_dir.empty() ? fs::path(scene.output.directory) : fs::path(options.out_dir),
      false);
}

int restart(const std::string& directory, const RunOptions& options) {
  const fs::path dir(directory);
  const fs::path file = dir / kCheckpointFile;
  std::error_code ec;
  if (!fs::exists(dir, ec))
    throw InputError(
        {directory + ": no such directory (--restart takes the directory a run wrote)"});
  if (!fs::is_directory(dir, ec)) {
    throw InputError({directory +
                      ": not a directory (--restart takes the directory a run wrote, which holds "
                      "checkpoint.bin and scene.json)"});
  }
  if (const std::string done = completed_run(dir); !done.empty()) throw InputError({done});
  if (!fs::exists(file)) {
    throw InputError({file.string() +
                      ": no checkpoint (mpm run writes one every "
                      "output.checkpoint_interval_steps steps and on SIGINT/SIGTERM)"});
  }
  CheckpointHeader header;
  try {
    header = read_checkpoint_header(file);
  } catch (const CheckpointError& e) {
    throw InputError({e.what()});
  }
  // Each rank continues its own box: the run's rank count, not another (the split would differ).
  const int ranks = options.comm.get().size();
  if (header.ranks != ranks) {
    try {
      verify_checkpoint_checksum(file);
    } catch (const CheckpointError& e) {
      throw InputError({e.what()});
    }
    throw InputError({file.string() + ": written by a run on " + std::to_string(header.ranks) +
                      " rank(s), this restart has " + std::to_string(ranks) +
                      " (restart on the run's rank count: " +
                      (header.ranks > 1 ? "mpirun -np " + std::to_string(header.ranks) + " mpm"
                                        : "mpm without mpirun") +
                      " run --restart " + directory + ")"});
  }
  // The scene is the directory's scene.json, as the checkpointed run wrote it.
  const fs::path scene_file = dir / "scene.json";
  const std::string text = read_text(scene_file);
  if (fnv1a(text.data(), text.size()) != header.scene_hash) {
    throw InputError({scene_file.string() +
                      ": changed since the checkpoint was written (it is not "
                      "the scene of " +
                      file.string() + ")"});
  }
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const std::exception& e) {
    throw InputError({scene_file.string() + ": " + e.what()});
  }
  // Material paths in scene.json are relative to the working directory of the run.
  if (doc.contains("materials") && doc["materials"].is_object()) {
    for (auto& item : doc["materials"].items()) {
      Json& m = item.value();
      if (!m.is_object() || !m.contains("file") || !m["file"].is_string()) continue;
      const fs::path p(m["file"].get<std::string>());
      if (p.is_relative())
        m["file"] = (fs::path(header.working_directory) / p).lexically_normal().string();
    }
  }
  const Scene scene = read_scene(doc, scene_file.string());
  for (const std::string& w : scene.warnings) std::cerr << "mpm: warning: " << w << '\n';
  RunOptions o = options;
  if (options.threads <= 0) {
    o.threads = header.threads;
  } else if (options.threads != header.threads) {
    std::cerr << "mpm: warning: --threads " << options.threads << " differs from the checkpoint's "
              << header.threads
              << " threads: the continued run is not bit-identical to an "
                 "uninterrupted one (round-off differences, docs/mpm.md#threads-and-determinism)\n";
  }
  if (run_threads(o.threads) != o.threads) {
    throw InputError(
        {file.string() + ": written with " + std::to_string(header.threads) +
         " threads, this process gets " + std::to_string(run_threads(o.threads)) +
         " (results would not be bit-identical; --threads N overrides with a warning)"});
  }
  // The first run's origin, unchanged: the next restart checks scene.json against the same hash
  // and resolves the material paths against the same directory.
  RunOrigin origin;
  origin.scene_hash = header.scene_hash;
  origin.working_directory = header.working_directory;
  origin.scene_file = header.scene_file;
  try {
    return run_in(scene, text, origin, o, dir, true);
  } catch (const CheckpointError& e) {
    throw InputError({e.what()});
  }
}

}  // namespace impact::mpm
