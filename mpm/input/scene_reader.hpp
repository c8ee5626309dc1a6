// The scene reader (docs/scenes.md): a JSON scene file read into a validated Scene. `extends` names
// a base scene; the file's own content is applied over it as an RFC 7396 JSON merge patch,
// recursively; every problem is reported at once with its file and key path. It sits
// above what it checks against: the shape catalogue (solver.interpolation) and the seed points
// (a body that would get no particle is refused).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "models/core/input.hpp"
#include "models/core/input_keys.hpp"
#include "mpm/scene/scene.hpp"
#include "support/patch_origins.hpp"

namespace impact::mpm {

/// Reads `file`, resolves `extends` chains (relative paths are relative to the file naming them;
/// a missing base or a cycle is an InputError naming the file that extends and the chain), then
/// validates. Throws InputError with every problem; warnings go to Scene::warnings.
Scene load_scene(const std::string& file);
/// The files of an extends chain with the document each one merges (without its "extends"): the
/// base of all first, the scene file itself last.
using ExtendsChain = std::vector<std::pair<std::string, Json>>;

/// The merged document only (extends resolved, material file paths made relative to the cwd);
/// `chain`, when given, receives the files of the extends chain (extends_origins).
Json load_scene_document(const std::string& file, ExtendsChain* chain = nullptr);
/// A --set patch's relative material paths made absolute from the working directory, the base
/// they are read from: "cannot open /home/u/data/m.json" then names it, where "data/m.json"
/// left the user guessing (issue 53's trial).
void resolve_patch_material_paths(Json& patch);
/// Names a problem at a key that a base scene set, and the scene file did not, after the base
/// (the last one to set it): "base.json (extended by scene.json): /grid/cell: unknown key ...",
/// where read_scene's message said "scene.json: /grid/cell: ...". Apply it after the --set
/// patches' attribution (support/patch_origins.hpp).
PatchOrigins extends_origins(const ExtendsChain& chain);
/// Validates an already-merged document; `file` is used in messages. With `keys`, records every
/// key the reader asks for (mpm/input/scene_keys.hpp).
Scene read_scene(const Json& document, const std::string& file, InputKeyRecorder* keys = nullptr);

}  // namespace impact::mpm
