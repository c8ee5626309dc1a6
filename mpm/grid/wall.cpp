// A rigid stationary wall with Coulomb friction on a grid face (grid.boundary.<face> = "wall";
// docs/scenes.md#grid). The wall is one-sided: its face nodes push and never pull, the condition a
// Taylor anvil or a target support needs. It acts only where its body touches it. Per step, field
// and face-layer node (the multi-velocity contact of Bardenhagen, Brackbill & Sulsky 2000, CMAME
// 187:529, and Bardenhagen et al. 2001, CMES 2:509, with the wall as a second body of infinite
// mass at rest):
//   touch      a particle of the field with the node in its stencil reaches the wall's plane
//              within the step: its domain (half-width l, uGIMP's) at its start velocity,
//              n . (x_p - x_wall) - l + dt min(0, n . v_p) <= 0, n the inward normal; l is fixed
//              at creation (as uGIMP's), so a particle compressed along n is held up to
//              l (1 - F_nn) before its deformed domain would touch, within a cell (Grid::
//              wall_touch, marked by particles-to-grid). Velocities alone held a body that was
//              still up to a cell and a half away, and one that had left but still vibrated
//              within that reach: an elastic block started half a cell from the wall at 50 m/s
//              left with 1.22 times the momentum it brought, energy_error +0.82; at 10 m/s it
//              turned back within 1 us without reaching the wall and the energy check stopped it
//              (tests/mpm/verification/wall_contact_test.cpp).
//   contact    the node touches a face and its end velocity v* moves into it: v*_n = v* . n < 0.
//              Then v*_n is set to zero: the FLIP increment v* - v stops the particles' approach,
//              and the normal impulse per unit mass is j = -v*_n >= 0. Otherwise the node is left
//              free (a separating surface is not held). On an edge or corner node every held face
//              is projected first, so that no face's friction acts on another face's normal
//              velocity (which that face holds at zero).
//   re-map     MUSL projects the moved particles' momentum back to the grid for the strain rate
//              (grid_to_particles.cpp); the wall holds there exactly the faces the step held
//              (wall_held), zeroing their normal component whatever its sign, and leaves every
//              other node free: the particles moved with v*, whose v*_n the step held at zero,
//              so the strain rate sees the same constraint (Bardenhagen et al. 2001 and Nairn
//              test contact again in each pass; decided on the re-mapped data, the hold was
//              lost). The cost: a body that leaves is released one re-map late (the bouncing
//              rod's residual -0.25 -> -0.33, wall_contact_test). Where the step's friction
//              stuck the node, the re-map takes the step's v* for the tangential
//              components as well, for the same reason: re-mapped from the particles, a stuck
//              face node read their FLIP velocities, the strain rate sheared a face that had not
//              moved, and friction pumped a resting block (mu 1: kinetic + strain - gravity's
//              work reached +4.5 U_s, the block lifted off and the energy check stopped it at
//              105 us; USL, without a re-map, never did); a block on a 30 degree ramp at mu 0.8
//              crept 26 um in 400 us and faster at h/2 (now 1000 times less), and a block at
//              rest in a three-wall corner booked friction heat without end (now flat after
//              the load settles). Decided afresh on the sign of the
//              re-mapped velocity, a face node the step had held (the particles did not move into
//              the wall) was released when its ringing re-map pointed outward, and the strain rate
//              stretched a face that had not moved: a block at rest on the wall under gravity
//              gained energy until the energy check stopped it at 204 us; a block spanning two
//              walls at 8 us (tests/mpm/verification/resting_contact_test.cpp). Only where the
//              step stuck: in slip the re-map keeps its own tangential velocity, for a light
//              node's v* is a force over a sliver of mass whose gradient is not small (nodes of
//              5e-21 kg at a mu = 1 wall slipped at up to 1500 m/s on a graded ramp and turned a
//              particle's det F to -2025 at step 538; contact_friction_test), and every case
//              above that the copy cured sticks.
//   friction   one Coulomb correction of what remains tangential to the held faces, u_t: the slip
//              removed is s = min(sum_f mu_f j_f, |u_t|): stick (u_t = 0) when |u_t| <= sum mu_f
//              j_f, slip otherwise.
//   heat       only where the material slides: in slip (s < |u_t|) and with the start
//              velocity (the particles' own, projected) sliding along t faster than one step's
//              friction can stop, v0 . t > s; then m s (v0 . t) per node, the friction impulse
//              m s times the slip at the start of the step along the slip direction t (the wall
//              is at rest), the convention of contact/contact.hpp; zero in stick. Without the
//              test v0 . t > s, a block at rest in an x-/z- corner (gravity 1e5 m/s^2 along the
//              bisector, mu 0.25) booked 1.1e-8 J of heat in 250 us that the mechanical energy
//              never lost (the books without any heat stay at -2e-9 J): its light face nodes
//              take a tangential force above mu times their normal one every step, slip by
//              |u_t| - s ~ 2e-3 m/s and are pulled back the next, while the particles barely move
//              (|v0| ~ 1e-3 m/s). Now that corner books 1.1e-9 J while the sudden load first
//              settles and nothing after; a steady slide has v0 . t ~ |u_t| >> s = mu g_n dt, and
//              the sliding block's books are unchanged (tests/mpm/verification/
//              resting_contact_test.cpp, wall_friction_test.cpp). Booked with the slip averaged
//              over the step, m s (v0 . t + |u_t| - s) / 2, as Nairn, Bardenhagen & Smith (2018,
//              Comput. Part. Mech. 5:285) do, the same corner made 1.0e-8 J in 100 us (without
//              their part for a slip that turns within the step, which only adds). Delivered to the
//              particles through Grid::heat. A component that another wall's ghost image sets (a
//              node beyond that wall) takes no friction: booked there, the heat of a bisector
//              impact into a corner at mu 2 was 97 % such velocities that no particle sees.
//   ghost      while its body touches a face (the face node's touch bit), the ghost node outside
//              it follows the face's decision, start and end: while the step holds the face node
//              (wall_held), the mirror image of the first interior node's normal velocity,
//              -n . v, so that a particle reaching into the wall sees its image there and stops
//              at the plane, and the face layer, pressed on, rings about it symmetrically;
//              once the face node is let go (the body leaves), inward at the interior's normal
//              speed |n . v|, which is the body's own velocity while it leaves, where the image
//              pulled back the particles still crossing the plane (a Taylor rod's rebound
//              momentum peaked at 5 % of its impact momentum and fell to 0.3 %; now it ends at
//              3.0 %: some pull remains while the interior node is slower than the particles
//              crossing the plane, and while a face node is still held its ghost's image pulls
//              the particles over the plane: the axisymmetric rod's wall impulse has -2.7 / -0.8
//              / -0.3 % of p0 pointing outward at 6 / 12 / 24 cells per radius, -1.8 / -0.3 /
//              -0.07 % under the rectified image below; the face nodes themselves never pull).
//              Inward at |n . v| while held as well, the image was rectified: a ringing interior
//              node approaching gave its image, one leaving gave its own velocity, so the ghost
//              always moved inward, the particles over the plane were pushed off the wall on
//              average, and a soft block resting on it climbed (plane strain, 1000 m/s^2: residual
//              +1.2 U_s by 1 s, U_s its settled strain energy; beside a symmetric face the energy
//              check stopped it at 3.2 s; resting_contact_test). Its tangential velocity is its own
//              (a wall pushes along its normal only: a tangential image changed the tangential
//              momentum of a block sliding on a frictionless wall by 4e-8 of it). Where no
//              particle touches, the ghost keeps its own velocity, as on a free face: only
//              particles whose domain crosses the plane weigh a ghost node, and those touch. Two
//              alternatives failed: released to its own velocity with its face node (v*_n >= 0),
//              the light ghost under the GPa compression of a Taylor rod's face accelerated into
//              the wall and kicked face particles through it (15 of 23 shots stopped); kept at
//              its own velocity where that is faster outward, a light ghost next to failed
//              particles kicked them out (energy_error +24 % on the rod with the shipped failure
//              stack).
// Only v* is corrected, unlike the mirror, which zeroes the start velocity's normal component too
// (there the image makes it zero): holding the start as well let the particles keep their
// approach velocity, the face layer was clamped inward and free outward, and a block pressed on
// the wall by gravity crept off it, the books gaining 16 % of E0 in 240 us.
// Why one-sided: a mirror plane also pulls, and its normal impulse alternates in sign with the
// grid-scale vibration of the face layer; bounding friction by |j| per step rectified that
// vibration into friction (a sliding block decelerated 1.5-2 times mu g). The one-sided wall has
// j >= 0, and its impulses add up to the load (tests/mpm/verification/wall_friction_test.cpp).
#include <cmath>

