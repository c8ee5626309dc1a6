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

void Grid::apply_mirror(std::vector<Vec3>& field_values, MirrorTime when) const {
  // The writes were listed at construction (face layers of every face, then the ghost layers in
  // face order: a ghost corner node is the reflection in both planes of an interior node) and
  // restricted to the active blocks by activate().
  const std::array<double, 6>& V = face_velocity_[when == MirrorTime::start ? 0 : 1];
  for (int f = 0; f < fields_; ++f) {
    Vec3* v = field_values.data() + std::size_t(f) * node_count();
    for (const MirrorWrite& w : mirror_active_) {
      Vec3& x = v[w.target];
      if (w.source < 0) {
        if (w.fixed) {
          x.setZero();
        } else {
          x(w.axis) = V[w.face];
        }
      } else {
        Vec3 m = v[w.source];
        if (w.fixed) {
          m = -m;
        } else {
          // The image about the plane moving at V; a still plane keeps the plain reflection's
          // bits (-0 for +0).
          m(w.axis) = V[w.face] == 0.0 ? -m(w.axis) : 2.0 * V[w.face] - m(w.axis);
        }
        x = m;
      }
    }
  }
}

double Grid::moving_face_work(int node, const Vec3& impulse) const {
  const std::array<int, 3> ijk = this->ijk(node);
  double work = 0.0;
  for (int d = 0; d < 3; ++d) {
    const int face = ijk[d] <= 0 ? 2 * d : ijk[d] >= spec_.cells[d] ? 2 * d + 1 : -1;
    if (face < 0 || !spec_.face_velocity[face].set) continue;
    work += impulse(d) * 0.5 * (face_velocity_[0][face] + face_velocity_[1][face]);
  }
  return work;
}

}  // namespace impact::mpm
