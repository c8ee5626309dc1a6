// The scene format's keys as the scene reader asks for them (models/core/input_keys.hpp): the
// reader reads sample scenes that switch on every optional block and every geometry type, and
// records each key's type, range, default and meaning. `mpm keys` prints them;
// tests/mpm/input/scene_keys_test.cpp checks docs/scenes.md's tables against them.
#pragma once

#include <string>
#include <string_view>

#include "models/core/input_keys.hpp"

namespace impact::mpm {

/// The name the sample scenes give every entry of a map of named entries (materials, objects,
/// union parts, gauges, particle paths): dotted_key() writes it as <name>.
inline constexpr std::string_view kSceneKeyName = "NAME";

/// The default recorded for a key whose default is computed from the scene (output.interval is
/// max_time / 100, output.directory names the scene file).
inline constexpr std::string_view kComputedDefault = "(computed)";

/// Every key of the scene format, in the order the reader reads them, with `extends` (resolved
/// before the reader, by load_scene_document) first. `material_file` is any valid material file:
/// the samples need one to be valid. Throws InputError if a sample scene is refused.
InputKeyRecorder scene_keys(const std::string& material_file);

}  // namespace impact::mpm
