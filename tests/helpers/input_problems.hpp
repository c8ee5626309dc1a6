// Input-error helpers shared by the tests of the JSON readers.
#pragma once

#include <string>

#include "models/core/input.hpp"

namespace impact::testing {

/// The message the problems would be thrown with ("" when there are none).
inline std::string problems_text(const InputProblems& problems) {
  try {
    problems.throw_if_any();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

}  // namespace impact::testing
