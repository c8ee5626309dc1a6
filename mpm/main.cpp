// mpm: the explicit MPM solver's command line.
//   mpm run SCENE.json [--out DIR] [--threads N] [--set JSON]... [--progress] [--overwrite]
//           [--inject-fault KIND:STEP[:PARTICLE]]...
//   mpm run --restart DIR [--threads N]
//   mpm check SCENE.json [--threads N] [--set JSON]... [--ranks N] [--fingerprint]
//   mpm study SCENE_DIR --out DIR [--threads N] [--cases LIST] [--no-plot]
//   mpm study --ladder LEVELS SCENE.json --out DIR [--threads N] [--ranks N] [--set JSON]...
//   mpm plot RUN [--out FIG]
//   mpm keys [--format md|json]
// Exit codes: 0 success, 1 usage error, 2 input error (file + JSON key path; a refused restart),
// 3 run failure (numerical fault), 4 refused before the start (the memory estimate above the
// available memory, the estimated steps above time.max_estimated_steps or the particle-steps above
// time.max_estimated_particle_steps), 128 + signal after a
// checkpoint on SIGINT (130) or SIGTERM (143).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "campaigns/plot/run_plot.hpp"
#include "campaigns/study/ladder_command.hpp"
#include "campaigns/study/study.hpp"
#include "mpm/input/scene_keys.hpp"
#include "mpm/input/scene_reader.hpp"
#include "mpm/run/memory.hpp"
#include "mpm/run/run.hpp"
#include "mpm/run/scene_fingerprint.hpp"
#include "mpm/run/step_estimate.hpp"
#include "mpm/run/summary.hpp"
#include "mpm/simulation/simulation.hpp"
#include "mpm/threads/threads.hpp"
#include "support/command_line.hpp"
#include "support/omp_wait_policy.hpp"
#include "support/shipped_file.hpp"

