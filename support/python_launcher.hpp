// The one way the programs start their Python helpers (plot scripts, the study table): a child
// process without a shell (posix_spawn: safe in a process with OpenMP or MPI threads), and one
// rule for the interpreter: $IMPACT_PYTHON when set (the older $POINTDRIVER_PYTHON and
// $MPM_PYTHON too), then Debian's /usr/bin/python3 (where python3-matplotlib installs; a pyenv or
// venv python3 earlier on PATH may lack it), then python3 on PATH.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

extern char** environ;

namespace impact {

/// Runs `argv` (argv[0] looked up on PATH); returns its exit status, 127 when it cannot start.
/// `quiet` sends its output to /dev/null (interpreter probes); `stdout_file` (when not empty)
/// takes the child's stdout instead (a caller that passes it on under its own name).
inline int spawn_process(const std::vector<std::string>& argv, bool quiet,
                         const std::string& stdout_file = {}) {
  std::cout.flush();
  std::cerr.flush();
  std::vector<char*> cargs;
  for (const auto& a : argv) cargs.push_back(const_cast<char*>(a.c_str()));
  cargs.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  } else if (!stdout_file.empty()) {
    posix_spawn_file_actions_addopen(&actions, 1, stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0600);
  }
  pid_t pid = 0;
  const int err = posix_spawnp(&pid, cargs[0], &actions, nullptr, cargs.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) return 127;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

/// The interpreters to try, in order (the rule of this header).
inline std::vector<std::string> python_candidates() {
  for (const char* name : {"IMPACT_PYTHON", "POINTDRIVER_PYTHON", "MPM_PYTHON"}) {
    if (const char* env = std::getenv(name); env != nullptr && *env != '\0') return {env};
  }
  return {"/usr/bin/python3", "python3"};
}

struct PythonInterpreter {
  std::string command;      ///< empty: none runs
  bool matplotlib = false;  ///< it imports matplotlib
  bool any_runs = false;    ///< some candidate started (false: no python3 at all)
};

/// The first candidate that imports matplotlib; failing that, the first that runs at all (a table
/// needs only the standard library), with matplotlib false.
inline PythonInterpreter find_python() {
  PythonInterpreter p;
  const auto candidates = python_candidates();
  for (const auto& c : candidates) {
    const int code = spawn_process({c, "-c", "import matplotlib"}, true);
    p.any_runs = p.any_runs || code != 127;
    if (code == 0) return {c, true, true};
  }
  for (const auto& c : candidates) {
    if (spawn_process({c, "-c", "import csv, json"}, true) == 0) return {c, false, true};
  }
  return p;
}

}  // namespace impact
