// JUnit XML (the format CI servers read: one <testsuite> of <testcase>s, a failed case holding a
// <failure message="...">), written by `pointdriver run`, `verify` and `check` with --junit FILE.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace impact::pointdriver {

struct JunitCase {
  std::string name;
  std::string classname;
  double seconds = 0.0;
  std::optional<std::string> failure;  ///< the message of a failed case
  std::string output;                  ///< <system-out>: what was compared
};

/// Writes `cases` as one test suite (whole or not at all: support/atomic_file.hpp);
/// std::runtime_error naming the file if it cannot be written.
void write_junit(const std::string& file, const std::string& suite,
                 const std::vector<JunitCase>& cases);

}  // namespace impact::pointdriver
