// libFuzzer target: an experiment file, the CSV with "# key [unit]: value" header lines
// (pointdriver/fit/experiment_data.cpp, parse_experiment). Each input is read twice: without a
// Young's modulus from the material and with one (total-strain curves need it).
// Property: the reader returns a curve or throws InputError (tests/fuzz/fuzz_support.hpp).
#include <sstream>

#include "pointdriver/fit/experiment_data.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fit = impact::pointdriver::fit;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const std::optional<double> modulus : {std::optional<double>(), std::optional(68.9e9)}) {
    impact::fuzz::expect_value_or_input_error("parse_experiment", [&] {
      std::istringstream in(text);
      fit::parse_experiment(in, "fuzz.csv", modulus);
    });
  }
  return 0;
}
