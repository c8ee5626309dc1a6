// The mpm program's commands and options, declared once for CLI11: the options shared by several
// commands (--threads, --set, --progress) are declared in one loop each, so their spelling and
// help agree (tests/command_line/same_flags_test.py).
#include "commands/mpm/commands.hpp"
#include "mpm/threads/threads.hpp"

namespace impact::mpm::commands {

namespace {

// The largest --ranks accepted: far above any machine's, so that the check's message is a plain
// range ("Value 0 not in range 1 to 1048576") rather than CLI11's PositiveNumber's DBL_MAX.
constexpr int kMaxRanks = 1 << 20;

// Each command's options in the order its --help lists them: its own first, then --set and
// --progress (declared for several commands in declare), then its own again.
void declare_run_scene(CommandLine& c) {
  c.run->add_option("SCENE.json", c.scene_file, "scene file (docs/scenes.md)");
  c.run->add_option("-o,--out", c.options.out_dir, "output directory")->type_name("DIR");
}

void declare_run_restart(CommandLine& c) {
  c.run
      ->add_option("--restart", c.restart_dir,
                   "continue DIR's run from DIR/checkpoint.bin (bit-identical; no SCENE.json)")
      ->type_name("DIR");
  c.run->add_flag("--overwrite", c.options.overwrite,
                  "start over in a DIR that holds an unfinished run's checkpoint (deletes it)");
  c.run
      ->add_option("--inject-fault", c.fault_texts,
                   "developer: nan|nan_velocity|outside|jacobian:STEP:P, sigterm|sigint:STEP")
      ->type_name("KIND:STEP[:P]")
      ->allow_extra_args(false);
}

void declare_check(CommandLine& c) {
  c.check->add_option("SCENE.json", c.scene_file, "scene file")->required();
  c.check
      ->add_option("--ranks", c.plan_ranks,
                   "also report the split over N MPI ranks: boxes, particles and halo bytes per "
                   "rank (docs/mpi.md)")
      ->type_name("N")
      ->check(CLI::Range(1, kMaxRanks));
  c.check->add_flag("--fingerprint", c.fingerprint_only,
                    "print only the scene fingerprint (16 hex digits; docs/mpm.md#output)");
}

void declare_study(CommandLine& c) {
  c.study
      ->add_option("SCENE_DIR", c.scene_file,
                   "folder of case*.json (+ recommended.json); with --ladder a scene file")
      ->required();
  c.study
      ->add_option("--ladder", c.ladder_levels,
                   "a grid-convergence ladder of the scene SCENE_DIR names: its cells times each "
                   "level per axis (a graded grid: its refined box's factor times the level), "
                   "observed order, Richardson value and GCI per observable "
                   "(campaigns/study/ladder.py; docs/accuracy.md#grid-convergence-ladders)")
      ->type_name("L1,L2,...");
  c.study->add_option("--ranks", c.ladder_ranks, "with --ladder: every level under mpirun -np N")
      ->type_name("N")
      ->check(CLI::Range(1, kMaxRanks));
  c.study->add_option("-o,--out", c.options.out_dir, "output directory (one folder per case)")
      ->type_name("DIR")
      ->required();
}

void declare_study_cases(CommandLine& c) {
  c.study->add_option("--cases", c.cases, "comma-separated case names, e.g. case01,case04");
  c.study->add_flag("--no-plot", c.no_plot, "write the table only (no figures)");
}

}  // namespace

void declare(CommandLine& c) {
  c.app.require_subcommand(1);
  c.run = c.app.add_subcommand("run", "run a scene to its end time");
  c.check = c.app.add_subcommand("check", "validate a scene; particles, mass, memory");
  c.study = c.app.add_subcommand("study",
                                 "the report's Table 2 study: every case of a folder; or --ladder: "
                                 "one scene at several resolutions, with error bars");
  c.plot = c.app.add_subcommand("plot", "draw one run's energy books, momentum and observables");
  c.keys = c.app.add_subcommand("keys", "list the scene keys: type, range, default, meaning");
  c.keys->add_option("--format", c.keys_format, "md (a Markdown table) or json")
      ->check(CLI::IsMember({"md", "json"}));
  c.plot->add_option("RUN", c.plot_run, "a directory mpm run wrote")->required();
  c.plot
      ->add_option("-o,--out", c.plot_figure, "figure file (.png, .pdf, .svg; default RUN/run.png)")
      ->type_name("FIG");
  for (CLI::App* command : {c.run, c.check, c.study}) {
    // Each command's help states its own default (study runs two cases at a time).
    command
        ->add_option("--threads", c.options.threads,
                     command == c.study ? "OpenMP threads per case (default: 2)"
                                        : "OpenMP threads (default: all)")
        ->type_name("N")
        ->check(CLI::Range(1, kMaxThreads));
  }
  declare_run_scene(c);
  declare_check(c);
  declare_study(c);
  cli::add_set(*c.run, c.set_texts, "the scene (after its extends)");
  cli::add_set(*c.check, c.set_texts, "the scene (after its extends)");
  cli::add_set(*c.study, c.set_texts, "every case (after its extends)");
  for (CLI::App* command : {c.run, c.study})
    command->add_flag("--progress", c.progress,
                      "the progress line also off a terminal (a batch log)");
  declare_run_restart(c);
  declare_study_cases(c);
  // mpm --help lists the commands; each command's --help its options, the common ones included.
  c.app.footer(kFooter);
  c.app.set_version_flag("--version", std::string("mpm ") + IMPACT_VERSION);
  cli::describe(*c.run, kRunFooter, c.verbosity);
  cli::describe(*c.check, kCheckFooter, c.verbosity);
  cli::describe(*c.study, kStudyFooter, c.verbosity);
  cli::describe(*c.plot, kPlotFooter, c.verbosity);
  cli::describe(*c.keys, kKeysFooter, c.verbosity);
}

}  // namespace impact::mpm::commands
