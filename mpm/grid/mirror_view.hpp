// What the face mirror (grid/boundary.cpp) leaves of a node's velocity, for the passes that act
// before it: contact (contact/contact.cpp) and the bodies' gap along a contact plane
// (step/contact_planes.cpp).
#pragma once

#include <array>

#include "mpm/grid/grid.hpp"

namespace impact::mpm {

// What the face mirror (grid/boundary.cpp) leaves of a node's velocity, which it applies after
// contact: `skip` for a node it overwrites whole (a ghost beyond a symmetric or fixed face, a
// node on a fixed face), else the axes it zeroes (bit d: the node lies on a symmetric face
// normal to d). Contact must see the face layer as the mirror leaves it: the particles of one
// side give a symmetric face node a normal velocity the mirror then zeroes, and counted in the
// slip it turned part of the friction onto that component. A block sliding on a block, cut in
// half by a symmetric plane along the slip, slid 1.1 % faster than the whole one
// (tests/mpm/verification/contact_friction_test.cpp); a node the mirror overwrites booked heat
// that no particle felt.
struct MirrorView {
  bool skip = false;
  int zeroed = 0;
  /// x with the components the mirror zeroes set to zero.
  Vec3 applied_to(Vec3 x) const {
    for (int d = 0; d < 3; ++d)
      if (zeroed & (1 << d)) x(d) = 0.0;
    return x;
  }
};

inline MirrorView mirror_view(const Grid& G, const std::array<int, 3>& n) {
  const GridSpec& s = G.spec();
  MirrorView view;
  for (int d = 0; d < 3; ++d) {
    if (s.planar() && d == 2) continue;  // one node plane along z, no faces there
    for (const bool upper : {false, true}) {
      const FaceCondition c = s.faces[2 * d + (upper ? 1 : 0)];
      if (c != FaceCondition::symmetric && c != FaceCondition::fixed) continue;
      const int beyond = upper ? n[d] - s.cells[d] : -n[d];  // > 0: in the ghost layer
      if (beyond > 0 || (beyond == 0 && c == FaceCondition::fixed)) view.skip = true;
      if (beyond == 0) view.zeroed |= 1 << d;
    }
  }
  return view;
}

}  // namespace impact::mpm
