// libFuzzer target: a material file (models/material/material.cpp, load_material).
// Property: the loader returns a material or throws InputError (tests/fuzz/fuzz_support.hpp); a
// material it accepts also survives a round trip through to_json (what material_check prints and
// what copies of resolved inputs hold).
#include "models/material/material.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = impact::fuzz::write_input("data/fuzz/material.json", data, size);
  impact::fuzz::expect_value_or_input_error("load_material", [&] {
    const impact::Material m = impact::load_material(file);
    try {
      impact::read_material(impact::to_json(m), file);
    } catch (const impact::InputError& e) {
      std::fprintf(stderr, "impact fuzz: an accepted material does not re-read: %s\n", e.what());
      std::abort();
    }
  });
  return 0;
}
