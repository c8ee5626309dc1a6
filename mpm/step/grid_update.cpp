// Grid momentum update (Sulsky et al. 1994 eq. 24): v_I = p_I/m_I, v*_I = v_I + dt (f_I/m_I + g)
// per velocity field; contact between fields (contact/contact.hpp) on v_I and on v*_I (the two
// passes of Bardenhagen et al. 2001); then the face conditions as a mirror (grid/boundary.cpp),
// the walls (grid/wall.cpp), the FLIP increment v*_I - v_I, and, for USL, the gradient velocity
// v^L_I (kLightNodeMassFraction). The particles move with the corrected v*_I and their velocity
// changes by the increment between the CORRECTED fields, as in Bardenhagen et al. (2001) and
// single-field MPM: the first pass only sets the start from which the step's forces act, and the
// second pass (the contact impulse of the step) reaches both the positions and the velocities.
// Handing the particles the first pass too (the increment from the uncorrected p_I/m_I) removes the
// same approach velocity again at every step, because the particles keep carrying it to the grid:
// the sphere-cylinder lost 26 % of E0 in 10 us that way
// (docs/mpm.md#velocity-fields-and-contact-physicscontact-contact). The mirror faces act on the
// start and end velocities alike: a stationary wall does no work; a `wall` holds the end velocity
// of the face nodes its body touches (grid/wall.cpp) (docs/mpm.md#ledger). A rigid object's field
// is held at its velocity after each of these (grid/rigid_fields.cpp).
#include <omp.h>

#include <algorithm>

#include "mpm/contact/contact.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

