// A rigid stationary wall with Coulomb friction on a grid face (grid.boundary.<face> = "wall";
// docs/scenes.md#grid). The wall is one-sided: it pushes and never pulls, the condition a Taylor
// anvil or a target support needs. Per step and face-layer node (Bardenhagen et al. 2000, CMES
// 1:509, sec. 3, with the wall as a second body of infinite mass at rest):
//   contact    the node's end velocity v* moves into the wall: v*_n = v* . n < 0, n the inward
//              normal. Then v*_n is set to zero: the FLIP increment v* - v stops the particles'
//              approach, and the normal impulse per unit mass is j = -v*_n >= 0. Otherwise the
//              node is left free (a separating surface is not held).
//   friction   the slip removed from the tangential u_t = v*_t is s = min(mu j, |u_t|): stick
//              (u_t = 0) when |u_t| <= mu j, slip otherwise.
//   heat       m s (|u_t| - s) >= 0 per node, the Coulomb work on the slip that remains (the
//              convention of contact/contact.hpp), delivered to the particles through Grid::heat.
// Only v* is corrected, unlike the mirror, which zeroes the start velocity's normal component too
// (there the image makes it zero): holding the start as well let the particles keep their
// approach velocity, the face layer was clamped inward and free outward, and a block pressed on
// the wall by gravity crept off it, the books gaining 16 % of E0 in 240 us.
// Why one-sided: a mirror plane also pulls, and its normal impulse alternates in sign with the
// grid-scale vibration of the face layer; bounding friction by |j| per step rectified that
// vibration into friction (a sliding block decelerated 1.5-2 times mu g). The one-sided wall has
// j >= 0, and its impulses add up to the load (tests/mpm/verification/wall_friction_test.cpp).
// The ghost layer outside the wall stays the mirror image of the first interior layer
// (grid/boundary.cpp), which the particles next to the face read while they touch it.
#include <cmath>

#include "mpm/grid/grid.hpp"

namespace impact::mpm {

double Grid::apply_walls(std::vector<Vec3>& end, WallPass pass) {
  const bool step = pass == WallPass::step;
  const bool write_heat = step && !heat.empty();
  double total_heat = 0.0;
  // Serial, in face-node order: the heat sum is deterministic.
  for (int f = 0; f < fields_; ++f) {
    const int offset = f * node_count();
    for (const WallNode& w : wall_active_) {
      const int e = offset + w.node;
      Vec3& v = end[e];
      const double vn = w.inward * v(w.axis);
      if (!(vn < 0.0)) continue;  // at rest on it or leaving: the wall does not pull
      v(w.axis) = 0.0;
      if (!step || w.mu == 0.0) continue;
      const double slip = v.norm();  // tangential: the normal component is zero now
      if (slip == 0.0) continue;
      const double s = std::min(w.mu * -vn, slip);  // -vn: the normal impulse per unit mass
      v *= (slip - s) / slip;
      const double h = mass[e] * s * (slip - s);
      if (owns(w.node)) total_heat += h;  // booked once in a domain decomposition
      if (write_heat) heat[e] += h;
    }
  }
  return total_heat;
}

}  // namespace impact::mpm
