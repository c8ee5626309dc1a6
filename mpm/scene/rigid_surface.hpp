// The surface of each rigid velocity field (SceneObject::rigid): what contact meets as the rigid
// partner's own surface (contact/contact.hpp), its geometry as seeded, at rest at t = 0.
#pragma once

#include <optional>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// Per velocity field (Scene::field_count()): the union of the rigid objects' geometries it
/// carries; empty for a field with no rigid object, and for one whose object an earlier object of
/// another field cuts (object_overlap.hpp: its seeded body is not its geometry, and its mass
/// gradient serves).
/// A face of a box or a cylinder's end that lies on, or beyond, a `symmetric` or `wall` face of
/// the grid that does not move, and that the object does not move away from, is no surface: the
/// body continues there as its mirror image (as the contact normals' masses do,
/// contact/contact.cpp), so the part is extended by its image across that face. The whole
/// vector is empty when no object is rigid.
std::vector<std::optional<Geometry>> rigid_field_surfaces(const Scene& scene);

}  // namespace impact::mpm
