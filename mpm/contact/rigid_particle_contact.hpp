// Contact against rigid objects at the particles (physics.contact.rigid_contact = "particles";
// docs/scenes.md#rigid-objects), instead of at the shared nodes (contact/contact.hpp); and
// against the `wall` faces of the grid (grid.wall_contact = "particles"; docs/scenes.md#grid),
// instead of at their face nodes (grid/wall.cpp). A wall is a plane at rest, phi(x) = n . x -
// offset with n its inward normal, its friction the face's wall_friction and its damping
// grid.wall_penalty_damping; a rigid object's are its mu (objects.<name>.mu, else contact.mu) and
// contact.penalty_damping.
// Why for walls: a wall's face nodes catch each arrival inelastically and hold and release a
// ringing face layer, so a body that stays on a wall loses energy without converging (a block
// spanning two walls: energy_error -0.94 at h, -0.87 at h/2; a block stuck under a tilted load
// applied at once, -0.50; one in a three-wall corner, -0.097; docs/verification.md). At the
// particles nothing is caught: the same three keep their books within 0.03, 1e-4 and 2e-4.
// What differs for walls: the wall's plane ends the grid, so a particle whose centre passes it
// leaves the grid and stops the run, where one that passes a rigid object's surface is pushed on
// from inside. So a wall's push counts the particle's whole domain (no clip to the seed point's
// depth in its body, which at a curved body's surface left a reach of microns and let a Hertz
// sphere's particle through at 10 m/s; an audit's catch), and its stiffness takes the closing
// speed kWallSpeed = 4 times, k_p = kStiffness m_p (c0 + 4 V_c)^2 / h^2: a particle alone
// arriving at V_c is stopped within its reach l = h / 4 when the energy stored there, k_p l^2 /
// 6, exceeds m_p V_c^2 / 2, i.e. for c0 + a V_c >= sqrt(12) V_c, a >= 3.46. With c0 + V_c a
// soft block (c0 = 116 m/s) thrown at 50 to 200 m/s, and an aluminium one at 1800 m/s, went
// through at the first contact (a new user's trial). The time step keeps this signal speed.
// A load beyond about rho0 (c0 + 4 V_c)^2 / 4 still pushes a particle through; the walls at the
// nodes hold any.
//
// Why: at the nodes, each contact node holds the rigid surface's normal at its own place, and
// the one-sided holds of a patch of nodes act as a kinematic constraint. On a curved surface the
// normals of the patch meet at its centre of curvature, and the only motion that keeps every held
// node's normal velocity is a turn about that centre: a disk sliding in a frictionless trough of
// radius R turns at omega r / v = r / (R - r) whatever h (docs/verification.md). A force per
// particle, along the exact surface's normal at the particle's own place, constrains no motion:
// the patch's forces add up to one through the contact region, and the patch shrinks with h.
//
// The force is a penalty (Wriggers, Computational Contact Mechanics, 2006) on each deformable
// particle whose domain reaches into a rigid object's exact surface. With
// phi(x) the signed distance of x from the surface (positive outside the object, its geometry
// moved by V t; geometry/surface_distance.hpp) and n its outward normal:
//   reach   c_p = min(l_min, d_p, max(0, phi_0(X_p))): the radius of the largest sphere in the
//           domain (l_min, uGIMP's smallest half-width over the mesh's axes), clipped to d_p, the
//           depth of the particle's seed point X_p inside its own object's geometry, and to
//           phi_0(X_p), its distance from the rigid object as seeded. A domain that overhangs its
//           body's true surface (a seed point beside a curved or oblique face, or beside a rigid
//           object that cuts the body) does not count: a body seeded touching or around a rigid
//           object starts with no overlap, where the unclipped domains of a disk in a trough
//           launched it (energy_error +107 in a prototype), and of a block around a rigid pin
//           gave it 1522 J/m at t = 0 (an audit's catch). c_p does not depend on x_p, so the force
//           below is the gradient of its energy (a reach l . |n| along the normal made it not).
//   overlap delta_p = c_p - phi(x_p), when > 0;
//   force   f_p = F(delta_p) n, growing smoothly from zero over the onset delta_s = h / 4:
//             F = k_p delta^2 / (2 delta_s)     for delta < delta_s,
//             F = k_p (delta - delta_s / 2)     beyond,
//           k_p = kStiffness m_p (c0 + V_c)^2 / h^2 min(1, (0.5 / time.multiplier)^2), c0 the
//           particle material's reference longitudinal speed sqrt((K + 4 G / 3) / rho0) and h the
//           grid's smallest spacing: the penalty's largest frequency sqrt(k_p / m_p) times the
//           step multiplier h / (c0 + V_c) is at most 1, half the explicit bound of 2.
//   speed   V_c, the closing speed the scene starts with: its fastest deformable body's initial
//           speed plus its fastest rigid object's. Why: a penalty of c0 alone stops a particle
//           within its reach only while the closing speed is below about c0; a soft block (c0 =
//           116 m/s) dropped at 1000 m/s on a rigid floor three cells thick passed through it
//           (a new user's trial). With V_c the contact pressure at an overlap of a cell is of
//           the impact's rho (c0 + V) V. It is fixed for the run, so the force stays the
//           gradient of its energy, and the time step keeps a signal speed of at least c0 + V_c
//           (signal_speed()): after an impact the steps stay those of its start. A body that
//           gravity or a body force speeds up to well beyond c0 + V_c is not covered.
//           Why the onset: a force that jumps to k_p delta as the domain enters acts a whole
//           step or not at all, and each entry and exit of a particle works up to k_p (v_n dt)^2
//           / 2 that no motion paid for. The onset keeps the books of bounces: a block spanning
//           two rigid blocks ends at energy_error -0.0073 with it, -0.021 with h / 20. The price
//           is a compliant layer, which carries a pressure p at an overlap of (h / 2) sqrt(p /
//           (rho c0^2)) (0.6 um for a 2 mm aluminium block under 1e5 m/s^2 at h = 0.5 mm, 1 um
//           at the ringing's peak; 8 um, a lag of 8 us, for a rigid piston pushing at 1 m/s at
//           h = 1.25 mm).
//   motion  a particle pushed this step moves with the velocity its strain sees, not with v*_I
//           (step/step.hpp, grid_to_particles): its W is a function of x_p, and the strain energy
//           of its neighbours of the displacement L integrates; driven by two velocities the two
//           energies trade work that is not a gradient, and a column resting on a rigid floor
//           gained energy until the energy check stopped it (docs/verification.md). Pushed is
//           decided at x^n: a particle entering contact within the step moves with v*_I, its
//           energy then below k delta^3 / (6 delta_s). Gravity's work stays booked at the nodes
//           with v*_I (grid_update.cpp), the same mismatch for a constant force: a residual of
//           the energy_error, within the column's 0.036.
//   energy  U = sum_p W(delta_p), W = k_p delta^3 / (6 delta_s) below the onset and
//           k_p (delta - delta_s / 2)^2 / 2 + k_p delta_s^2 / 24 beyond: F = dW / d delta, so the
//           force is conservative and its work on the bodies is -dU (the ledger's contact_energy
//           column); a rigid object moving at V works f_p . V on the system (external_work).
//   friction with contact.mu > 0, Coulomb's law by a stick spring and a return map (the
//           elastoplastic tangential penalty of Wriggers 2006; Simo & Laursen 1992): each pushed
//           particle keeps an anchor a_p (Particles::friction_anchor), the point it sticks to,
//           carried with the surface (a_p += V dt). With n, F_n and V the normal, the push and
//           the velocity of the surface that pushes it hardest, at x_p:
//             trial    s* = (x_p - a_p) - ((x_p - a_p) . n) n, the spring's extension along the
//                      surface; a_p = x_p - s* (the anchor kept in the plane through x_p normal
//                      to n: on a curved surface the force -k s is then its energy's gradient),
//             stick    s = s*                              where k_p |s*| <= mu F_n,
//             slip     s = (mu F_n / k_p) s* / |s*|, a_p = x_p - s, heat mu F_n (|s*| - |s|),
//           and f_t = -k_p s joins f_p. Where it touches nothing, a_p = x_p. The anchors move
//           only when time has moved on since the last evaluation: a second one at the same
//           time (several ranks, a restart) reads the same anchors and gives the same bits.
//           Why an anchor, a function of the position as the push is: a spring that integrated
//           the particle's FLIP velocity (s += dt u_t) moved with another velocity than the
//           particle and made energy (a block stuck on a floor under a tangential load:
//           energy_error +0.05 in 200 us, climbing), as the push did before it moved the pushed
//           particle with the velocity its strain sees. Why a spring: a rate-only law (f_t =
//           -min(mu F_n, m_p |u_t| / dt) along u_t) holds a block's bottom layer only while it
//           creeps: that layer carries the whole block's tangential load, and a particle's cap
//           m_p |u_t| / dt reaches it at |u_t| = (layers) g_t dt, about H g_t / c0 whatever h.
//           The springs' energy sum k_p |s|^2 / 2 joins U (contact_energy), the slip's
//           mu F_n (|s*| - |s|) >= 0 is heat (friction_heat), retained in the particle's
//           temperature as plastic work is (models/thermal/adiabatic_heating.hpp; the rigid
//           object takes none).
//   corners a particle that two surfaces push (a corner, a sheet between two dies) rubs on the
//           one whose Coulomb bound mu F_n is the largest only, with that one's F_n, n and V
//           (with one mu: the one that pushes it hardest): its friction is low there by the
//           other's share (at most half), on the particles within a cell of the corner. Chosen by
//           the push alone, a frictionless wall beside a rough one took the edge row's friction
//           away (a block sliding along an x- wall at mu 0.5 beside a frictionless y- wall
//           slowed at 0.938 of Coulomb's rate; an audit's catch). One spring in the plane normal
//           to the summed push would pull the particle onto the wall it leaves (adhesion), carry
//           the anchor at a mean of the surfaces' velocities, and give no friction where opposed
//           pushes cancel. An anchor per surface would be exact (open).
//   damping with contact.penalty_damping = zeta > 0 (opt-in; default 0), a dashpot beside each
//           push: F = max(0, F(delta) - c_p u_n), c_p = 2 zeta sqrt(k_p m_p), u_n = (u_p - V) . n
//           (negative when approaching), never a pull, with u_p = (x^n - x^{n-1}) / dt the
//           velocity the particle moved with over the last step (Particles::damper_velocity; its
//           initial velocity at the start), the half-step velocity of central-difference damping.
//           Why not v_p: a pushed particle moves with the velocity its strain sees (below,
//           "motion"), and its FLIP velocity drifts from it; a dashpot on v_p pumped energy into
//           a plane-strain block resting on a wall at zeta 0.3 (energy_error -31 by 1 ms, the
//           contact_damping column negative; zeta 0.5: stopped on the energy check at 703 us; an
//           audit's catch), the same on a rigid floor. Why damp: the penalty's compliant layer is
//           undamped, and a body pressed by a load applied at once rings on it, off the surface
//           for spells; with friction the ringing makes a stuck body walk and lets sideways
//           motion grow from round-off (docs/scenes.md#rigid-objects). The energy it takes is
//           the work of the step's dashpot forces f_d on the particles' own motion relative to
//           the surface, -f_d . (x^{n+1} - x^n - V dt): the ledger's contact_damping column, a
//           numerical dissipation named as one (a bounce loses energy by it). Booked as c_p u_n^2
//           dt from the FLIP velocity instead, it over-counted: a pushed particle moves with the
//           velocity its strain sees, and v_p's ringing added to the sum (energy_error +0.20 on
//           a block settling on a slope). Stable with the penalty's frequency times the step at
//           most 1 while zeta <= 0.5 (central-difference damping with the half-step velocity is
//           stable for omega dt <= 2 (sqrt(1 + zeta^2) - zeta) = 1.24 at zeta 0.5).
// The force joins the particle's internal force in particles-to-grid (f_p S_Ip). The rigid
// objects' particles put no mass on the grid in this mode, so node contact never meets them.
#pragma once

