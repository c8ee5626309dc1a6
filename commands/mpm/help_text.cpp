// The end of each command's --help: what it writes and its exit codes.
#include "commands/mpm/commands.hpp"

namespace impact::mpm::commands {

const char* const kFooter =
    "mpm COMMAND --help gives a command's options, outputs and exit codes. Scene keys:\n"
    "docs/scenes.md. Exit codes: 0 ok, 1 usage, 2 input error (or a refused restart or\n"
    "replacement), 3 run failure or an output not written, 4 refused before the start (memory\n"
    "or step estimate), 130 SIGINT, 143 SIGTERM (checkpoint written).\n";
const char* const kRunFooter =
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
const char* const kCheckFooter =
    "Prints one JSON document: \"resolved\" (the scene after extends and --set),\n"
    "\"warnings\", \"refusal\" (why mpm run would refuse the scene, or \"\") and \"report\":\n"
    "particles, mass and volume per object, the memory estimate, the estimated steps, the\n"
    "gauges' particles, the fingerprint and with --ranks N the split over N ranks\n"
    "(docs/mpi.md); no report when the memory estimate refuses the scene (nothing is seeded).\n"
    "Exit codes: 0 valid, 1 usage, 2 input error, 3 stdout not written, 4 mpm run would refuse\n"
    "the scene (the memory or step estimate; the reason on stderr).\n";
const char* const kStudyFooter =
    "study SCENE_DIR runs every case*.json (and recommended.json) into OUT/<case>/ and writes\n"
    "OUT/study.json, OUT/summary.csv, OUT/summary.md and the figures (docs/sphere_cylinder.md);\n"
    "study --ladder L1,L2,... SCENE.json runs the scene at each level of its cells per axis\n"
    "(a graded grid: of its refined box's factor; docs/accuracy.md#grid-convergence-ladders).\n"
    "Exit codes: 0 every case completed, 1 usage, 2 input error, 3 a case failed, 130 SIGINT.\n";
const char* const kPlotFooter =
    "Draws RUN's energy books, energy error, momentum and observables into RUN/run.png (or\n"
    "--out FIG ending in .png, .pdf or .svg; python3 + matplotlib).\n"
    "Exit codes: 0 drawn, 1 usage (or no python3 or matplotlib), 2 RUN is not a run directory,\n"
    "3 the figure or stdout could not be written, 141 stdout closed by its reader (| head).\n";
const char* const kKeysFooter =
    "Prints every scene key the reader knows: type, range, default, meaning (docs/scenes.md).\n"
    "Exit codes: 0 printed, 1 usage, 3 stdout not written.\n";

}  // namespace impact::mpm::commands
