// Multi-material contact at the nodes (Bardenhagen, Guilkey, Roessig, Brackbill, Witzel & Foster
// 2001, CMES 2:509; docs/report_code.md sec. 14). Each material (and each companion field of
// converted particles) has its own nodal mass and velocity; where two or more fields meet at a
// node their velocities are corrected towards the centre-of-mass velocity v_cm:
//   normal      (against a rigid object: its own surface, below)
//               `mass_gradients` (the default): n_f = unit(grad m_rest - grad m_f), the report's
//               (colinear for a pair, n_A = -n_B, so every correction sums to zero momentum).
//               `larger_volume`, for a pair: the surface of the body with more volume (m / rho0)
//               at the node, -grad m_b / |.| for that body b and +grad m_b / |.| for the other
//               (colinear too); the sum where that body has no gradient, and for three or more
//               bodies. At the corner of a small body resting on a large one the larger body's
//               face is the contact surface: the sum of the gradients tilts there towards the
//               small body's side face, sees its slide as an approach, and took 0.9 m/s in 10 us
//               off a block sliding at 5 m/s on another, then decelerated it 1.6 times faster
//               than Coulomb's law. Where two equal bodies' edges meet, the sum is the right one
//               (docs/mpm.md#velocity-fields-and-contact-physicscontact-contact).
//               `logistic_regression`, for a pair: the normal of the plane that separates the
//               two bodies' particles weighing on the node (Nairn, Hammerquist & Smith 2020;
//               contact/separating_plane.hpp, fitted each step by step/contact_planes.cpp to
//               the particles within about two cells): right where two equal bodies' edges meet,
//               close at a small body's corner on a large flat one, and the only normal that lets
//               a pressed interface off the grid's axes slide (a block on a ramp); the sum where
//               no plane was fitted (three or more bodies, mixed particles) and within a body.
//   detection   approaching, u_n = (v_f - v_cm) . n_f > 0. Bodies pressed together meet it at
//               every step (the compressed material pushes its nodes outward), so the friction
//               they transmit is bounded by the normal impulse of the step: a block resting on
//               another under gravity, pushed along the interface, sticks below mu and slides at
//               g_t - mu g_n above it (tests/mpm/verification/contact_friction_test.cpp). The
//               step never holds a separating pair (the strain pass keeps the step's decision:
//               ContactPass below): the report's friction also glued separating
//               surfaces in compression, which fed energy in; the rule that replaced it, touching
//               (u_n = 0) in compression, corrected nothing (u_n = 0 gives no correction) and has
//               been removed with its nodal-stress scatter. Approach alone starts contact where
//               the bodies' stencils first share a node, up to two cells before their particles
//               meet. `separation` (with the fitted plane): also the gap between the two bodies'
//               particle domains along the plane's normal (Grid::contact_gap, measured by
//               step/contact_planes.cpp) must be closed; a pair with a gap above 0.02 of the
//               node's smallest cell is apart in every pass of the step (Nairn, Hammerquist &
//               Smith 2020's displacement check; the margin: contact.cpp kGapMargin). At a
//               node of three or more bodies the gap is measured pair by pair; where none could
//               be measured (mixed particles: no plane), approach alone.
//   correction  Dv = -u_n n - s t, s = min(mu u_n, |u_t|), u = v_f - v_cm, t = u_t / |u_t|:
//               Coulomb slip, or stick when s = |u_t|. With a rigid object at the node v_cm is
//               its velocity (infinite mass; with two, the one with more volume there), it
//               takes no correction, and the mean correction is not removed: the momentum the
//               others gain is its reaction (grid/rigid_fields.cpp). The normal there is the
//               rigid body's own surface whatever `normal` says (it does not deform): its
//               geometry's, the nearest surface's outward normal at the node (moved by V t;
//               mpm/geometry/surface_distance.hpp; at a node inside it, the face where it is
//               left along the other body's mass gradient, grid/rigid_fields.cpp); where that
//               gives no direction, grad m_rigid (grad m_rigid - grad m_f deep inside it, where
//               its own gradient is round-off; contact.cpp normal_against_rigid). At a node of
//               three or more bodies
//               with a rigid one, each is corrected against the rigid alone; the other bodies
//               are not corrected against each other there.
//   heat        only in slip (s < |u_t|; static friction does no work): m_f s (u0_f . t) >= 0
//               per field, the friction impulse times the relative slip at the start of the step
//               (u0 = v0_f - v0_cm of the corrected start field) along the slip direction t; a
//               wall books the same where the material slides, u0 . t > s (grid/wall.cpp, why
//               not here: docs/mpm.md#ledger).
// `friction` and `approach` are this one model (the report's Table 2 names both: its approach
// contact was its friction without the compression rule).
// Bodies: a material's parent field and the companion field of its converted particles are one
// body against the other materials (their summed mass, momentum and mass gradient: the surface
// the other body sees), and a pair between themselves, corrected after. Correcting each of three
// or four fields against the centre of mass of all the others, with normals that are not
// colinear and the mean correction removed afterwards, is not a projection: it took kinetic
// energy at every step (sphere-cylinder case 1 to 10 us at multiplier 0.1: energy_error -6.98 %
// against -0.14 % for a single field; -0.78 % with bodies; docs/sphere_cylinder.md).
// Differences from the 2004 code: its normals were computed per material independently (not
// colinear), so nodal momentum was not conserved; here a node with three or more bodies also
// has the mass-weighted mean correction removed, so momentum is conserved to round-off (but for
// a rigid object's reaction, booked as a boundary impulse).
// single_velocity contact is ordinary single-field MPM and never reaches this code (one field).
#pragma once