#include <optional>
#include <vector>

#include "mpm/geometry/geometry.hpp"
#include "mpm/geometry/surface_distance.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"

namespace impact::mpm {

class RigidParticleContact {
 public:
  /// The penalty's stiffness in units of m_p c0^2 / h^2 (header comment): 4 gives a frequency of
  /// 2 c0 / h.
  static constexpr double kStiffness = 4.0;
  /// The onset delta_s in units of h (header comment): a quarter of a cell, uGIMP's half-width
  /// at two particles per cell.
  static constexpr double kOnset = 0.25;
  /// A wall's stiffness takes the closing speed this many times (header comment, "walls").
  static constexpr double kWallSpeed = 4.0;

  /// `surfaces` and `velocities` per velocity field (GridSettings::rigid_surface and
  /// rigid_velocity), met when scene.rigid_contact_at_particles(); the `wall` faces when
  /// scene.grid.walls_at_particles(); `half_widths` per object [m]. Throws std::invalid_argument
  /// where a rigid field met here has no surface of its own (an object cut by an earlier one):
  /// nothing would meet it.
  RigidParticleContact(const Scene& scene, std::vector<std::optional<Geometry>> surfaces,
                       std::vector<Vec3> velocities, std::vector<Vec3> half_widths);

  /// The forces and the energy at time t from the particles' positions (x_p) and seed points
  /// (X_p). With friction (contact.mu > 0) it also moves the anchors of the particles that slip
  /// (P.friction_anchor, carried with their surface since the last call) and retains the slip's
  /// heat in their temperature (P.state).
  void evaluate(Particles& P, double t, int threads);

