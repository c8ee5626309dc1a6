// libFuzzer target: FIT.json and CHECK.json (pointdriver/fit/fit_config.cpp). Each input is read
// as both; "data/materials/..." and "data/experiments/..." (files and globs) resolve inside the
// scratch mirror. Property: each reader returns a configuration or throws InputError
// (tests/fuzz/fuzz_support.hpp).
#include "pointdriver/fit/fit_config.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fit = impact::pointdriver::fit;
  const std::string file = impact::fuzz::write_input("data/fuzz/config.json", data, size);
  impact::fuzz::expect_value_or_input_error("read_fit_config", [&] { fit::read_fit_config(file); });
  impact::fuzz::expect_value_or_input_error("read_check_config",
                                            [&] { fit::read_check_config(file); });
  return 0;
}
