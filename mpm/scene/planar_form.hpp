// What a scene's 3D bodies become on a 2D grid (scene/grid_geometry.hpp). The objects keep their
// 3D geometry, so a 2D scene and its 3D twin describe the same body; the 2D grid seeds its
// section z = 0. That section is the body only where the body has the 2D form:
//   axisymmetric: a body of revolution about the x axis (sphere centred on it, cylinder or hollow
//     cylinder along it), seeded in the half-plane y >= 0 as its meridian section;
//   plane strain: a prism along z (box, cylinder or uncapped hollow cylinder along z).
// The scene reader refuses any other (docs/scenes.md#2d-grids).
#pragma once

#include <string>

#include "mpm/geometry/geometry.hpp"

namespace impact::mpm {

/// Why `g` is not a body of revolution about the x axis ("" if it is): a sentence naming the part
/// and the form expected (the axisymmetric grid's form_problem, scene/grid_geometry.hpp).
std::string revolution_problem(const Geometry& g);

/// Why `g` is not a prism along z ("" if it is; the plane-strain grid's form_problem).
std::string prism_problem(const Geometry& g);

/// The area of the prism's section z = 0 [m^2]; a union's parts summed. `g` is a prism along z.
double section_area(const Geometry& g);

/// The area of the meridian half-section y >= 0 of a body of revolution [m^2]: a sphere's
/// half-disc, a cylinder's length times its radius, a hollow cylinder's wall and cap; a union's
/// parts summed. `g` is a body of revolution about x.
double meridian_area(const Geometry& g);

}  // namespace impact::mpm
