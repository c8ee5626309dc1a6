// The error bar of a run from a grid-convergence ladder (summary.json "discretization_error",
// docs/mpm.md#output). campaigns/study/ladder.py runs a scene at several resolutions and writes
// its table beside the scene file, "<stem>.ladder.json": per level the scene fingerprint
// (mpm/run/scene_fingerprint.hpp), per observable a JSON pointer into summary.json, its
// Richardson-extrapolated value, observed order and fine-grid GCI (Celik et al. 2008), whether
// that value may be quoted (`quotable`: the ladder is in the asymptotic range with a plausible
// order) and the range the levels and the plausible orders bound. A run whose fingerprint is one
// of the levels' reads its own value at each pointer and reports its relative error against the
// extrapolated value where it is quotable, the range where it is not; a value that differs from
// the ladder's own run of that level by more than round-off marks the table stale. The table is
// untrusted input: whatever it holds, the run neither stops nor fails; a malformed table gives a
// status naming the key path.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "models/core/input.hpp"

namespace impact::mpm {

/// "<stem>.ladder.json" beside `scene_file`.
std::filesystem::path ladder_table_path(const std::filesystem::path& scene_file);

/// summary.json "discretization_error" of a run of the scene file `scene_file` (empty: none)
/// whose fingerprint is `fingerprint` and whose summary (as it will be written) is `summary`;
/// nullopt when there is no table beside the scene file. Never throws:
///   {"table", "level", "ladder_commit", "observables": {name: {"path", "value",
///    "extrapolated", "error [-]" (null unless quotable), "gci_fine [-]", "order", "status",
///    "quotable", "range" and "verdict" (when the table gives them)}}} for a matching level,
///   {"table", "status": "no level of the ladder matches this scene (fingerprint X)"} else,
///   {"table", "status": "unreadable: <reason naming the key path>"} for a malformed table.
std::optional<Json> discretization_error(const std::string& scene_file,
                                         const std::string& fingerprint, const Json& summary);

/// As above from the table's text (what the test can write); `table` names it in the result.
Json discretization_error_of(const std::string& table, const std::string& text,
                             const std::string& fingerprint, const Json& summary);

}  // namespace impact::mpm
