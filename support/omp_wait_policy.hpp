// OpenMP threads that sleep at their barriers unless the user asked otherwise.
// libgomp's default lets an idle thread spin at a barrier before it sleeps; when another process
// holds one of the cores, the spinning thread takes the time slices its busy partner needs, and a
// run on all cores collapses (the Taylor rod on 2 threads with one core busy: 77.6 s against
// 0.58 s on 1 thread; with OMP_WAIT_POLICY=passive 1.7 s; docs/performance.md#threads). libgomp
// reads the policy once, when it is loaded, before main: a program started without
// OMP_WAIT_POLICY therefore sets it to passive and executes itself again, the same process (its
// PID, arguments and an MPI launcher's environment stay). A policy the user set is kept.
#pragma once

#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <string>

namespace impact::cli {

/// Call first thing in main, before any OpenMP or MPI call. Returns only if nothing was done (the
/// policy was set, or this is not the program itself, by its name or a link to it: under valgrind
/// /proc/self/exe is the tool)
/// or the re-execution failed (then the run goes on with libgomp's default).
inline void wait_passively_unless_asked(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || argv == nullptr || argv[0] == nullptr) return;
  char exe[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
  if (n <= 0) return;
  exe[n] = '\0';
  const auto base = [](const std::string& path) {
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
  };
  // The program itself (by name, or through a link to it), not a tool that runs it.
  char target[PATH_MAX];
  const bool linked = realpath(argv[0], target) != nullptr && std::string(target) == exe;
  if (base(exe) != base(argv[0]) && !linked) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv(exe, argv);
}

}  // namespace impact::cli
