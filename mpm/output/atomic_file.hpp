// Whole-file outputs (summary.json, scene.json, status.json, particles.pvd, the VTU snapshots) are
// written to `<name>.tmp` in the same directory and renamed over `<name>` only after a successful
// close, so a crash or kill leaves either the previous complete file or the new one, never a
// truncated one (rename within one directory is atomic on POSIX file systems). A stray `.tmp` is
// at most the one file being written when the process died.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace impact::mpm {

/// Writes `path` through `write` (binary stream) via `path.tmp` and a rename. Throws
/// std::runtime_error naming the file when it cannot be opened, written, closed or renamed; the
/// temporary is removed then (also when `write` throws, which is re-thrown).
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace impact::mpm
