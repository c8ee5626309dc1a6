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
// far face of a slab two cells thick, a side face within a cell of an edge, the wall of a bowl
// beside its floor, the near wall of a gap narrower than the body. There the surface is the one
// where the object is left along `toward` (the body's mass gradient, pointing into the body):
// marched from the node in steps of its distance to the nearest surface, which inside never
// passes a surface (sphere tracing), up to its depth and two of its cells. Taken at the node moved
// its depth and two cells at once instead (an audit's catch), a floor node within two cells of a
// bowl's wall took the wall's normal, and in a gap under four cells the other wall's, pointing
// out of the object. A test of the node's own normal against the body's gradient instead
// (accepted within 60 degrees of it) threw most nodes of a pressed ramp back on the staircase
// gradient: the block on a rigid 20-degree ramp slid at 0.56 of Coulomb's rate. A node on the
// joint of two parts (no direction) keeps the mass gradient: marching from there too took 13 % of
// the energy put into a block resting in the corner of a rigid floor and wall (against 1.5 %).
Vec3 Grid::rigid_inward_normal(int f, int node, const Vec3& toward) const {
  if (settings_.rigid_surface.empty()) return Vec3::Zero();
  const std::optional<Geometry>& surface = settings_.rigid_surface[std::size_t(f)];
  if (!surface) return Vec3::Zero();
  const std::array<int, 3> n = ijk(node);
  Vec3 x = Vec3::Zero();
  double cell = 0.0;  // the node's largest cell edge along the mesh's axes
  for (int d = 0; d < spec_.dimensions(); ++d) {
    x(d) = node_coordinate(d, n[d]);
    cell = std::max(cell, spec_.graded() ? spec_.dual_size(d, n[d]) : dx_(d));
  }
  x -= settings_.rigid_velocity[std::size_t(f)] * time_;
  const bool prism_z = spec_.per_metre_of_thickness();  // its bodies: prisms along z
  SurfaceDistance s = surface_distance(*surface, x, prism_z);
  const double norm = toward.norm();
  const bool within = s.distance < 0.0;
  if (!within || !(norm > 0.0)) return -s.outward;
  const Vec3 e = toward / norm;
  const double reach = -s.distance + 2.0 * cell, least = 1e-3 * cell;
  double travelled = 0.0;
  Vec3 p = x;
  for (int k = 0; k < 32 && travelled < reach; ++k) {
    const double step = std::min(std::max(-s.distance, least), reach - travelled);
    p += step * e;
    travelled += step;
    s = surface_distance(*surface, p, prism_z);
    if (s.distance > 0.0) break;  // out: the nearest surface is the one left through
  }
  return -s.outward;
}

}  // namespace impact::mpm
