// The message reading a scene document throws, for the tests of the scene reader's checks.
#pragma once

#include <string>

#include "models/core/input.hpp"
#include "mpm/input/scene_reader.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::testing {

/// Every problem line of the InputError raised by reading `doc` as "test.json" ("" if none).
inline std::string scene_error_of(const nlohmann::json& doc) {
  try {
    mpm::read_scene(doc, "test.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace impact::testing
