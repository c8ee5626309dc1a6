// The files a run owns in its output directory. A new run into a used directory first removes the
// previous run's files, so that nothing of it (a snapshot its .pvd no longer names, a summary, a
// checkpoint) outlives the new run; it refuses to destroy a run that can still be continued. A
// restart keeps the directory and removes only the snapshots its checkpoint does not list (those a
// killed run wrote after the checkpoint). Other files in the directory are never touched.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace impact::mpm {

/// Why a new run must not replace `dir`'s files: it holds the checkpoint of a run that has not
/// finished (status.json not "completed" or "failed"), which `mpm run --restart DIR` continues.
/// Empty when nothing is in the way.
std::string unfinished_run(const std::filesystem::path& dir);

/// Why `mpm run --restart DIR` has nothing to continue: DIR's run completed (status.json
/// "completed"), and a restart would rerun the steps after its last checkpoint to the same end
/// without a word. Empty otherwise (a failed run may be continued: an output error, say, after
/// freeing the disk).
std::string completed_run(const std::filesystem::path& dir);

/// Removes the files of a previous run from `dir`: history.csv, summary.json, status.json,
/// scene.json, particles.pvd, checkpoint.bin and checkpoint.rankN.bin, particles/step_*.vtu and
/// .pvtu, the particle paths its scene.json names in paths/, and any of them with .tmp left by a
/// killed write. Returns how many files it removed.
std::size_t clear_previous_run(const std::filesystem::path& dir);

/// Removes `dir`/particles/step_* files of a step that no entry of `entries` (the .pvd's
/// (time, file) entries a checkpoint restored) names. Returns how many.
std::size_t remove_unlisted_snapshots(const std::filesystem::path& dir,
                                      const std::vector<std::pair<double, std::string>>& entries);

}  // namespace impact::mpm
