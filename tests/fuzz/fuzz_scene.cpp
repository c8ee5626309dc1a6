// libFuzzer target: an MPM scene file (mpm/scene/scene.cpp, load_scene): `extends` chains and
// material files resolve inside the scratch mirror, where the input sits beside links to every
// repository scene (so "extends": "case01.json" and "../../materials/al6061_t6.json" work).
// Property: the loader returns a scene or throws InputError (tests/fuzz/fuzz_support.hpp).
#include "mpm/input/scene_reader.hpp"
#include "mpm/scene/scene.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = impact::fuzz::write_input("data/scenes/fuzz/input.json", data, size);
  impact::fuzz::expect_value_or_input_error("load_scene", [&] { impact::mpm::load_scene(file); });
  return 0;
}
