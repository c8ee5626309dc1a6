// pointdriver: runs material-point paths through the models library, verifies it, and plots.
//   pointdriver run PATH.json [-o out.csv] [--set JSON]     one path, one CSV row per step
//   pointdriver verify [--out DIR] [--case NAME]            the verification suite
//   pointdriver batch --paths P1.json ... [--materials M.json ...] [--out DIR]
//   pointdriver convergence [--out DIR]                     accuracy versus cost study
//   pointdriver plot out.csv --x COL --y COL [--y COL ...] -o fig.png
//   pointdriver fit FIT.json [--out DIR]                   flow-stress fit through the driver
//   pointdriver check CHECK.json [--out DIR]               a parameter set against data
//   pointdriver cards MATERIAL.json [--units U] [--out DIR] LS-DYNA and Abaqus cards
// Exit codes: 0 success, 1 usage error, 2 input error, 3 a step could not be solved or a
// verification case failed.
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "pointdriver/commands.hpp"

namespace {

const char* usage =
    "usage: pointdriver <command> [options]   (pointdriver <command> --help for details)\n"
    "commands:\n"
    "  run PATH.json [-o OUT.csv] [--set JSON]   run one path; one CSV row per step\n"
    "  verify [--out DIR] [--case NAME]          run the verification suite (table + figures)\n"
    "  batch --paths P.json... [--materials M.json...] [--out DIR]\n"
    "                                            every material on every path in one process\n"
    "  convergence [--out DIR] [--quick]         accuracy versus cost of three paths\n"
    "  plot OUT.csv --x COL --y COL... -o FIG.png   quick figure (python3-matplotlib)\n"
    "  fit FIT.json [--out DIR]                  fit a flow-stress law to measured curves\n"
    "  check CHECK.json [--out DIR]              check a parameter set against measured curves\n"
    "  cards MATERIAL.json [--units U] [--out DIR]   LS-DYNA and Abaqus Johnson-Cook cards\n"
    "exit codes: 0 success, 1 usage, 2 input error, 3 unsolved step or failed verification\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    std::cout << usage;
    return argc < 2 ? 1 : 0;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  using namespace impact::pointdriver;
  if (command == "run") return command_run(args);
  if (command == "verify") return command_verify(args);
  if (command == "batch") return command_batch(args);
  if (command == "convergence") return command_convergence(args);
  if (command == "fit") return command_fit(args);
  if (command == "check") return command_check(args);
  if (command == "cards") return command_cards(args);
  if (command == "plot") return command_plot(args, argv[0]);
  std::cerr << "pointdriver: unknown command '" << command << "'\n" << usage;
  return 1;
}