  /// After a checkpoint's particles replace the ones evaluated: the next evaluate() carries no
  /// anchor (the checkpoint's were carried to its time).
  void resume() { last_time_.reset(); }
  /// Per particle [N] (zero where nothing overlaps), in particle order.
  const std::vector<Vec3>& forces() const { return force_; }
  /// sum_p W(delta_p) + k_p |s_p|^2 / 2 [J] at the last evaluate(): the pushes' and the stick
  /// springs' energy.
  double energy() const { return energy_; }
  /// sum_p f_p [N]: the rigid objects' push on the system, a boundary impulse per unit time.
  const Vec3& total_force() const { return total_force_; }
  /// sum_p f_p . V [W], V the velocity of the object pushing: its work per unit time.
  double power() const { return power_; }
  /// The slip's heat at the last evaluate() [J], >= 0: the Coulomb work since the one before.
  double friction_heat() const { return heat_; }
  /// The energy the dashpots took over the step just made [J] (header comment, "damping"; 0
  /// without): -sum_p f_d . (x_p - x_p at the last evaluate() - V dt), the work of the forces the
  /// step applied on the particles' own motion relative to the surface. Call it before the next
  /// evaluate(), with the particles in the same order.
  double damper_work(const Particles& P, double dt, int threads) const;
  /// max over the deformable bodies' materials of c0 + V_c [m/s] (header comment, "speed"): the
  /// time step's signal speed is at least this, so that the penalty's frequency times the step
  /// stays at most 1 after the bodies have slowed down.
  double signal_speed() const { return signal_speed_; }

