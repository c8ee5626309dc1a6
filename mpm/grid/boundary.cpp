// Grid face conditions as a mirror (Bardenhagen & Kober 2004 sec. 4; reference_code_notes.md
// sec. 15): a symmetric face is a rigid frictionless wall, i.e. a mirror plane through the face
// nodes. On the face layer the normal component is zeroed (the mirror image cancels it); the ghost
// layer outside, which uGIMP reaches from the first half cell, carries the reflection of the first
// interior layer: v_ghost = M v_inner with M = diag(-1 normal, +1 tangential). Then an affine
// field odd about the face (v_n = -rate x_n) is continued exactly, and a particle in the first
// cell sees the same nodal field as its image would. A fixed face is the antisymmetric mirror
// (M = -I, all components zeroed on the face layer). The 2004 code zeroed all three components of
// the ghost layer of every symmetric face (missing braces: reference_code_notes.md sec. 0 item 11).
#include "mpm/grid/grid.hpp"

namespace impact::mpm {

void Grid::apply_mirror(std::vector<Vec3>& field_values) const {
  const int c[3] = {spec_.cells[0], spec_.cells[1], spec_.cells[2]};
  // The face layers first (all faces), then the ghost layers in face order: a ghost corner node
  // is then the reflection in both planes of an interior node.
  for (int f = 0; f < fields_; ++f)
    for (int pass = 0; pass < 2; ++pass) {
      Vec3* v = field_values.data() + std::size_t(f) * node_count();
      for (int face = 0; face < 6; ++face) {
        if (!constrained_[face]) continue;
        const bool fixed = spec_.faces[face] == FaceCondition::fixed;
        const int axis = face / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
        const int layer = face % 2 == 0 ? 0 : c[axis];
        const int ghost = face % 2 == 0 ? -1 : c[axis] + 1;
        const int inner = face % 2 == 0 ? 1 : c[axis] - 1;
        for (int u = -1; u <= c[a] + 1; ++u)
          for (int w = -1; w <= c[b] + 1; ++w) {
            int ijk[3];
            ijk[a] = u;
            ijk[b] = w;
            if (pass == 0) {
              ijk[axis] = layer;
              Vec3& x = v[index(ijk[0], ijk[1], ijk[2])];
              if (fixed) {
                x.setZero();
              } else {
                x(axis) = 0.0;
              }
            } else {
              ijk[axis] = inner;
              Vec3 m = v[index(ijk[0], ijk[1], ijk[2])];
              if (fixed) {
                m = -m;
              } else {
                m(axis) = -m(axis);
              }
              ijk[axis] = ghost;
              v[index(ijk[0], ijk[1], ijk[2])] = m;
            }
          }
      }
    }
}

}  // namespace impact::mpm
