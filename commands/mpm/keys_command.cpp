// `mpm keys`: the scene format's keys as the reader records them (mpm/input/scene_keys.hpp).
#include <iostream>

#include "commands/mpm/commands.hpp"
#include "mpm/input/scene_keys.hpp"
#include "support/shipped_file.hpp"

namespace impact::mpm::commands {

namespace {

int print_scene_keys(const std::string& format) {
  const auto keys = scene_keys(shipped_file("data/materials/al6061_t6.json").string());
  const std::string_view name = kSceneKeyName;
  if (format == "json") {
    std::cout << keys_json(keys.keys(), name).dump(2) << '\n';
  } else {
    std::cout << keys_markdown(keys.keys(), name);
  }
  return 0;
}

}  // namespace

int keys_command(const std::string& format) {
  try {
    return print_scene_keys(format);
  } catch (const InputError& e) {  // a sample scene refused: a bug, reported as input
    std::cerr << e.what() << '\n';
    return 2;
  }
}

}  // namespace impact::mpm::commands
