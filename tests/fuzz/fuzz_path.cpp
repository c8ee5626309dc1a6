// libFuzzer target: a path file for the point driver (pointdriver/path/path.cpp, load_path),
// named legs included. "data/materials/..." resolves inside the scratch mirror.
// Property: the loader returns a path or throws InputError (tests/fuzz/fuzz_support.hpp).
#include "pointdriver/path/path.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = impact::fuzz::write_input("data/fuzz/path.json", data, size);
  impact::fuzz::expect_value_or_input_error("load_path",
                                            [&] { impact::pointdriver::load_path(file); });
  return 0;
}
