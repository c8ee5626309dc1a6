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
#include "mpm/run/progress.hpp"
#include "mpm/run/run_outputs.hpp"
#include "mpm/run/run_status.hpp"
#include "mpm/run/scene_fingerprint.hpp"
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
double mass_in_play(const Particles& P, const Communicator* comm) {
  double mass = 0.0;
  for (const double m : P.mass) mass += m;
  return comm ? comm->sum(mass) : mass;
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

// The run of run() and restart() (`resume`: from dir/checkpoint.bin): set-up, the step loop with
// its outputs, checkpoints, signals and reports, then the summary. On several ranks every rank
// steps its box and writes its snapshot piece and checkpoint; the gauges, observables and the
// summary are reduced over the ranks, and rank 0 writes history.csv, the .pvtu/.pvd and the
// summary. No rank ever holds another's particles. `scene_text`: DIR/scene.json as the first run
// wrote it (a new run writes it); `origin`: its hash, working directory and the scene file it was
// started from (empty: none, else absolute), whose ladder table gives the summary's error bar.
// Every checkpoint carries `origin` unchanged, so a restarted run can be restarted again.
int run_in(const Scene& scene, const std::string& scene_text, const RunOrigin& origin,
           const RunOptions& options, const fs::path& dir, bool resume) {
  const Communicator* comm =
      options.comm != nullptr && options.comm->size() > 1 ? options.comm : nullptr;
  const bool root = comm == nullptr || comm->root();
  const int threads = run_threads(options.threads);
  // More threads than cores: each barrier waits for a descheduled thread (the rod at --threads
  // 256 on 2 cores took 24 s against 0.6 s).
  if (const int cores = omp_get_num_procs(); threads > cores && options.threads > 0) {
    std::cerr << "mpm: warning: --threads " << threads << " on " << cores
              << " cores: the threads take turns, which is slower than " << cores
              << " threads, not faster\n";
  }
  // Refuse before anything is allocated or written.
  if (const std::string refusal = start_refusal(scene); !refusal.empty()) {
    if (root) std::cerr << "mpm: " << refusal << '\n';
    return kExitMemory;
  }
  // Before the run: the material files as the run read them.
  const std::string fingerprint = scene_fingerprint(scene.resolved);
  if (!resume) {
    // Every rank looks, and they agree (a collective call: none looks after rank 0 removed).
    std::string unfinished = options.overwrite ? "" : unfinished_run(dir);
    if (comm && comm->max(unfinished.empty() ? 0.0 : 1.0) > 0.0 && unfinished.empty())
      unfinished = dir.string() + ": holds an unfinished run (rank 0 says which)";
    if (!unfinished.empty()) throw InputError({unfinished});
    // The previous run's files go before the Simulation's first collective call, so no other
    // rank writes into the directory before they are gone.
    const std::size_t removed = root ? clear_previous_run(dir) : 0;
    if (removed > 0 && options.report) {
      std::cerr << "mpm: replacing the previous run in " << dir.string() << " (" << removed
                << " file(s) removed)\n";
    }
  }
  if (root) {
    create_output_directory(dir);
    if (!resume)
      write_file_atomically(dir / "scene.json", [&](std::ostream& o) { o << scene_text; });
  }
  WallClock wall;
  Simulation sim(scene, threads, comm);
  if (resume && sim.threads() != threads) {
    throw InputError({(dir / kCheckpointFile).string() + ": needs " + std::to_string(threads) +
                      " threads, this process gets " + std::to_string(sim.threads())});
  }
  for (const FaultInjection& f : options.faults) {
    if (is_signal(f)) continue;
    try {
      sim.inject(f);  // the particle's seed index, on any number of ranks
    } catch (const std::out_of_range& e) {
      if (root) std::cerr << "mpm: --inject-fault: " << e.what() << '\n';
      return 1;
    }
  }
  // Every rank keeps its outputs: on several ranks the gauges, observables and snapshots read the
  // particles each rank holds (collective calls), rank 0 writes history.csv and the .pvd.
  RunOutputs outputs(scene, sim.particles(), sim.communicator());
  RunStatus status_file(dir,
                        scene.physics.on_numerical_fault == NumericalFaultAction::fail_particle);
  RunState resumed;
  double paths_start = 0.0;  // after a restart: the paths begin there
  if (resume) {
    resumed = read_checkpoint(checkpoint_file(dir, sim.rank()), sim);
    if (comm && comm->min(double(sim.steps())) != comm->max(double(sim.steps()))) {
      throw InputError({(dir / kCheckpointFile).string() +
                        ": the ranks' checkpoint files are of different steps (a run stopped "
                        "while writing them)"});
    }
    if (root) {
      std::cerr << "mpm: restarting " << dir.string() << " from step " << sim.steps() << ", time "
                << sim.time() << " s (" << sim.threads() << " threads";
      if (comm) std::cerr << ", " << comm->size() << " ranks";
      std::cerr << ")\n";
    }
    paths_start = sim.time();
    status_file.checkpointed(sim.steps(), sim.time());
    // Snapshots a killed run wrote after the checkpoint: the continued .pvd will not name them.
    if (root) remove_unlisted_snapshots(dir, resumed.snapshots);
    if (comm) comm->barrier();  // gone before any rank writes a piece of the same name
  }
  outputs.open(scene, dir, sim.particles(), sim.ledger(), resume ? &resumed : nullptr);
  ProgressLine progress(options.progress && root);
  const auto write_outputs = [&](bool snapshot, long index) {
    for (const int face : outputs.write_history(sim, sim.particles()))
      if (root)
        std::cerr << progress.break_line() << "mpm: warning: " << outputs.face_reach().warning(face)
                  << '\n';
    if (root) status_file.write(sim, wall.seconds(), "running");
    if (snapshot) outputs.write_snapshot(sim.particles(), index, sim.time());
  };
  if (!resume) write_outputs(true, sim.steps());
  double next_output = resume ? resumed.next_output : scene.output.interval;
  // Every rank writes its own file; rank 0's also holds the outputs' positions.
  const auto checkpoint = [&] {
    const RunState state = outputs.state(next_output, wall.seconds());
    write_checkpoint(checkpoint_file(dir, sim.rank()), sim, state, origin);
    if (comm) comm->barrier();  // every file in place before the status names the checkpoint
    status_file.checkpointed(sim.steps(), sim.time());
  };
  const long every = scene.output.checkpoint_interval_steps;
  const InterruptHandlers handlers(
      options.handle_signals ||
      std::any_of(options.faults.begin(), options.faults.end(), is_signal));
  FaultReport faults(progress);
  wall.restart(resume ? resumed.wall_time : 0.0);
  const long first_step = sim.steps();  // this process's steps: the halo traffic's divisor
  progress.start();
  const bool removal = scene.grid.outflow == Outflow::remove;
  bool grid_emptied = false;  // warned once
  std::string status = "completed", message;
  int code = 0;
  try {
    while (!sim.finished()) {
      const double t_before = sim.time();
      outputs.before_step(sim.particles());
      const long removed = sim.step().particles.removed;
      outputs.after_step(sim.particles(), sim.time(), sim.time() - t_before);
      if (removal && !grid_emptied && (comm ? comm->max(double(removed)) : double(removed)) > 0.0 &&
          mass_in_play(sim.particles(), comm) == 0.0) {
        // A valid end (grid.outflow = remove lets bodies go), but what follows is an empty grid.
        grid_emptied = true;
        if (root)
          std::cerr << progress.break_line() << "mpm: warning: every particle has left the grid "
                    << "(grid.outflow = remove) by step " << sim.steps() << ", t = " << sim.time()
                    << " s; the run goes on to time.max_time " << scene.time.max_time
                    << " s with nothing left to move\n";
      }
      faults.report(sim);
      if (sim.time() >= next_output * (1.0 - 1e-12) || sim.finished()) {
        write_outputs(true, sim.steps());
        while (next_output <= sim.time() * (1.0 + 1e-12)) next_output += scene.output.interval;
      }
      if (every > 0 && sim.steps() % every == 0 && !sim.finished()) checkpoint();
      for (const FaultInjection& f : options.faults) {
        if (is_signal(f) && f.step == sim.steps()) {
          raise_signal(f.kind == FaultInjection::Kind::sigint ? sigint_number() : sigterm_number());
        }
      }
      // A signal reaches every rank (mpirun forwards it); they stop at the same step.
      int signal = pending_interrupt();
      if (signal == 0 && options.poll_interrupt) signal = options.poll_interrupt();
      if (comm) signal = static_cast<int>(comm->max(double(signal)));
      if (signal != 0 && !sim.finished()) {
        std::ostringstream m;
        m.precision(9);
        m << "interrupted by " << signal_name(signal) << " after step " << sim.steps() << ", time "
          << sim.time() << " s";
        if (status_file.checkpoint_step() != sim.steps()) checkpoint();
        m << ": checkpoint " << (dir / kCheckpointFile).string()
          << "; continue with: " << (comm ? "mpirun -np " + std::to_string(comm->size()) + " " : "")
          << "mpm run --restart " << dir.string();
        status = "interrupted";
        message = m.str();
        code = kExitSignalBase + signal;
        if (root) std::cerr << progress.break_line() << "mpm: " << message << '\n';
        break;
      }
      progress.update(sim);
    }
  } catch (const SolverFailure& e) {  // on every rank alike: the ranks agree on a failure
    status = "failed";
    message = e.what();
    code = kExitRunFailed;
    if (root) std::cerr << progress.break_line() << "mpm: run failed: " << message << '\n';
    outputs.write_snapshot(sim.particles(), sim.steps() + 1, sim.time());
    outputs.write_history(sim, sim.particles());  // a face reached now: in the summary
    if (root) status_file.write(sim, wall.seconds(), "running");
  } catch (const std::exception& e) {  // e.g. an output that cannot be written: say so, re-throw
    try {
      if (root) status_file.write(sim, wall.seconds(), "failed", e.what());
    } catch (const std::exception&) {  // keep the original error
    }
    throw;
  }
  if (status != "interrupted") progress.end();
  if (sim.faulted_particles() > 0 && root) {
    std::cerr << "mpm: " << sim.faulted_particles()
              << " particle(s) flagged failed by numerical faults (physics.on_numerical_fault = "
                 "fail_particle)\n";
  }
  // Per rank: the particles it holds at the end and its time in MPI calls (waiting for the others
  // and moving data): the load balance (docs/mpi.md).
  std::vector<double> held, in_mpi, peak, halo_bytes, halo_messages;
  Json phases = Json::object();  // each phase's seconds (per rank with several)
  for (const auto& [name, phase] : PhaseTimes::kPhases) {
    const double mine = sim.phase_totals().*phase;
    phases[name] = comm ? Json(comm->gather_all(mine)) : Json(mine);
  }
  if (comm) {
    held = comm->gather_all(double(sim.particles().size()));
    in_mpi = comm->gather_all(comm->seconds_in_mpi());
    peak = comm->gather_all(peak_resident_memory().value_or(0.0) / 1e6);
    const double steps = double(std::max(sim.steps() - first_step, 1L));
    halo_bytes = comm->gather_all(double(comm->exchanged_bytes()) / steps);
    halo_messages = comm->gather_all(double(comm->exchanged_messages()) / steps);
  }
  const double seconds = wall.seconds();
  Json summary = run_summary(sim, sim.particles(), status, message, seconds, outputs.observables(),
                             outputs.gauge_extrema(), &outputs.paths());
  summary["scene_fingerprint"] = fingerprint;
  summary["material_reached_faces"] = outputs.face_reach().summary();
  if (!root) return code;
  outputs.write_paths(dir, scene, paths_start);  // also after a failure: the path up to it
  summary["phase_seconds [s]"] = phases;
  if (comm) {
    summary["ranks_load"] = {{"particles_at_end", held},
                             {"seconds_in_mpi [s]", in_mpi},
                             {"peak_resident_memory [MB]", peak},
                             {"halo_bytes_sent_per_step [B]", halo_bytes},
                             {"halo_messages_sent_per_step", halo_messages},
                             {"rebalances", sim.rebalances()},
                             {"boxes",
                              {{"ranks_per_axis", sim.boxes().ranks_per_axis()},
                               {"x", sim.boxes().axis(0).first_cells()},
                               {"y", sim.boxes().axis(1).first_cells()},
                               {"z", sim.boxes().axis(2).first_cells()}}}};
  }
  // Last: the ladder's pointers read the summary as written.
  if (auto error = discretization_error(origin.scene_file, fingerprint, summary))
    summary["discretization_error"] = std::move(*error);
  write_file_atomically(dir / "summary.json",
                        [&](std::ostream& o) { o << summary.dump(2) << '\n'; });
  status_file.write(sim, seconds, status, message);  // last: every file is then in place
  // A run that ends in a handful of steps resolves nothing: almost always lengths or times typed
  // in other units (a grid in mm makes the stable step a thousand times too long).
  if (root && status == "completed" && sim.steps() < kFewSteps) {
    std::cerr << "mpm: warning: the run completed in " << sim.steps()
              << " step(s) to t = " << sim.time() << " s (time.max_time " << scene.time.max_time
              << " s): too few to resolve a wave or an impact; check the scene's units (SI: "
                 "lengths in m, times in s, speeds in m/s)"
              << (mentions_a_unit_slip(scene.warnings) ? ", as the warnings above suggest" : "")
              << '\n';
  }
  if (options.report && status == "completed") {
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
    line << "; results in " << dir.string() << " (summary.json, history.csv"
         << (scene.output.snapshots ? ", particles.pvd" : "") << ")\n";
    std::cout << line.str() << std::flush;
  }
  return code;
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
  const int ranks = options.comm ? options.comm->size() : 1;
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
