// The scene reader (docs/scenes.md): a JSON scene file read into a validated Scene. `extends` names
// a base scene; the file's own content is applied over it as an RFC 7396 JSON merge patch,
// recursively; every problem is reported at once with its file and key path. It sits
// above what it checks against: the shape catalogue (solver.interpolation) and the seed points
// (a body that would get no particle is refused).
#pragma once

#include <string>

#include "models/core/input.hpp"
#include "models/core/input_keys.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// Reads `file`, resolves `extends` chains (relative paths are relative to the file naming them;
/// a missing base or a cycle is an InputError naming the file that extends and the chain), then
/// validates. Throws InputError with every problem; warnings go to Scene::warnings.
Scene load_scene(const std::string& file);
/// The merged document only (extends resolved, material file paths made relative to the cwd).
Json load_scene_document(const std::string& file);
/// Validates an already-merged document; `file` is used in messages. With `keys`, records every
/// key the reader asks for (mpm/input/scene_keys.hpp).
Scene read_scene(const Json& document, const std::string& file, InputKeyRecorder* keys = nullptr);

}  // namespace impact::mpm
