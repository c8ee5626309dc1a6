// What a scene's 3D bodies become on a 2D grid (scene.hpp GridGeometry). The objects keep their
// 3D geometry, so a 2D scene and its 3D twin describe the same body; the 2D grid seeds its
// section z = 0. That section is the body only where the body has the 2D form:
//   axisymmetric: a body of revolution about the x axis (sphere centred on it, cylinder or hollow
//     cylinder along it), seeded in the half-plane y >= 0 as its meridian section;
//   plane strain: a prism along z (box, cylinder or uncapped hollow cylinder along z).
// The scene reader refuses any other (docs/scenes.md#2d-grids).
#pragma once

#include <string>

#include "mpm/geometry/geometry.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// Why `g` has no form on a grid of geometry `kind` ("" if it has one, and always on a 3D grid):
/// a sentence naming the part and the 2D form expected.
std::string planar_form_problem(const Geometry& g, GridGeometry kind);

/// The volume a grid of geometry `kind` models of `g` [m^3]: the body's (3D and axisymmetric,
/// where it is the revolved body), or per metre of thickness (plane strain: the section's area
/// times 1 m). `g` has its 2D form (planar_form_problem is empty).
double modelled_volume(const Geometry& g, GridGeometry kind);

/// The area of the section z = 0 that a 2D grid of geometry `kind` seeds of `g` [m^2]: the
/// meridian half-section y >= 0 (axisymmetric: a sphere's half-disc, a cylinder's length times
/// its radius, a hollow cylinder's wall and cap), or the prism's section (plane strain); a
/// union's parts summed. `g` has its 2D form. (The memory estimate's particle count.)
double seeded_area(const Geometry& g, GridGeometry kind);

}  // namespace impact::mpm
