// Where a program finds the files it ships with (plot scripts, data): share/impact/<relative>
// beside the running executable (bin/../share/impact/, what `cmake --install` lays out), else the
// source tree the build came from (IMPACT_SOURCE_DIR of the including target). So the programs run
// from the build tree, from an install prefix, and from that prefix moved elsewhere.
// IMPACT_NO_SOURCE_TREE=1 in the environment drops the source-tree fallback (the relocation test
// uses it to prove the installed copy is the one found).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace impact {

inline std::filesystem::path shipped_file(const std::string& relative) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / "share" / "impact" / relative;
    if (fs::exists(installed, ec)) return installed;
  }
  const char* no_source = std::getenv("IMPACT_NO_SOURCE_TREE");
  if (no_source != nullptr && std::string(no_source) == "1") return fs::path(relative);
#ifdef IMPACT_SOURCE_DIR
  return fs::path(IMPACT_SOURCE_DIR) / relative;
#else
  return fs::path(relative);
#endif
}

}  // namespace impact