#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/ledger/totals.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// The work of the contact reactions in one correction [J] (docs/mpm.md#ledger). The normal
/// reaction keeps the fields from interpenetrating: after it acts their relative normal velocity
/// is zero, so it does no work on the motion the bodies make; the kinetic energy it takes from
/// the nodes returns as the strain energy of the compression the constrained positions impose
/// (booking it as a loss counted that energy twice: +7.6 % of E0 on the elastic contact blocks).
/// The friction reaction's Coulomb dissipation is m s (u0 . t) >= 0 per field in slip (s < |u_t|),
/// s = min(mu u_n, |u_t|) the slip it removes; zero in stick.
/// A rigid object (SceneObject::rigid) is a partner of infinite mass: the other bodies are
/// corrected against its velocity V, it is never corrected, and the momentum they gain is its
/// reaction, booked as a boundary's impulse J (the sum of m dv over the fields it corrected), its
/// work J . V (zero for a body at rest) as external work, as a moving face's.
struct ContactTotals {
  double friction_heat = 0.0;         ///< >= 0 [J]
  long contact_nodes = 0;             ///< nodes where a correction was applied
  Vec3 rigid_impulse = Vec3::Zero();  ///< what the rigid objects gave the other bodies [N s]
  double rigid_work = 0.0;            ///< its work, J . V [J]
  /// How each total combines over threads and ranks (mpm/ledger/totals.hpp).
  static constexpr auto kFields =
      std::tuple{summed(&ContactTotals::friction_heat), summed(&ContactTotals::contact_nodes),
                 summed(&ContactTotals::rigid_impulse), summed(&ContactTotals::rigid_work)};
};

/// Which correction: `start` on the start velocities (the start the step's forces act from; the
/// particles' velocities never carry it, so nothing is booked), `step` on v* (the step's contact
/// impulse, which the particles see: books the friction work, writes G.heat and marks the nodes
/// it corrected in G.contact_held), `strain` on the velocity the strain is built from (MUSL's
/// re-map, USL's v^L; nothing booked): at the nodes the step corrected the relative normal
/// velocity is zeroed whatever its sign (the step's decision holds), keeping the fields' centre
/// of mass (against a rigid object: its velocity), and where the step's friction stuck the pair (s
/// = |u_t|) all of it, the slip too; elsewhere it is corrected where the fields approach; Coulomb
/// acts where they approach. (Re-mapped from the particles' FLIP velocities, a stuck interface read
/// a slip that had not happened; the strain rate sheared it and friction pumped a resting stack:
/// three blocks on a wall, mu 0.3, rattled after 20 000 quiet steps and the energy check stopped
/// them at step 24 576; now they stay at rest to 1 ms, stack_friction.json. Taking the step's v*
/// itself there instead, an experiment not landed, took 6.9 % of the sliding contact blocks' energy
/// against 2.7 %: at a light node v* is p / m of a sliver of mass, and the strain pass must not
/// move the fields' centre of mass. Nairn re-decides stick and slip on the re-mapped momenta;
/// carrying the step's stick over departs from that as the hold does. Exact for a pair; at a node
/// of three or more bodies the stuck ones are corrected against all the others and the mean
/// removed, as in the step.) (Holding only the step's nodes and leaving the others alone let a
/// block sliding on a block and its half cut by a symmetric plane differ by 0.016 m/s of a 5 m/s
/// slip, against 5e-6 m/s.)
///
/// Why the strain pass follows the step. Summed over a node's fields, a step whose strain is built
/// from v* books Delta KE + Delta U <= 0: at a held node (frictionless, forces along n)
/// -dt^2 (f_1^2/m_1 + f_2^2/m_2)/2 + mu_12 dt^2 (f_1/m_1 + f_2/m_2)^2/2 <= 0 by Cauchy-Schwarz
/// (the contact's part only: the stress power booked on the mid-step stress adds its own
/// positive O(dt^2) term, single field or not). The strain velocity is not v*: MUSL's re-map
/// spreads each body's increments over its particles, which dilutes the contact impulse at the
/// interface nodes, and USL scales a light node's increment. Where that velocity let the fields
/// separate at a node the step held, the stress did work the nodes did not. This departs from
/// Nairn's post-update extrapolation, which decides contact again from the re-mapped momenta (as
/// the earlier rule here did); nothing is glued for longer than the step: the strain pass moves
/// no momentum, and the next step decides afresh. Re-deciding contact from it (the earlier rule:
/// correct where the re-mapped fields approach) made energy between dissimilar bodies, first order
/// in dt: an elastic steel rod on an aluminium plate at 100 m/s, 6 cells per rod radius, +30.1 /
/// +15.5 / +8.2 % of its energy by 40 us at multipliers 0.5 / 0.25 / 0.125, +22 % with USL; holding
/// the step's nodes, -0.05 % and -1.7 % (tests/mpm/verification/dissimilar_contact_test.cpp,
/// docs/mpm.md#velocity-fields-and-contact-physicscontact-contact). Replacing the strain
/// velocity's normal component by v*'s instead (a new switch, discontinuous in u_n) lost
/// 6.6 % on two elastic blocks and swapped round-off for 1e-4 m/s differences between a body and
/// its symmetric half.
enum class ContactPass { start, step, strain };

/// Corrects the nodal velocities `v` (all fields, Grid entry order) at every node shared by two
/// or more fields.
ContactTotals apply_contact(Grid& G, const ContactSpec& contact, std::vector<Vec3>& v,
                            ContactPass pass);

}  // namespace impact::mpm
