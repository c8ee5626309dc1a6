// A rigid stationary wall with Coulomb friction on a grid face (grid.boundary.<face> = "wall";
// docs/scenes.md#grid). The wall is one-sided: it pushes and never pulls, the condition a Taylor
// anvil or a target support needs. It acts only where its body touches it. Per step, field and
// face-layer node (Bardenhagen et al. 2000, CMES 1:509, sec. 3, with the wall as a second body of
// infinite mass at rest):
//   touch      a particle of the field with the node in its stencil reaches the wall's plane
//              within the step: its domain (half-width l, uGIMP's) at its start velocity,
//              n . (x_p - x_wall) - l + dt min(0, n . v_p) <= 0, n the inward normal (Grid::
//              wall_touch, marked by particles-to-grid). Velocities alone would hold a body that
//              is still up to a cell and a half away: an elastic block started 0.5 cells from
//              the wall bounced back within 1 us at 10 m/s with 5 % more momentum than it brought
//              and energy_error +1.0 (the energy check stopped it), without ever reaching it.
//   contact    the node touches a face and its end velocity v* moves into it: v*_n = v* . n < 0.
//              Then v*_n is set to zero: the FLIP increment v* - v stops the particles' approach,
//              and the normal impulse per unit mass is j = -v*_n >= 0. Otherwise the node is left
//              free (a separating surface is not held). On an edge or corner node every held face
//              is projected first, so that no face's friction acts on another face's normal
//              velocity (which that face holds at zero).
//   friction   one Coulomb correction of what remains tangential to the held faces, u_t: the slip
//              removed is s = min(sum_f mu_f j_f, |u_t|): stick (u_t = 0) when |u_t| <= sum mu_f
//              j_f, slip otherwise.
//   heat       m s (|u_t| - s) >= 0 per node: the friction impulse m s times the slip the
//              particles then make (|u_t| - s, zero in stick), the Coulomb work on the relative
//              tangential motion (the convention of contact/contact.hpp; Nairn, Bardenhagen &
//              Smith 2018, Comput. Part. Mech. 5:285), delivered to the particles through
//              Grid::heat.
//   ghost      the normal velocity of the ghost node outside a held face is the mirror image of
//              the first interior node's (start and end), so that a particle reaching into the
//              wall sees its image there and stops at the plane; its tangential velocity is its
//              own (a wall pushes along its normal only: the mirror's tangential image changed
//              the tangential momentum of a block sliding on a frictionless wall by 4e-8 of it);
//              outside a free face the ghost keeps its own velocity, as on a free face. A ghost
//              that stayed a mirror after its face was released pushed and pulled the particles
//              next to the face: an elastic block leaving the wall kept gaining impulse and ended
//              with energy_error +0.54.
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

double Grid::apply_walls(std::vector<Vec3>* start, std::vector<Vec3>& end, WallPass pass) {
  const bool step = pass == WallPass::step;
  const bool write_heat = step && !heat.empty();
  const std::size_t nw = wall_active_.size();
  double total_heat = 0.0;
  // Serial, in ascending node order: the heat sum is deterministic.
  for (int f = 0; f < fields_; ++f) {
    const int offset = f * node_count();
    std::uint8_t* const held = wall_held_.data() + std::size_t(f) * wall_all_.size();
    for (std::size_t k = 0; k < nw; ++k) {
      const WallNode& w = wall_active_[k];
      const int e = offset + w.node;
      held[k] = 0;
      const std::uint8_t touch = wall_touch[e];
      if (touch == 0) continue;
      Vec3& v = end[e];
      double capacity = 0.0;  // sum over held faces of mu_f j_f
      for (int i = 0; i < w.count; ++i) {
        const WallFace& face = w.face[i];
        const double vn = face.inward * v(face.axis);
        if (!(touch & face.bit) || !(vn < 0.0)) continue;  // not touching, at rest or leaving
        v(face.axis) = 0.0;
        capacity += face.mu * -vn;  // -vn: the normal impulse per unit mass
        held[k] |= face.bit;
      }
      if (!step || capacity == 0.0) continue;
      const double slip = v.norm();  // tangential to every held face now
      if (slip == 0.0) continue;
      const double s = std::min(capacity, slip);
      v *= (slip - s) / slip;
      const double h = mass[e] * s * (slip - s);
      if (owns(w.node)) total_heat += h;  // booked once in a domain decomposition
      if (write_heat) heat[e] += h;
    }
    // The ghosts of the held faces take the image of the first interior node's normal velocity,
    // face by face, after every face node has been corrected.
    Vec3* const v_end = end.data() + offset;
    Vec3* const v_start = start ? start->data() + offset : nullptr;
    for (int face = 0; face < 6; ++face) {
      const std::uint8_t bit = std::uint8_t(1u << face);
      for (std::size_t k = 0; k < nw; ++k) {
        if (!(held[k] & bit)) continue;
        const WallNode& w = wall_active_[k];
        for (int i = 0; i < w.count; ++i) {
          const WallFace& wf = w.face[i];
          if (wf.bit != bit) continue;
          v_end[wf.ghost](wf.axis) = -v_end[wf.inner](wf.axis);
          if (v_start) v_start[wf.ghost](wf.axis) = -v_start[wf.inner](wf.axis);
        }
      }
    }
    // The mirror's ghosts whose source is on a wall's layers see the walls' result.
    for (const MirrorWrite& m : mirror_after_walls_active_) {
      for (Vec3* v : {v_end, v_start}) {
        if (!v) continue;
        Vec3 x = v[m.source];
        if (m.fixed) {
          x = -x;
        } else {
          x(m.axis) = -x(m.axis);
        }
        v[m.target] = x;
      }
    }
  }
  return total_heat;
}

}  // namespace impact::mpm
