// mpm: the explicit MPM solver's command line. The commands are in this folder (commands.hpp),
// above mpm/ and campaigns/.
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

#include <iostream>

#include "campaigns/plot/run_plot.hpp"
#include "commands/mpm/commands.hpp"
#include "support/omp_wait_policy.hpp"

namespace {

int run_main(int argc, char** argv) {
  using namespace impact::mpm;
  // Under mpirun or srun: one rank of a domain decomposition (docs/mpi.md); else no MPI at all.
  if (started_by_launcher() && !mpi_available()) {
    // Each process would run the whole scene into the same directory.
    std::cerr << "mpm: started by an MPI launcher, but this mpm was built without MPI (install "
                 "libopenmpi-dev and rebuild: ./run.sh mpi, docs/mpi.md)\n";
    return 2;
  }
  MpiSession mpi(argc, argv);
  const Communicator comm(&mpi);
  commands::CommandLine c;
  c.options.comm = comm;
  c.progress = isatty(STDERR_FILENO) != 0;
  commands::declare(c);
  if (const auto code = impact::cli::parse(c.app, argc, argv, c.verbosity)) return *code;
  if (c.plot->parsed()) return plot_run(c.plot_run, c.plot_figure);
  if (c.keys->parsed()) return commands::keys_command(c.keys_format);
  return commands::scene_command(c);
}

}  // namespace

int main(int argc, char** argv) {
  // OpenMP threads sleep at barriers unless OMP_WAIT_POLICY says otherwise: a busy core must not
  // stall the run (support/omp_wait_policy.hpp). First, before OpenMP and MPI start.
  impact::cli::wait_passively_unless_asked(argv);
  impact::cli::report_file_size_limits();
  return impact::cli::stdout_checked(run_main(argc, argv), "mpm");
}