namespace {

// The end of each --help: what the command writes and its exit codes (mpm --help: every command).
const char* kFooter =
    "mpm COMMAND --help gives a command's options, outputs and exit codes. Scene keys:\n"
    "docs/scenes.md. Exit codes: 0 ok, 1 usage, 2 input error (or a refused restart or\n"
    "replacement), 3 run failure or an output not written, 4 refused before the start (memory\n"
    "or step estimate), 130 SIGINT, 143 SIGTERM (checkpoint written).\n";
const char* kRunFooter =
    "Writes DIR/history.csv (energy and momentum ledger), DIR/particles/step_NNNNNN.vtu +\n"
    "DIR/particles.pvd (ParaView), DIR/summary.json, DIR/scene.json (resolved), DIR/status.json\n"
    "and DIR/checkpoint.bin (every output.checkpoint_interval_steps steps, and on SIGINT or\n"
    "SIGTERM, after which the run stops with 128 + the signal number). DIR defaults to the\n"
    "scene's output.directory; a new run first removes a previous run's files there (it refuses\n"
    "to replace an unfinished run's checkpoint without --overwrite; --restart keeps them). On\n"
    "success it prints one line: steps, wall time, energy error and DIR. Under mpirun -np N (or\n"
    "srun), with a build that has MPI, the grid is split into N boxes (solver.ranks_per_axis, or\n"
    "the split cutting the fewest node faces; check --ranks N plans it); rank 0 writes every\n"
    "file (docs/mpi.md).\n"
    "Exit codes: 0 completed, 1 usage, 2 input error (or a refused restart or replacement), 3\n"
    "run failure or an output not written, 4 refused before anything is written: the memory\n"
    "estimate exceeds the available memory, the estimated steps time.max_estimated_steps, or\n"
    "the particle-steps time.max_estimated_particle_steps\n"
    "(docs/mpm.md#memory-and-step-estimates), 130 SIGINT, 143 SIGTERM (checkpoint written).\n";
const char* kCheckFooter =
    "Prints one JSON document: \"resolved\" (the scene after extends and --set),\n"
    "\"warnings\", \"refusal\" (why mpm run would refuse the scene, or \"\") and \"report\":\n"
    "particles, mass and volume per object, the memory estimate, the estimated steps, the\n"
    "gauges' particles, the fingerprint and with --ranks N the split over N ranks\n"
    "(docs/mpi.md); no report when the memory estimate refuses the scene (nothing is seeded).\n"
    "Exit codes: 0 valid, 1 usage, 2 input error, 3 stdout not written, 4 mpm run would refuse\n"
    "the scene (the memory or step estimate; the reason on stderr).\n";
const char* kStudyFooter =
    "study SCENE_DIR runs every case*.json (and recommended.json) into OUT/<case>/ and writes\n"
    "OUT/study.json, OUT/summary.csv, OUT/summary.md and the figures (docs/sphere_cylinder.md);\n"
    "study --ladder L1,L2,... SCENE.json runs the scene at each level of its cells per axis\n"
    "(docs/accuracy.md#grid-convergence-ladders).\n"
    "Exit codes: 0 every case completed, 1 usage, 2 input error, 3 a case failed, 130 SIGINT.\n";
const char* kPlotFooter =
    "Draws RUN's energy books, energy error, momentum and observables into RUN/run.png (or\n"
    "--out FIG ending in .png, .pdf or .svg; python3 + matplotlib).\n"
    "Exit codes: 0 drawn, 1 usage (or no python3 or matplotlib), 2 RUN is not a run directory,\n"
    "3 the figure or stdout could not be written, 141 stdout closed by its reader (| head).\n";
const char* kKeysFooter =
    "Prints every scene key the reader knows: type, range, default, meaning (docs/scenes.md).\n"
    "Exit codes: 0 printed, 1 usage, 3 stdout not written.\n";

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

// What is wrong with `mpm study --ladder LEVELS` (empty: nothing): checked here, so that the
// message names --ladder; ladder.py, which names its own --levels, then refuses only two levels
// that give the same cells (it needs the scene for that).
std::string ladder_levels_problem(const std::string& text) {
  std::vector<std::string> items;
  std::vector<double> levels;
  if (!parse_list(text, items)) return "expected comma-separated levels, e.g. --ladder 1,1.5,2.25";
  for (const std::string& item : items) {
    char* end = nullptr;
    const double level = std::strtod(item.c_str(), &end);
    if (end != item.c_str() + item.size() || !std::isfinite(level) || !(level > 0.0))
      return "expected positive numbers (multipliers of the scene's cells per axis), got '" + item +
             "' in '" + text + "'";
    if (std::find(levels.begin(), levels.end(), level) != levels.end())
      return "the level '" + item + "' is repeated in '" + text + "'";
    levels.push_back(level);
  }
  return {};
}

// A usage error of one command: named, with that command's help to read (not mpm --help's list
// of commands).
int usage_error(const std::string& command, const std::string& message) {
  std::cerr << "mpm " << command << ": " << message << "\nRun 'mpm " << command
            << " --help' for the options.\n";
  return impact::cli::kExitUsage;
}

// `mpm keys`: the scene format's keys as the reader records them (mpm/input/scene_keys.hpp).
int print_scene_keys(const std::string& format) {
  const auto keys =
      impact::mpm::scene_keys(impact::shipped_file("data/materials/al6061_t6.json").string());
  const std::string_view name = impact::mpm::kSceneKeyName;
  if (format == "json") {
    std::cout << impact::keys_json(keys.keys(), name).dump(2) << '\n';
  } else {
    std::cout << impact::keys_markdown(keys.keys(), name);
  }
  return 0;
}

// `mpm check`: one JSON document on stdout, the keys of Python's impact.check_scene: the resolved
// scene, its warnings, why mpm run would refuse it ("" when it would not) and, unless the memory
// estimate refuses it (then nothing is seeded), the report: particles, mass, memory, steps.
int check_scene(const impact::mpm::Scene& scene, const std::vector<std::string>& warnings,
                int threads, int plan_ranks) {
  impact::Json out = {{"resolved", scene.resolved}, {"warnings", warnings}};
  const std::string memory = impact::mpm::memory_refusal(scene);
  const std::string refusal = memory.empty() ? impact::mpm::step_refusal(scene) : memory;
  out["refusal"] = refusal;
  if (memory.empty()) {
    out["report"] = impact::mpm::check_report(scene, impact::mpm::run_threads(threads), plan_ranks);
  }
  std::cout << out.dump(2) << '\n';
  if (refusal.empty()) return 0;
  std::cerr << "mpm: check: mpm run would refuse this scene: " << refusal << '\n';
  return impact::mpm::kExitMemory;
}

// A run writes its resolved scene to DIR/scene.json: a scene file that is that file would be
// overwritten (the user's extends and comments lost). Why, or empty.
std::string overwritten_scene(const impact::mpm::Scene& scene, const std::string& out_dir) {
  namespace fs = std::filesystem;
  const fs::path dir = out_dir.empty() ? fs::path(scene.output.directory) : fs::path(out_dir);
  std::error_code ec;
  if (!fs::equivalent(dir / "scene.json", scene.file, ec)) return {};
  return scene.file + ": is " + (dir / "scene.json").string() + ", which the run replaces with " +
         "the resolved scene (" + (out_dir.empty() ? "/output/directory" : "--out") + " " +
         dir.string() + "): give the scene another name or the run another directory";
}

int run_main(int argc, char** argv) {
  // Under mpirun or srun: one rank of a domain decomposition (docs/mpi.md); else no MPI at all.
  if (impact::mpm::started_by_launcher() && !impact::mpm::mpi_available()) {
    // Each process would run the whole scene into the same directory.
    std::cerr << "mpm: started by an MPI launcher, but this mpm was built without MPI (install "
                 "libopenmpi-dev and rebuild: ./run.sh mpi, docs/mpi.md)\n";
    return 2;
  }
  impact::mpm::MpiSession mpi(argc, argv);
  const impact::mpm::Communicator comm(&mpi);

  CLI::App app{"The explicit MPM solver.", "mpm"};
  impact::cli::Verbosity verbosity;
  impact::mpm::RunOptions options;
  options.comm = &comm;
  impact::mpm::StudyOptions study_options;
  std::string scene_file, restart_dir, cases;
  std::vector<std::string> set_texts, fault_texts;
  bool progress = isatty(STDERR_FILENO) != 0;
  app.require_subcommand(1);
  CLI::App* run = app.add_subcommand("run", "run a scene to its end time");
  CLI::App* check = app.add_subcommand("check", "validate a scene; particles, mass, memory");
  CLI::App* study =
      app.add_subcommand("study",
                         "the report's Table 2 study: every case of a folder; or --ladder: one "
                         "scene at several resolutions, with error bars");
  CLI::App* plot =
      app.add_subcommand("plot", "draw one run's energy books, momentum and observables");
  CLI::App* keys = app.add_subcommand("keys", "list the scene keys: type, range, default, meaning");
  std::string keys_format = "md";
  keys->add_option("--format", keys_format, "md (a Markdown table) or json")
      ->check(CLI::IsMember({"md", "json"}));
  std::string plot_run, plot_figure;
  plot->add_option("RUN", plot_run, "a directory mpm run wrote")->required();
  plot->add_option("-o,--out", plot_figure, "figure file (.png, .pdf, .svg; default RUN/run.png)")
      ->type_name("FIG");
  for (CLI::App* c : {run, check, study}) {
    // Each command's help states its own default (study runs two cases at a time).
    c->add_option(
         "--threads", options.threads,
         c == study ? "OpenMP threads per case (default: 2)" : "OpenMP threads (default: all)")
        ->type_name("N")
        ->check(CLI::Range(1, impact::mpm::kMaxThreads));
  }
  run->add_option("SCENE.json", scene_file, "scene file (docs/scenes.md)");
  check->add_option("SCENE.json", scene_file, "scene file")->required();
  int plan_ranks = 0;
  check
      ->add_option("--ranks", plan_ranks,
                   "also report the split over N MPI ranks: boxes, particles and halo bytes per "
                   "rank (docs/mpi.md)")
      ->type_name("N")
      ->check(CLI::PositiveNumber);
  bool fingerprint_only = false;
  check->add_flag("--fingerprint", fingerprint_only,
                  "print only the scene fingerprint (16 hex digits; docs/mpm.md#output)");
  study
      ->add_option("SCENE_DIR", scene_file,
                   "folder of case*.json (+ recommended.json); with --ladder a scene file")
      ->required();
  std::string ladder_levels;
  int ladder_ranks = 1;
  study
      ->add_option("--ladder", ladder_levels,
                   "a grid-convergence ladder of the scene SCENE_DIR names: its cells times each "
                   "level per axis, observed order, Richardson value and GCI per observable "
                   "(campaigns/study/ladder.py; docs/accuracy.md#grid-convergence-ladders)")
      ->type_name("L1,L2,...");
  study->add_option("--ranks", ladder_ranks, "with --ladder: every level under mpirun -np N")
      ->type_name("N")
      ->check(CLI::PositiveNumber);
  run->add_option("-o,--out", options.out_dir, "output directory")->type_name("DIR");
  study->add_option("-o,--out", options.out_dir, "output directory (one folder per case)")
      ->type_name("DIR")
      ->required();
  impact::cli::add_set(*run, set_texts, "the scene (after its extends)");
  impact::cli::add_set(*check, set_texts, "the scene (after its extends)");
  impact::cli::add_set(*study, set_texts, "every case (after its extends)");
  for (CLI::App* c : {run, study})
    c->add_flag("--progress", progress, "the progress line also off a terminal (a batch log)");
  run->add_option("--restart", restart_dir,
                  "continue DIR's run from DIR/checkpoint.bin (bit-identical; no SCENE.json)")
      ->type_name("DIR");
  run->add_flag("--overwrite", options.overwrite,
                "start over in a DIR that holds an unfinished run's checkpoint (deletes it)");
  run->add_option("--inject-fault", fault_texts,
                  "developer: nan|nan_velocity|outside|jacobian:STEP:P, sigterm|sigint:STEP")
      ->type_name("KIND:STEP[:P]")
      ->allow_extra_args(false);
  study->add_option("--cases", cases, "comma-separated case names, e.g. case01,case04");
  bool no_plot = false;
  study->add_flag("--no-plot", no_plot, "write the table only (no figures)");
  // mpm --help lists the commands; each command's --help its options, the common ones included.
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("mpm ") + IMPACT_VERSION);
  impact::cli::describe(*run, kRunFooter, verbosity);
  impact::cli::describe(*check, kCheckFooter, verbosity);
  impact::cli::describe(*study, kStudyFooter, verbosity);
  impact::cli::describe(*plot, kPlotFooter, verbosity);
  impact::cli::describe(*keys, kKeysFooter, verbosity);
  if (const auto code = impact::cli::parse(app, argc, argv, verbosity)) return *code;
  if (plot->parsed()) return impact::mpm::plot_run(plot_run, plot_figure);
  if (keys->parsed()) {
    try {
      return print_scene_keys(keys_format);
    } catch (const impact::InputError& e) {  // a sample scene refused: a bug, reported as input
      std::cerr << e.what() << '\n';
      return 2;
    }
  }

