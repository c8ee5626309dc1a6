// What happens to the stress of a failed point (report sec. 3; docs/report_code.md sec. 11).
// Applied every step to the freshly updated stress of a failed point, as the 2004 code did:
//   none            no failure detection at all (the caller skips TEPLA and stability checks);
//                   the stress is left unchanged
//   AllowNoTension  sigma -> dev(sigma) if the mean stress is tensile (tr sigma > 0), else
//                   unchanged: a failed point carries no hydrostatic tension but still resists
//                   compression and keeps its deviator (the 2004 code's rule)
//   KeepStress      unchanged; the point is only flagged as failed
//   ZeroStress      sigma -> 0
// In the 2004 code "KeepStress" was not a keyword: ANY string other than none, RemoveMass,
// AllowNoTension and ZeroStress behaved so, so a misspelt name silently kept the stress. Here
// unknown names are rejected. RemoveMass (shrinking the particle's weight in the grid transfers)
// is a solver-level operation, not a stress operation, and the report did not use it.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "models/core/input.hpp"
#include "models/core/tensor.hpp"

namespace impact {

enum class Erosion { none, allow_no_tension, keep_stress, zero_stress };

/// The stress of a failed point after erosion.
Mat3 erode_stress(Erosion algorithm, const Mat3& stress);

/// The report's spelling: "none", "AllowNoTension", "KeepStress", "ZeroStress".
std::string_view erosion_name(Erosion algorithm);

/// The algorithm spelled `name` (exactly, case-sensitive), or nothing for an unknown name.
std::optional<Erosion> erosion_from_name(std::string_view name);

/// Every algorithm's name, catalogue order (erosion.cpp's table: one line an algorithm).
std::vector<std::string_view> erosion_names();

/// Reads {"algorithm": "none" | "AllowNoTension" | "KeepStress" | "ZeroStress"} (required).
Erosion read_erosion(JsonReader& r);

}  // namespace impact
