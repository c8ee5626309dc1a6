// The tests' one copy of the illustrative Mechanical Threshold Stress set
// (tests/data/flow_stress/mts_illustrative.json; not a published set).
#pragma once

#include <string>

#include "models/core/input.hpp"

namespace impact::testing {

/// The law's JSON object, "type" included.
inline Json mts_illustrative_law() {
  return load_json_file(std::string(IMPACT_SOURCE_DIR) +
                        "/tests/data/flow_stress/mts_illustrative.json")["flow_stress"];
}

}  // namespace impact::testing
