// The signed distance from a point to a shape's surface and the surface's outward normal there:
// what contact against a rigid object reads as the object's own surface (contact/contact.hpp),
// exact where the mass gradient of its seeded particles is a staircase (a ramp off the grid's
// axes, a sphere) or has no central difference (a floor two cells thick).
#pragma once

#include "mpm/geometry/geometry.hpp"

namespace impact::mpm {

/// `distance` [m]: negative inside, zero on the surface; `outward`: the unit gradient of the
/// distance, the outward normal of the nearest surface point (for a point inside, of the nearest
/// face). Where two faces are equally near (a box's edge, a cylinder's rim) `outward` is their
/// normals' mean, normalised; where no direction is defined (a sphere's centre, the middle of a
/// slab, a cylinder's axis inside it) it is zero.
struct SurfaceDistance {
  double distance;
  Vec3 outward;
};

/// Exact for a box, a sphere and a capped cylinder. A hollow cylinder is the union of its open
/// tube and its cap. A union, outside its parts: the nearest part's (exact); inside: the nearest
/// face, among the parts that hold the point, that no other part buries (two boxes that touch
/// share a face that is no surface), exact but where that part's nearest face is buried (beside a
/// joint, where the normal is zero). `prism_z`: the shape is a prism along z (a plane-strain
/// body, whose grid seeds its section z = 0): its faces across z (a box's z faces, a
/// z-cylinder's ends) are not surfaces.
SurfaceDistance surface_distance(const Geometry& g, const Vec3& x, bool prism_z = false);

}  // namespace impact::mpm
