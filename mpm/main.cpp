// mpm: the explicit MPM solver's command line.
//   mpm run SCENE.json [--out DIR] [--threads N] [--set JSON]... [--progress]
//           [--inject-fault KIND:STEP[:PARTICLE]]...
//   mpm run --restart DIR [--threads N]
//   mpm check SCENE.json [--threads N] [--set JSON]...
//   mpm study SCENE_DIR --out DIR [--threads N] [--cases LIST] [--no-plot]
// Exit codes: 0 success, 1 usage error, 2 input error (file + JSON key path; a refused restart),
// 3 run failure (numerical fault), 4 memory estimate above the available memory, 128 + signal
// after a checkpoint on SIGINT (130) or SIGTERM (143).
#include <unistd.h>

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "mpm/run/memory.hpp"
#include "mpm/run/run.hpp"
#include "mpm/run/summary.hpp"
#include "mpm/solver.hpp"
#include "mpm/study/study.hpp"

namespace {

const char* kUsage =
    "usage: mpm run SCENE.json [--out DIR] [--threads N] [--set JSON]... [--progress]\n"
    "               [--inject-fault KIND:STEP[:PARTICLE]]...\n"
    "       mpm run --restart DIR [--threads N] [--progress]\n"
    "       mpm check SCENE.json [--threads N] [--set JSON]...\n"
    "       mpm study SCENE_DIR --out DIR [--threads N] [--cases case01,case04] [--no-plot]\n"
    "       mpm --help\n"
    "run:   runs the scene; writes DIR/history.csv (energy and momentum ledger), DIR/particles/\n"
    "       step_NNNNNN.vtu + DIR/particles.pvd (ParaView), DIR/summary.json, DIR/scene.json\n"
    "       (the resolved scene), DIR/status.json (step reached; completed, failed or\n"
    "       interrupted), DIR/checkpoint.bin (every output.checkpoint_interval_steps steps, and\n"
    "       on SIGINT/SIGTERM, after which the run stops with 128 + the signal number).\n"
    "       DIR defaults to the scene's output.directory. Refuses to start (exit 4) when the\n"
    "       memory estimate exceeds the available memory.\n"
    "       --set JSON (run, check; repeatable): a JSON merge patch over the scene (after its\n"
    "       extends) before validation. --progress: the progress line also when stderr is not\n"
    "       a terminal (a batch job's log).\n"
    "       --restart DIR continues DIR's run from DIR/checkpoint.bin with DIR/scene.json and\n"
    "       the checkpoint's thread count: bit-identical to an uninterrupted run (--threads N\n"
    "       overrides, with a warning that it no longer is).\n"
    "       --inject-fault (developer, repeatable): nan:STEP:P (P's updated stress is NaN),\n"
    "       nan_velocity:STEP:P, outside:STEP:P (P moved beyond the x+ face), jacobian:STEP:P\n"
    "       (det F < 0), sigterm:STEP, sigint:STEP (the signal after step STEP).\n"
    "       Under mpirun -np N (or srun), with a build that has MPI, the grid is split into N\n"
    "       slabs along x, one per rank; rank 0 writes every file; a restart needs the same N\n"
    "       (docs/mpi.md).\n"
    "check: validates the scene and prints it resolved, with particle counts, mass and particle\n"
    "       volume against the exact geometric volume per object, estimated steps and memory\n"
    "       (exit 4 when the memory estimate exceeds the available memory).\n"
    "study: the report's Table 2 study: runs SCENE_DIR/case*.json (by name, then\n"
    "       recommended.json; --cases picks some) one after another, N threads each (default 2),\n"
    "       without snapshots, into DIR/<case>/; then mpm/study/study_plot.py writes\n"
    "       DIR/summary.csv + DIR/summary.md (one row per case) and DIR/<case>/energy.png (energy\n"
    "       and momentum vs time beside case01; not with --no-plot). Python: $MPM_PYTHON,\n"
    "       /usr/bin/python3 or python3 with matplotlib. Exit 3 if any case failed.\n"
    "Scene keys: docs/scenes.md. Exit codes: 0 ok, 1 usage, 2 input error (or a refused\n"
    "restart), 3 run failure, 4 not enough memory, 130 SIGINT, 143 SIGTERM (checkpoint written).\n";

int usage_error(const std::string& message) {
  std::cerr << "mpm: " << message << '\n' << kUsage;
  return 1;
}

/// A positive integer, the whole argument.
bool parse_positive(const char* text, int& value) {
  try {
    std::size_t used = 0;
    value = std::stoi(text, &used);
    return used == std::strlen(text) && value >= 1;
  } catch (const std::exception&) {
    return false;
  }
}

/// Comma-separated, no empty items.
bool parse_list(const std::string& text, std::vector<std::string>& items) {
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma - start);
    if (item.empty()) return false;
    items.push_back(item);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  // Under mpirun or srun: one rank of a domain decomposition (docs/mpi.md); else no MPI at all.
  if (impact::mpm::started_by_launcher() && !impact::mpm::mpi_available()) {
    // Each process would run the whole scene into the same directory.
    std::cerr << "mpm: started by an MPI launcher, but this mpm was built without MPI (install "
                 "libopenmpi-dev and rebuild: ./run.sh mpi, docs/mpi.md)\n";
    return 2;
  }
  impact::mpm::MpiSession mpi(argc, argv);
  const impact::mpm::Communicator comm(&mpi);
  if (argc < 2) return usage_error("missing command");
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << kUsage;
    return 0;
  }
  if (command != "run" && command != "check" && command != "study")
    return usage_error("unknown command '" + command + "'");
  const bool study = command == "study";
  std::string scene_file, restart_dir;
  std::vector<impact::Json> patches;
  bool progress = isatty(STDERR_FILENO) != 0;
  impact::mpm::RunOptions options;
  options.comm = &comm;
  impact::mpm::StudyOptions study_options;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--out" && command != "check") {
      if (i + 1 >= argc) return usage_error("--out needs a directory");
      options.out_dir = argv[++i];
    } else if (a == "--threads") {
      if (i + 1 >= argc) return usage_error("--threads needs a number");
      if (!parse_positive(argv[++i], options.threads))
        return usage_error("--threads: expected a positive integer, got '" + std::string(argv[i]) +
                           "'");
      study_options.threads = options.threads;
    } else if (a == "--cases" && study) {
      if (i + 1 >= argc || !parse_list(argv[++i], study_options.cases))
        return usage_error(
            "--cases needs a comma-separated list of case names, e.g. case01,case04");
    } else if (a == "--restart" && command == "run") {
      if (i + 1 >= argc) return usage_error("--restart needs a directory");
      restart_dir = argv[++i];
    } else if (a == "--inject-fault" && command == "run") {
      if (i + 1 >= argc) return usage_error("--inject-fault needs KIND:STEP[:PARTICLE]");
      const auto fault = impact::mpm::parse_fault_injection(argv[++i]);
      if (!fault) {
        return usage_error(
            "--inject-fault: expected nan|nan_velocity|outside|jacobian:STEP:PARTICLE "
            "or sigterm|sigint:STEP (STEP >= 1), got '" +
            std::string(argv[i]) + "'");
      }
      options.faults.push_back(*fault);
    } else if (a == "--set" && !study) {
      if (i + 1 >= argc) return usage_error("--set needs a JSON merge patch");
      try {
        patches.push_back(impact::Json::parse(argv[++i]));
      } catch (const impact::Json::parse_error& e) {
        return usage_error("--set: invalid JSON: " + std::string(e.what()));
      }
    } else if (a == "--progress") {
      progress = true;
    } else if (a == "--no-plot" && study) {
      study_options.plot = false;
    } else if (!a.empty() && a[0] == '-') {
      return usage_error("unknown option '" + a + "'");
    } else if (scene_file.empty()) {
      scene_file = a;
    } else {
      return usage_error("unexpected argument '" + a + "'");
    }
  }
  if (!restart_dir.empty()) {
    if (!scene_file.empty())
      return usage_error("--restart takes the scene from DIR/scene.json: no SCENE.json");
    if (!options.out_dir.empty()) return usage_error("--restart writes into DIR: no --out");
    if (!patches.empty())
      return usage_error("--restart continues DIR/scene.json as it is: no --set");
  } else if (scene_file.empty()) {
    return usage_error(study ? "missing SCENE_DIR" : "missing SCENE.json");
  }
  if (study && options.out_dir.empty()) return usage_error("study needs --out DIR");
  try {
    if (study) {
      study_options.scene_dir = scene_file;
      study_options.out_dir = options.out_dir;
      study_options.progress = progress;
      return impact::mpm::run_study(study_options);
    }
    options.progress = progress;
    options.handle_signals = true;
    if (!restart_dir.empty()) return impact::mpm::restart(restart_dir, options);
    impact::Json document = impact::mpm::load_scene_document(scene_file);
    for (const impact::Json& patch : patches) document.merge_patch(patch);
    const impact::mpm::Scene scene = impact::mpm::read_scene(document, scene_file);
    for (const std::string& w : scene.warnings) std::cerr << "mpm: warning: " << w << '\n';
    if (command == "check") {
      std::cout << scene.resolved.dump(2) << '\n';
      const int threads = impact::mpm::run_threads(options.threads);
      // An oversized scene is reported without seeding it.
      if (const std::string refusal = impact::mpm::memory_refusal(scene); !refusal.empty()) {
        std::cerr << "mpm: check: mpm run would refuse this scene: " << refusal << '\n';
        return impact::mpm::kExitMemory;
      }
      std::cout << impact::mpm::check_report(scene, threads).dump(2) << '\n';
      return 0;
    }
    return impact::mpm::run(scene, options);
  } catch (const impact::InputError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mpm: " << e.what() << '\n';
    return 3;
  }
}
