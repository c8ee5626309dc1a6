// Multi-material contact at the nodes (Bardenhagen, Guilkey, Roessig, Brackbill, Witzel & Foster
// 2001, CMES 2:509; reference_code_notes.md sec. 14). Each material (and each companion field of
// converted particles) has its own nodal mass and velocity; where two or more fields meet at a
// node their velocities are corrected towards the centre-of-mass velocity v_cm:
//   normal      n_f = unit(grad m_rest - grad m_f) (central differences of the nodal masses),
//               colinear for a pair (n_A = -n_B) so every correction sums to zero momentum;
//   detection   approach: (v_f - v_cm) . n_f > 0;  friction: approaching, or touching
//               (u_n = 0) in compression (n . sigma_I . n < 0, sigma_I = sum_p S_Ip sigma_p over
//               all fields at the node); the report's friction also glued separating surfaces
//               in compression, which fed energy in (contact.cpp);
//   correction  Dv = -u_n n - mu' |u_n| t, mu' = min(mu, |u_t| / |u_n|) (Coulomb stick / slip),
//               u = v_f - v_cm, t = u_t / |u_t|.
// Differences from the 2004 code: its normals were computed per material independently (not
// colinear), so nodal momentum was not conserved; here a node with three or more fields also
// has the mass-weighted mean correction removed, so momentum is conserved to round-off always.
// single_velocity contact is ordinary single-field MPM and never reaches this code (one field).
#pragma once

#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// Work of the contact reaction in one application [J]: with reference (start-of-step) velocities
/// w, dissipation = -sum_f m_f Dv_f . (w_f - w_cm): the reaction works only on the relative
/// motion (zero while the bodies move together, friction times slip when they slide). Not
/// sign-definite step by step (the reference is the start velocity, the correction acts on v*).
struct ContactTotals {
  double dissipation = 0.0;
  double friction_heat = 0.0;  ///< the tangential (Coulomb) part of it, turned into heat
  long contact_nodes = 0;      ///< nodes where a correction was applied
};

/// Corrects the nodal velocities `v` (all fields, Grid entry order) at every node shared by two
/// or more fields. With `reference` (the corrected start velocities) the work is booked and the
/// friction heat of each entry written to G.heat if it is sized; without, the correction is a
/// projection (pass 1, the MUSL re-map) and nothing is booked.
ContactTotals apply_contact(Grid& G, const ContactSpec& contact, std::vector<Vec3>& v,
                            const std::vector<Vec3>* reference);

}  // namespace impact::mpm
