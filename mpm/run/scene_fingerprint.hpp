// The scene fingerprint (docs/mpm.md#output, summary.json "scene_fingerprint"): 16 lowercase hex
// digits naming what a run computes, so that a run can be matched with a level of a grid-
// convergence ladder (mpm/run/discretization_error.hpp). It is the 64-bit FNV-1a of the compact
// dump (keys sorted) of the resolved scene document, as `mpm run` writes it to DIR/scene.json,
// with
//   - "description" removed and of "output" only "interval", "gauges" and "crater" kept (where
//     and what a run writes, and free text, change no result; the history interval sets the rows
//     at which peaks are sampled, and the gauges and crater define observables), and
//   - every material {"file": PATH, "overrides": O} replaced by the content of its file with O
//     applied (RFC 7396), the document the material reader validates: the fingerprint depends on
//     the material's values, not on the working directory or where the repository is cloned.
// Any change of grid, time, physics, solver, objects or material values changes it.
#pragma once

#include <string>

#include "models/core/input.hpp"

namespace impact::mpm {

/// The document the fingerprint hashes (above). Material file paths are read as they stand
/// (relative ones from the working directory, as the scene reader reads them); a file that
/// cannot be read or parsed is an InputError.
Json fingerprint_document(const Json& resolved);

/// 16 lowercase hex digits: FNV-1a 64 of fingerprint_document(resolved).dump().
std::string scene_fingerprint(const Json& resolved);

}  // namespace impact::mpm
