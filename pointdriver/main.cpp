// pointdriver: runs material-point paths through the models library, verifies it, fits and
// checks flow-stress laws, and plots. `pointdriver <command> --help` gives each command's options
// (pointdriver/commands/, on the programs' convention: support/command_line.hpp).
// Exit codes: 0 success, 1 usage error, 2 input error, 3 a step could not be solved, a check or a
// verification case failed, a fit did not converge, or an output (a file, stdout) could not be
// written.
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "pointdriver/commands/commands.hpp"
#include "support/command_line.hpp"

namespace {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const std::vector<std::string>&);
};

/// Every command, in the order --help lists them.
const std::vector<Command>& commands() {
  using namespace impact::pointdriver;
  static const std::vector<Command> list = {
      {"run", "run one path; one CSV row per step", command_run},
      {"verify", "run the verification suite (table + figures)", command_verify},
      {"batch", "every material on every path in one process", command_batch},
      {"convergence", "accuracy versus cost of three paths", command_convergence},
      {"plot", "quick figure of CSV columns (python3-matplotlib)", command_plot},
      {"fit", "fit a flow-stress law to measured curves", command_fit},
      {"check", "check a parameter set against measured curves", command_check},
      {"cards", "LS-DYNA and Abaqus cards (Johnson-Cook, Swift x Cowper-Symonds)", command_cards}};
  return list;
}

void print_usage(std::ostream& out) {
  out << "Material-point paths, verification, fitting and checking of flow-stress laws.\n"
         "Usage: pointdriver COMMAND [OPTIONS]   (pointdriver COMMAND --help for its options)\n\n"
         "Commands:\n";
  for (const auto& c : commands())
    out << "  " << std::left << std::setw(14) << c.name << c.summary << '\n';
  out << "\nEvery command takes --help, --version, -q/--quiet and -v/--verbose.\n"
         "Exit codes: 0 success, 1 usage, 2 input error, 3 unsolved step, failed check or\n"
         "verification, fit not converged, an output not written; 4 run refused (the estimated\n"
         "CSV or memory does not fit); 130/143 stopped by SIGINT/SIGTERM; 141 stdout closed by\n"
         "its reader (| head).\n";
}

}  // namespace

int main(int argc, char** argv) {
  impact::cli::report_file_size_limits();
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_usage(std::cerr);
    return impact::cli::kExitUsage;
  }
  // Checked like every output: --help > /dev/full exits 3, not 0.
  if (args[0] == "--help" || args[0] == "-h") {
    print_usage(std::cout);
    return impact::cli::stdout_checked(0, "pointdriver");
  }
  if (args[0] == "--version") {
    std::cout << "pointdriver " << IMPACT_VERSION << '\n';
    return impact::cli::stdout_checked(0, "pointdriver");
  }
  for (const auto& c : commands()) {
    if (args[0] == c.name) {
      const int code = c.run(std::vector<std::string>(args.begin() + 1, args.end()));
      return impact::cli::stdout_checked(code, std::string("pointdriver ") + c.name);
    }
  }
  std::cerr << "pointdriver: unknown command '" << args[0] << "'\n";
  print_usage(std::cerr);
  return impact::cli::kExitUsage;
}
