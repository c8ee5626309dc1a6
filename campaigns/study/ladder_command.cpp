#include "campaigns/study/ladder_command.hpp"

#include <csignal>
#include <filesystem>
#include <iostream>

#include "support/python_launcher.hpp"
#include "support/shipped_file.hpp"

namespace impact::mpm {

int run_ladder(const LadderOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path script = shipped_file("campaigns/study/ladder.py");
  if (!fs::is_regular_file(script, ec)) {
    std::cerr << "mpm study --ladder: script not found: " << script.string() << '\n';
    return 1;
  }
  const PythonInterpreter python = find_python();
  if (!python.any_runs) {
    std::cerr << "mpm study --ladder: no python3 found ($IMPACT_PYTHON, /usr/bin/python3, "
                 "python3); install it with: apt-get install -y python3 python3-matplotlib\n";
    return 1;
  }
  // The ladder runs this very binary, so the levels and the error bars come from one build.
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  std::vector<std::string> argv{python.command,
                                script.string(),
                                options.scene_file,
                                "--out",
                                options.out_dir,
                                "--levels",
                                options.levels,
                                "--threads",
                                std::to_string(options.threads),
                                "--ranks",
                                std::to_string(options.ranks)};
  if (!ec) argv.insert(argv.end(), {"--mpm", self.string()});
  for (const std::string& s : options.set_texts) argv.insert(argv.end(), {"--set", s});
  if (!options.plot || !python.matplotlib) argv.emplace_back("--no-plot");
  if (options.plot && !python.matplotlib)
    std::cerr << "mpm study --ladder: python3 cannot import matplotlib: tables only\n";
  // Ctrl-C reaches the whole process group: the script stops its level (one SIGINT to mpm, which
  // writes its checkpoint) and exits 130. This process waits for it instead of dying first and
  // handing the prompt back while the checkpoint is still being written. A handler that does
  // nothing, unlike SIG_IGN, is not inherited: the script keeps the default.
  struct sigaction quiet {
  }, old_int{}, old_term{};
  quiet.sa_handler = [](int) {};
  sigemptyset(&quiet.sa_mask);
  sigaction(SIGINT, &quiet, &old_int);
  sigaction(SIGTERM, &quiet, &old_term);
  const int code = spawn_process(argv, false);
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  return code;
}

}  // namespace impact::mpm
