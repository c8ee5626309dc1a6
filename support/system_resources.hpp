// What this process may still use, for the programs' refusals before a run (mpm run: memory;
// pointdriver run: memory and the CSV's size): memory it may still allocate, and bytes an output
// file may still take. Linux: /proc, cgroup v2 and the resource limits (ulimit -v, -d, -f).
#pragma once

#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>

namespace impact {

/// "Key:   123 kB" of a /proc file, in bytes.
inline std::optional<double> proc_field_bytes(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, key.size() + 1, key + ":") != 0) continue;
    std::istringstream s(line.substr(key.size() + 1));
    double kb = 0.0;
    if (s >> kb) return kb * 1024.0;
  }
  return std::nullopt;
}

/// A file holding one number (a cgroup's memory.max: "max" means none).
inline std::optional<double> file_number(const char* file) {
  std::ifstream in(file);
  double v = 0.0;
  if (in >> v) return v;
  return std::nullopt;
}

/// The soft limit of `resource` in bytes, or nothing when unlimited.
inline std::optional<double> resource_limit(int resource) {
  rlimit r{};
  if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return static_cast<double>(r.rlim_cur);
}

/// What this process may still allocate [bytes]: MemAvailable of /proc/meminfo, or less when a
/// cgroup (v2) memory.max, the address-space limit (ulimit -v, less VmSize) or the data limit
/// (ulimit -d, less VmData) leaves less; nothing when none can be read.
inline std::optional<double> available_memory() {
  std::optional<double> available = proc_field_bytes("/proc/meminfo", "MemAvailable");
  const auto lower = [&](double left) {
    left = std::max(left, 0.0);
    available = available ? std::min(*available, left) : left;
  };
  const std::optional<double> limit = file_number("/sys/fs/cgroup/memory.max");
  const std::optional<double> used = file_number("/sys/fs/cgroup/memory.current");
  if (limit && used) lower(*limit - *used);
  if (const auto as = resource_limit(RLIMIT_AS)) {
    lower(*as - proc_field_bytes("/proc/self/status", "VmSize").value_or(0.0));
  }
  if (const auto data = resource_limit(RLIMIT_DATA)) {
    lower(*data - proc_field_bytes("/proc/self/status", "VmData").value_or(0.0));
  }
  return available;
}

/// Peak resident set size of this process so far (VmHWM of /proc/self/status) [bytes].
inline std::optional<double> peak_resident_memory() {
  return proc_field_bytes("/proc/self/status", "VmHWM");
}

/// How many bytes a new regular file `file` may take: the free space of its directory's file
/// system for this user (of its nearest existing ancestor when the directory is still to be
/// made: nothing is created to ask), or less under a file-size limit (ulimit -f). Nothing when
/// `file` is an existing non-regular file (/dev/null, a FIFO), the space cannot be read, or the
/// file system has no blocks at all (/proc, /sys: its 0 B free is no size limit, and the write
/// itself fails with the reason).
inline std::optional<double> available_output_bytes(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status)) return std::nullopt;
  fs::path dir = file.parent_path();
  while (!dir.empty() && !fs::exists(dir, ec)) dir = dir.parent_path();
  const fs::space_info space = fs::space(dir.empty() ? fs::path(".") : dir, ec);
  if (ec || space.capacity == 0) return std::nullopt;
  double available = static_cast<double>(space.available);
  if (const auto size = resource_limit(RLIMIT_FSIZE)) available = std::min(available, *size);
  return available;
}

}  // namespace impact