#include "mpm/grid/grid.hpp"

namespace impact::mpm {

namespace {
// Grid::wall_held's bit for "the step's friction stuck this node" (the face bits are 1 << face,
// faces 0-5).
constexpr std::uint8_t kStuck = 0x40;
}  // namespace

double Grid::apply_walls(std::vector<Vec3>* start, std::vector<Vec3>& end, WallPass pass) {
  const bool step = pass == WallPass::step;
  const bool write_heat = step && !heat.empty();
  const std::size_t nw = wall_active_.size();
  double total_heat = 0.0;
  // Serial, in ascending node order: the heat sum is deterministic.
  for (int f = 0; f < fields_; ++f) {
    // A rigid object's field is held at its velocity (grid/rigid_fields.cpp): a wall neither
    // moves it nor books heat on a slip no particle has.
    if (is_rigid_field(f)) continue;
    const int offset = f * node_count();
    for (std::size_t k = 0; k < nw; ++k) {
      const WallNode& w = wall_active_[k];
      const int e = offset + w.node;
      const std::uint8_t touch = wall_touch[e];
      if (touch == 0) continue;
      Vec3& v = end[e];
      if (!step) {  // the re-map: the step's decision, whatever the re-mapped velocity's sign
        for (int i = 0; i < w.count; ++i)
          if (wall_held[e] & w.face[i].bit) v(w.face[i].axis) = 0.0;
        // Where the step's friction stuck the node, the tangential components it decided too:
        // the particles moved with that v*.
        if (wall_held[e] & kStuck) {
          bool decided[3] = {false, false, false};
          for (int i = 0; i < w.images; ++i)
            if (wall_touch[offset + w.image[i].face_node] & w.image[i].bit)
              decided[w.image[i].axis] = true;  // set by the other wall's ghost image below
          for (int i = 0; i < w.count; ++i)
            if (wall_held[e] & w.face[i].bit) decided[w.face[i].axis] = true;  // zeroed above
          for (int d = 0; d < 3; ++d)
            if (!decided[d]) v(d) = velocity_new[e](d);
        }
        continue;
      }
      double capacity = 0.0;  // sum over held faces of mu_f j_f
      for (int i = 0; i < w.count; ++i) {
        const WallFace& face = w.face[i];
        const double vn = face.inward * v(face.axis);
        if (!(touch & face.bit) || !(vn < 0.0)) continue;  // not touching, at rest or leaving
        v(face.axis) = 0.0;
        wall_held[e] |= face.bit;
        capacity += face.mu * -vn;  // -vn: the normal impulse per unit mass
      }
      if (capacity == 0.0) continue;
      // What remains is tangential to every held face; a component another wall's ghost image
      // sets afterwards (a node beyond that wall) takes no friction: it would book heat on a
      // velocity the particles never see.
      Vec3 ut = v;
      for (int i = 0; i < w.images; ++i)
        if (wall_touch[offset + w.image[i].face_node] & w.image[i].bit) ut(w.image[i].axis) = 0.0;
      const double slip = ut.norm();
      if (slip == 0.0) continue;
      const double s = std::min(capacity, slip);
      const Vec3 t = ut / slip;
      v -= s * t;
      if (!(s < slip)) wall_held[e] |= kStuck;
      // Heat only where the material slides (header comment): its start slip along t exceeds
      // what friction takes off in one step (static friction does no work).
      if (!(s < slip) || !start) continue;
      const double slip_start = (*start)[e].dot(t);
      if (!(slip_start > s)) continue;
      const double h = mass[e] * s * slip_start;
      if (owns(w.node)) total_heat += h;  // booked once in a domain decomposition
      if (write_heat) heat[e] += h;
    }
    // The ghosts outside a touched face take the image of the first interior node's normal
    // velocity, face by face, after every face node has been corrected.
    Vec3* const v_end = end.data() + offset;
    Vec3* const v_start = start ? start->data() + offset : nullptr;
    for (int face = 0; face < 6; ++face) {
      const std::uint8_t bit = std::uint8_t(1u << face);
      for (std::size_t k = 0; k < nw; ++k) {
        const WallNode& w = wall_active_[k];
        if (!(wall_touch[offset + w.node] & bit)) continue;
        for (int i = 0; i < w.count; ++i) {
          const WallFace& wf = w.face[i];
          if (wf.bit != bit) continue;
          // While the face node is held, the mirror image of the interior's normal velocity;
          // once it is let go, inward at the interior's normal speed |n . v_inner| (header
          // comment).
          if (wall_held[offset + w.node] & bit) {
            v_end[wf.ghost](wf.axis) = -v_end[wf.inner](wf.axis);
            if (v_start) v_start[wf.ghost](wf.axis) = -v_start[wf.inner](wf.axis);
            continue;
          }
          v_end[wf.ghost](wf.axis) = wf.inward * std::abs(v_end[wf.inner](wf.axis));
          if (v_start)
            v_start[wf.ghost](wf.axis) = wf.inward * std::abs(v_start[wf.inner](wf.axis));
        }
      }
    }
    // The mirror's ghosts whose source is on a wall's layers see the walls' result.
    for (const MirrorWrite& m : mirror_after_walls_active_) {
      for (const int when : {1, 0}) {  // end, start (apply_mirror's images)
        Vec3* v = when == 1 ? v_end : v_start;
        if (!v) continue;
        Vec3 x = v[m.source];
        const double V = face_velocity_[when][m.face];
        if (m.fixed) {
          x = -x;
        } else {
          x(m.axis) = V == 0.0 ? -x(m.axis) : 2.0 * V - x(m.axis);
        }
        v[m.target] = x;
      }
    }
  }
  return total_heat;
}

}  // namespace impact::mpm
