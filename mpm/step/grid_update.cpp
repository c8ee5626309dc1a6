// Grid momentum update (Sulsky et al. 1994 eq. 24): v_I = p_I/m_I, v*_I = v_I + dt (f_I/m_I + g),
// then the face conditions as a mirror (grid/boundary.cpp), the FLIP increment v*_I - v_I, the
// faces' impulse and, for USL, the gradient velocity v^L_I (kLightNodeMassFraction).
#include <omp.h>

#include <algorithm>

#include "mpm/step/step.hpp"

namespace impact::mpm {

GridUpdate grid_update(Grid& G, double dt, const Vec3& gravity, bool usl_gradient) {
  const std::vector<NodeData>& nodes = G.nodes();
  const int n = G.node_count();
#pragma omp parallel for schedule(static) num_threads(G.threads())
  for (int i = 0; i < n; ++i) {
    const NodeData& a = nodes[i];
    if (a.mass > 0.0) {
      const Vec3 p(a.momentum[0], a.momentum[1], a.momentum[2]);
      const Vec3 f(a.force[0], a.force[1], a.force[2]);
      G.velocity[i] = p / a.mass;
      G.velocity_new[i] = G.velocity[i] + dt * (f / a.mass + gravity);
    } else {
      G.velocity[i].setZero();
      G.velocity_new[i].setZero();
    }
  }
  // The mirror holds for the start-of-step field too: the image cancels the face layer's normal
  // momentum, so the wall acts on the particles only through the stress (an affine field odd
  // about the face passes unchanged; tests/mpm/verification/uniaxial_compression_test.cpp).
  G.apply_mirror(G.velocity, /*project_face=*/true);
  G.apply_mirror(G.velocity_new, /*project_face=*/true);
#pragma omp parallel for schedule(static) num_threads(G.threads())
  for (int i = 0; i < n; ++i) G.increment[i] = G.velocity_new[i] - G.velocity[i];

  // The faces' share of each constrained node's increment, and its momentum (serial, in node
  // order: deterministic). The particles' momentum changes by sum_I m_I (v*_I - v_I), so this
  // is exactly what the faces exerted.
  GridUpdate out;
  for (int i : G.boundary_nodes()) {
    const double m = nodes[i].mass;
    if (m <= 0.0) continue;
    const Vec3 f(nodes[i].force[0], nodes[i].force[1], nodes[i].force[2]);
    const Vec3 free = dt * (f / m + gravity);
    out.boundary.impulse += m * (G.increment[i] - free);
    G.bc_increment[i] = G.velocity[i];  // scratch: the mirrored start velocity
  }
  // The faces' velocity correction: the start velocity v_I projected on the face layer minus v_I
  // (the ghost layer's v_I is already the reflection). A wall that holds a pressure without
  // motion has none; its reaction -dt f_n does no work.
  G.apply_mirror(G.bc_increment, /*project_face=*/true, /*mirror_ghost=*/false);
  for (int i : G.boundary_nodes()) {
    const bool has_mass = nodes[i].mass > 0.0;
    G.bc_increment[i] = has_mass ? Vec3(G.bc_increment[i] - G.velocity[i]) : Vec3::Zero();
  }
  // Work of the faces: v_face . impulse, zero for the stationary faces here (docs/mpm.md#ledger).
  out.boundary.work = 0.0;

  if (usl_gradient) {
    const double m_light = G.light_mass;
#pragma omp parallel for schedule(static) num_threads(G.threads())
    for (int i = 0; i < n; ++i) {
      const double alpha = G.mass[i] >= m_light ? 1.0 : G.mass[i] / m_light;
      G.velocity_L[i] = G.velocity[i] + alpha * G.increment[i];
    }
    G.apply_mirror(G.velocity_L, /*project_face=*/true);
  }
  if (!gravity.isZero(0.0)) {
    // Impulse dt m_I g and its work at the mid-step nodal velocity (serial: deterministic).
    for (int i = 0; i < n; ++i) {
      if (nodes[i].mass <= 0.0) continue;
      const Vec3 J = dt * nodes[i].mass * gravity;
      out.external_impulse += J;
      out.external_work += 0.5 * (G.velocity[i] + G.velocity_new[i]).dot(J);
    }
  }
  return out;
}

}  // namespace impact::mpm
