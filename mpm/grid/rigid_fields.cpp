// Rigid objects on the grid: a rigid object's velocity field is not integrated. Wherever its
// particles put mass, the field moves at the object's velocity V, so its FLIP increment is zero
// (the particles keep V), its velocity gradient is zero (no strain), and contact meets it as a
// partner of infinite mass (contact/contact.hpp). Nairn's rigid material sets the nodal velocity
// of its field the same way (Nairn, NairnMPM's RigidMaterial; docs/scenes.md#rigid-objects).
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

}  // namespace impact::mpm