 private:
  /// One surface the particles meet: a rigid object's or a wall's.
  struct Surface {
    std::optional<Geometry> geometry;  ///< a rigid object's at t = 0, moved by V t; none: a wall
    Vec3 inward = Vec3::Zero();        ///< a wall's plane, inward . x = offset [-, m]
    double offset = 0.0;
    Vec3 velocity = Vec3::Zero();  ///< V [m/s]
    double mu = 0.0;       ///< the rigid object's (Scene::rigid_field_friction), or the wall face's
    double damping = 0.0;  ///< contact.penalty_damping, or grid.wall_penalty_damping
  };
  /// phi(x) and the outward normal of surface s at time t.
  SurfaceDistance distance(const Surface& s, const Vec3& x, double t) const;

  const Scene& scene_;
  std::vector<Surface> surfaces_;
  std::vector<Vec3> half_widths_;       // per object
  std::vector<double> stiffness_;       // per material: kStiffness (c0 + V_c)^2 / h^2 [1/s^2]
  std::vector<double> wall_stiffness_;  // per material: with c0 + kWallSpeed V_c [1/s^2]
  double signal_speed_ = 0.0;
  std::vector<std::uint8_t> rigid_;  // per field: a rigid object's
  double h_;
  bool prism_z_;
  int axes_;  ///< the mesh's axes: a 2D grid's particles have no extent along z
  bool friction_ = false, damped_ = false;  ///< a surface with mu > 0, with damping > 0
  std::vector<Vec3> force_;
  std::optional<double> last_time_;  ///< of the last evaluate(): the anchors' carry, V (t - t_last)
  std::vector<Vec3> damper_force_, evaluated_at_;  ///< per particle, with damping
  double energy_ = 0.0, power_ = 0.0, heat_ = 0.0, damper_power_ = 0.0;
  Vec3 total_force_ = Vec3::Zero();
};

}  // namespace impact::mpm