  for (const auto& text : fault_texts) {
    const auto fault = impact::mpm::parse_fault_injection(text);
    if (!fault) {
      return usage_error(
          "run",
          "--inject-fault: expected nan|nan_velocity|outside|jacobian:STEP:PARTICLE or "
          "sigterm|sigint:STEP (STEP >= 1), got '" +
              text + "'");
    }
    options.faults.push_back(*fault);
  }
  if (!cases.empty() && !parse_list(cases, study_options.cases))
    return usage_error("study",
                       "--cases needs a comma-separated list of case names, e.g. case01,case04");
  if (options.threads > 0) study_options.threads = options.threads;
  study_options.plot = !no_plot;
  if (!restart_dir.empty()) {
    if (!scene_file.empty())
      return usage_error("run", "--restart takes the scene from DIR/scene.json: no SCENE.json");
    if (!options.out_dir.empty()) return usage_error("run", "--restart writes into DIR: no --out");
    if (!set_texts.empty())
      return usage_error("run", "--restart continues DIR/scene.json as it is: no --set");
    if (options.overwrite) return usage_error("run", "--restart continues DIR: no --overwrite");
  } else if (scene_file.empty()) {
    return usage_error("run", "missing SCENE.json (or --restart DIR)");
  }
  std::vector<impact::Json> patches;
  impact::mpm::ExtendsChain chain;  // the scene file's, for messages
  try {
    patches = impact::cli::patches_of(set_texts);
    for (impact::Json& patch : patches) impact::mpm::resolve_patch_material_paths(patch);
    if (study->parsed() && study->get_option("--ladder")->count() > 0) {
      if (const std::string problem = ladder_levels_problem(ladder_levels); !problem.empty())
        return usage_error("study", "--ladder: " + problem);
      if (!cases.empty()) return usage_error("study", "--ladder runs one scene: no --cases");
      impact::mpm::LadderOptions ladder;
      ladder.scene_file = scene_file;
      ladder.out_dir = options.out_dir;
      ladder.levels = ladder_levels;
      ladder.threads = study_options.threads;
      ladder.ranks = ladder_ranks;
      ladder.set_texts = set_texts;
      ladder.plot = !no_plot;
      return impact::mpm::run_ladder(ladder);
    }
    if (study->parsed()) {
      if (ladder_ranks != 1) return usage_error("study", "--ranks goes with --ladder");
      study_options.patches = patches;
      study_options.scene_dir = scene_file;
      study_options.out_dir = options.out_dir;
      study_options.progress = progress;
      return impact::mpm::run_study(study_options);
    }
    options.progress = progress;
    options.handle_signals = true;
    options.report = comm.root();  // one rank prints the outcome
    if (!restart_dir.empty()) return impact::mpm::restart(restart_dir, options);
    impact::Json document = impact::mpm::load_scene_document(scene_file, &chain);
    for (const impact::Json& patch : patches) document.merge_patch(patch);
    const impact::mpm::Scene scene = impact::mpm::read_scene(document, scene_file);
    const std::vector<std::string> warnings = impact::mpm::extends_origins(chain).attribute(
        impact::cli::set_origins(scene_file, patches).attribute(scene.warnings));
    for (const std::string& w : warnings) std::cerr << "mpm: warning: " << w << '\n';
    if (verbosity.verbose) std::cerr << scene.resolved.dump(2) << '\n';
    if (check->parsed() && fingerprint_only) {
      std::cout << impact::mpm::scene_fingerprint(scene.resolved) << '\n';
      return 0;
    }
    if (check->parsed()) return check_scene(scene, warnings, options.threads, plan_ranks);
    if (const std::string clash = overwritten_scene(scene, options.out_dir); !clash.empty())
      throw impact::InputError({clash});
    return impact::mpm::run(scene, options);
  } catch (const impact::InputError& e) {
    // A key a --set patch set names the patch; one a base scene set, the base.
    std::cerr << impact::mpm::extends_origins(chain)
                     .attribute(impact::cli::set_origins(scene_file, patches).attribute(e))
                     .what()
              << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mpm: " << e.what() << '\n';
    return 3;
  }
}

}  // namespace

int main(int argc, char** argv) {
  // OpenMP threads sleep at barriers unless OMP_WAIT_POLICY says otherwise: a busy core must not
  // stall the run (support/omp_wait_policy.hpp). First, before OpenMP and MPI start.
  impact::cli::wait_passively_unless_asked(argv);
  impact::cli::report_file_size_limits();
  return impact::cli::stdout_checked(run_main(argc, argv), "mpm");
}
