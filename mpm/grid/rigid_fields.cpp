// Rigid objects on the grid: a rigid object's velocity field is not integrated. Wherever its
// particles put mass, the field moves at the object's velocity V, so its FLIP increment is zero
// (the particles keep V), its velocity gradient is zero (no strain), and contact meets it as a
// partner of infinite mass (contact/contact.hpp). Nairn's rigid material sets the nodal velocity
// of its field the same way (Nairn, NairnMPM's RigidMaterial; docs/scenes.md#rigid-objects).
#include <algorithm>

#include "mpm/geometry/surface_distance.hpp"
#include "mpm/grid/grid.hpp"

namespace impact::mpm {

void Grid::hold_rigid_fields(std::vector<Vec3>& v) const {
  if (!has_rigid_fields()) return;
  const int nn = node_count();
  for (int f = 0; f < fields_; ++f) {
    if (!is_rigid_field(f)) continue;
    const Vec3 V = settings_.rigid_velocity[std::size_t(f)];
    for (const int I : active_) {
      const int e = f * nn + I;
      if (mass[e] > 0.0) v[e] = V;
    }
  }
}

// The object's particles move at V from their seed points, so at time t its surface is the
// seeded geometry moved by V t. A 2D grid's node plane is the section z = 0 the grid seeds
// (scene/planar_form.hpp); a plane-strain body is a prism along z, whose z faces are none.
// A node inside the object has a nearest face that need not be the one the other body meets: the
// far face of a slab two cells thick, a side face within a cell of an edge. There the surface
// is the one nearest to a point on the body's side, the node moved along `toward` out of the
// object (its depth and two cells more). A test of the node's own normal against the body's
// gradient instead (accepted within 60 degrees of it) threw most nodes of a pressed ramp back on
// the staircase gradient: the block on a rigid 20-degree ramp slid at 0.56 of Coulomb's rate.
Vec3 Grid::rigid_inward_normal(int f, int node, const Vec3& toward) const {
  if (settings_.rigid_surface.empty()) return Vec3::Zero();
  const std::optional<Geometry>& surface = settings_.rigid_surface[std::size_t(f)];
  if (!surface) return Vec3::Zero();
  const std::array<int, 3> n = ijk(node);
  Vec3 x = Vec3::Zero();
  for (int d = 0; d < spec_.dimensions(); ++d) x(d) = node_coordinate(d, n[d]);
  x -= settings_.rigid_velocity[std::size_t(f)] * time_;
  const bool prism_z = spec_.per_metre_of_thickness();  // its bodies: prisms along z
  SurfaceDistance s = surface_distance(*surface, x, prism_z);
  const double norm = toward.norm();
  if (s.distance < 0.0 && norm > 0.0) {
    const Vec3 h = spec_.spacing();  // the base cells, the largest of a graded grid
    const double cell = spec_.planar() ? std::max(h(0), h(1)) : h.maxCoeff();
    const double out = -s.distance + 2.0 * cell;
    s = surface_distance(*surface, x + out * (toward / norm), prism_z);
  }
  return -s.outward;
}

}  // namespace impact::mpm
