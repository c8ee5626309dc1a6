// Grid face conditions as a mirror (Bardenhagen & Kober 2004 sec. 4; docs/report_code.md
// sec. 15): a symmetric face is a rigid frictionless wall, i.e. a mirror plane through the face
// nodes. On the face layer the normal component is zeroed (the mirror image cancels it); the ghost
// layer outside, which uGIMP reaches from the first half cell, carries the reflection of the first
// interior layer: v_ghost = M v_inner with M = diag(-1 normal, +1 tangential). Then an affine
// field odd about the face (v_n = -rate x_n) is continued exactly, and a particle in the first
// cell sees the same nodal field as its image would. A fixed face is the antisymmetric mirror
// (M = -I, all components zeroed on the face layer). The 2004 code zeroed all three components of
// the ghost layer of every symmetric face (missing braces: docs/report_code.md sec. 0 item 11).
#include "mpm/grid/grid.hpp"

namespace impact::mpm {

void Grid::apply_mirror(std::vector<Vec3>& field_values) const {
  // The writes were listed at construction (face layers of every face, then the ghost layers in
  // face order: a ghost corner node is the reflection in both planes of an interior node) and
  // restricted to the active blocks by activate().
  for (int f = 0; f < fields_; ++f) {
    Vec3* v = field_values.data() + std::size_t(f) * node_count();
    for (const MirrorWrite& w : mirror_active_) {
      Vec3& x = v[w.target];
      if (w.source < 0) {
        if (w.fixed) {
          x.setZero();
        } else {
          x(w.axis) = 0.0;
        }
      } else {
        Vec3 m = v[w.source];
        if (w.fixed) {
          m = -m;
        } else {
          m(w.axis) = -m(w.axis);
        }
        x = m;
      }
    }
  }
}

}  // namespace impact::mpm