GridUpdate grid_update(Grid& G, double dt, const Vec3& gravity, bool usl_gradient,
                       const ContactSpec* contact) {
  const std::vector<NodeData>& nodes = G.nodes();
  const bool contact_on = contact != nullptr && G.fields() > 1;
  G.for_active_entries([&](int i) {
    const NodeData& a = nodes[i];
    if (a.mass > 0.0) {
      G.velocity[i] = Vec3(a.momentum[0], a.momentum[1], a.momentum[2]) / a.mass;
    } else {
      G.velocity[i].setZero();
    }
  });
  GridUpdate out;
  G.hold_rigid_fields(G.velocity);  // a rigid object's field moves at its velocity, always
  // Friction heat of this step (contact and walls add to it; grid-to-particles reads it).
  if (!G.heat.empty()) G.for_active_entries([&](int e) { G.heat[e] = 0.0; });
  if (contact_on) apply_contact(G, *contact, G.velocity, ContactPass::start);
  G.for_active_entries([&](int i) {
    const NodeData& a = nodes[i];
    if (a.mass > 0.0) {
      const Vec3 f(a.force[0], a.force[1], a.force[2]);
      G.velocity_new[i] = G.velocity[i] + dt * (f / a.mass + gravity);
    } else {
      G.velocity_new[i].setZero();
    }
  });
  G.hold_rigid_fields(G.velocity_new);
  // The step's contact impulse on v*: the particles see it, the ledger books its friction work.
  // A rigid object's reaction is a boundary's: its impulse, and its work at its velocity.
  if (contact_on) {
    out.contact = apply_contact(G, *contact, G.velocity_new, ContactPass::step);
    out.boundary_impulse += out.contact.rigid_impulse;
    out.external_work += out.contact.rigid_work;
  }

  // The mirror holds for the start-of-step field too: the image cancels the face layer's normal
  // momentum, so the wall acts on the particles only through the stress (an affine field odd
  // about the face passes unchanged; tests/mpm/verification/uniaxial_compression_test.cpp).
  // Only the boundary nodes in active blocks can carry mass (Grid::active_boundary()).
  const std::vector<int>& bn = G.boundary_nodes();
  const std::vector<int>& active_bn = G.active_boundary();
  const std::size_t nb = bn.size();
  const int nn = G.node_count();
  for (int f = 0; f < G.fields(); ++f)
    for (const int k : active_bn) {
      const int e = f * nn + bn[k];
      G.free_increment[f * nb + k] = G.velocity_new[e] - G.velocity[e];
    }
  G.apply_mirror(G.velocity, MirrorTime::start);
  G.apply_mirror(G.velocity_new, MirrorTime::end);
  if (G.has_walls())
    out.wall_friction_heat = G.apply_walls(&G.velocity, G.velocity_new, WallPass::step);
  G.hold_rigid_fields(G.velocity);  // the faces do not move a rigid object either
  G.hold_rigid_fields(G.velocity_new);
  if (!gravity.isZero(0.0)) {
    // Impulse dt m_I g and its work at the mid-step velocity the node keeps, after contact, the
    // mirror and the walls (serial, ascending entries: deterministic, and the same order on the
    // dense grid). Booked before the faces held their nodes, a body resting on a face was
    // credited about M_face g^2 dt^2 / 2 a step that no motion made (2.1e-6 J in 240 us against
    // 9.2e-9 J of potential energy released; issue 53).
    const std::vector<int>& active = G.active_nodes();
    for (int f = 0; f < G.fields(); ++f) {
      if (G.is_rigid_field(f)) continue;  // held at its velocity: gravity does not move it
      for (const int I : active) {
        const int i = f * G.node_count() + I;
        if (nodes[i].mass <= 0.0 || !G.owns(I)) continue;
        const Vec3 J = dt * nodes[i].mass * gravity;
        out.external_impulse += J;
        out.external_work += 0.5 * (G.velocity[i] + G.velocity_new[i]).dot(J);
      }
    }
  }
  G.for_active_entries([&](int i) { G.increment[i] = G.velocity_new[i] - G.velocity[i]; });
  // The faces' impulse: what they changed in the increments that move the particles (serial, in
  // node order: deterministic). A stationary wall does no work (docs/mpm.md#ledger).
  const bool moving_faces = G.spec().has_moving_faces();
  for (int f = 0; f < G.fields(); ++f)
    for (const int k : active_bn) {
      const int e = f * nn + bn[k];
      if (nodes[e].mass <= 0.0 || !G.owns(bn[k])) continue;
      const Vec3 J = nodes[e].mass * (G.increment[e] - G.free_increment[f * nb + k]);
      out.boundary_impulse += J;
      // A moving face works on what it holds: its impulse times its mid-step velocity (an
      // external work, docs/mpm.md#ledger); a still face does none.
      if (moving_faces) out.external_work += G.moving_face_work(bn[k], J);
    }

  if (usl_gradient) {
    const double m_light = G.settings().light_mass;
    // Axisymmetric: the ring masses grow with the radius, so does the mass of a light node.
    const double per_radius =
        G.settings().light_radius > 0.0 ? m_light / G.settings().light_radius : 0.0;
    const int nn = G.node_count();
    const bool graded = G.settings().node_mean_mass;
    G.for_active_entries([&](int i) {
      double light = per_radius > 0.0
                         ? per_radius * std::max(G.settings().light_radius,
                                                 G.node_coordinate(1, G.ijk(i % nn)[1]))
                         : m_light;
      // Graded: particles of one body differ in mass with their seeded cells (by factor^3), so
      // the threshold is the node's own mean particle mass, sum S m_p^2 / sum S m_p. One
      // threshold (the lightest particle's) let a coarse particle's sliver through: a linear/USL
      // rigid translation across a factor-2 grading stopped unstable at step 158 of 206
      // (tests/mpm/verification/rigid_translation_test.cpp).
      if (graded && G.mass[i] > 0.0)
        light = kLightNodeMassFraction * nodes[i].mass_moment / G.mass[i];
      const double alpha = G.mass[i] >= light ? 1.0 : G.mass[i] / light;
      G.velocity_L[i] = G.velocity[i] + alpha * G.increment[i];
    });
    // The light-node rule scales an increment contact may have bounded: the step's held nodes
    // stay held (contact.hpp, ContactPass::strain).
    if (contact_on) {
      apply_contact(G, *contact, G.velocity_L, ContactPass::strain);
      // As MUSL's re-map (grid_to_particles.cpp): the walls hold what contact may have moved.
      if (G.has_walls()) G.apply_walls(nullptr, G.velocity_L, WallPass::projection);
    }
    G.apply_mirror(G.velocity_L);
    G.hold_rigid_fields(G.velocity_L);
  }
  return out;
}

}  // namespace impact::mpm
