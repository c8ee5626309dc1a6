// The `wall` face condition at one node (mpm/grid/wall.cpp) against the rigid-wall projection
// worked by hand: a node held by every face it touches and moves into, one Coulomb correction of
// what remains tangential to the held faces with capacity sum_f mu_f j_f, heat m s (v0 . t) in
// slip (v0 the start velocity, here equal to the end velocity before the walls; 0 in stick), a
// ghost outside a touched face that is the interior node's mirror image while its face node is
// held and moves inward at the interior's normal speed once it is let go (the image of an
// approaching body, the velocity of a leaving one), and nothing where no particle
// touches the wall. All numbers are exact in binary
// (tolerance 0). Before the single projection, an edge node was corrected face by face: the first
// face's friction took mu j off the second face's normal velocity (which that face then zeroed
// anyway) and booked it as heat (0.25 m for v* = (-1, 0, -1) at mu = 0.5); the result depended
// on which face came first.
#include <boost/test/unit_test.hpp>

#include "mpm/grid/grid.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

constexpr int kXm = 0, kYm = 2, kZm = 4;  // face indices (kFaceNames order)

// A dense 4 x 4 x 4 grid of unit cells with `wall` faces `walls` (coefficient mu each), the other
// faces free.
Grid wall_grid(std::initializer_list<int> walls, double mu) {
  GridSpec spec;
  spec.lower = Vec3::Zero();
  spec.upper = Vec3::Constant(4.0);
  spec.cells = {4, 4, 4};
  spec.faces.fill(FaceCondition::free);
  for (const int f : walls) {
    spec.faces[f] = FaceCondition::wall;
    spec.wall_friction[f] = mu;
  }
  spec.active_blocks = false;
  return Grid(spec, GridSettings{});  // one thread
}

std::uint8_t bit(int face) {
  return std::uint8_t(1u << face);
}

struct Outcome {
  Vec3 v;
  double heat;
};

// One node of mass 2 with start and end velocity v, touching the faces `touch`; the step pass.
Outcome hold(Grid& G, const std::array<int, 3>& ijk, const Vec3& v, std::uint8_t touch) {
  const int e = G.index(ijk[0], ijk[1], ijk[2]);
  G.mass[e] = 2.0;
  G.wall_touch[e] = touch;
  G.velocity_new[e] = G.velocity[e] = v;
  if (!G.heat.empty()) G.heat[e] = 0.0;  // zeroed at the start of each step (grid_update)
  const double heat = G.apply_walls(&G.velocity, G.velocity_new, WallPass::step);
  if (!G.heat.empty()) BOOST_TEST(G.heat[e] == heat);
  return {G.velocity_new[e], heat};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(wall)

BOOST_AUTO_TEST_CASE(an_edge_node_moving_into_both_faces_stops_without_heat) {
  Grid G = wall_grid({kXm, kZm}, 0.5);
  const Outcome o = hold(G, {0, 2, 0}, Vec3(-1.0, 0.0, -1.0), bit(kXm) | bit(kZm));
  BOOST_TEST(o.v.isZero(0.0));
  BOOST_TEST(o.heat == 0.0);  // face by face: 0.25 m = 0.5 J
}

BOOST_AUTO_TEST_CASE(an_edge_node_sticks_or_slips_on_the_sum_of_both_faces_friction) {
  // Capacity mu_x j_x + mu_z j_z = 0.5 * 1 + 0.5 * 1 = 1 along the edge (y).
  Grid G = wall_grid({kXm, kZm}, 0.5);
  const std::uint8_t both = bit(kXm) | bit(kZm);
  const Outcome stick = hold(G, {0, 2, 0}, Vec3(-1.0, 0.75, -1.0), both);
  BOOST_TEST(stick.v.isZero(0.0));
  BOOST_TEST(stick.heat == 0.0);  // static friction does no work
  const Outcome slip = hold(G, {0, 2, 0}, Vec3(-1.0, 3.0, -1.0), both);
  BOOST_TEST(slip.v(0) == 0.0);
  BOOST_TEST(slip.v(1) == 2.0);  // 3 - 1
  BOOST_TEST(slip.v(2) == 0.0);
  BOOST_TEST(slip.heat == 2.0 * 1.0 * 3.0);  // m s (v0 . t)
}

BOOST_AUTO_TEST_CASE(a_slip_the_step_turned_back_makes_no_heat) {
  // A face node ringing at the grid scale under a resting body: the particles' start velocity is
  // small or opposite to the end's slip direction, and friction takes off less than the slip.
  // Nothing slides along t for the step, so no heat; the velocity is corrected all the same.
  Grid G = wall_grid({kXm}, 0.5);
  const int e = G.index(0, 2, 2);
  const auto ring = [&](const Vec3& start, const Vec3& end) {
    G.mass[e] = 2.0;
    G.wall_touch[e] = bit(kXm);
    G.velocity[e] = start;
    G.velocity_new[e] = end;
    G.heat[e] = 0.0;
    return G.apply_walls(&G.velocity, G.velocity_new, WallPass::step);
  };
  // Turned back: start -1 along y, end +3 (capacity 0.5 * 1): slips to 2.5, no heat.
  BOOST_TEST(ring(Vec3(0.0, -1.0, 0.0), Vec3(-1.0, 3.0, 0.0)) == 0.0);
  BOOST_TEST(G.velocity_new[e] == Vec3(0.0, 2.5, 0.0));
  // Along t but slower than one step's friction (0.4 < s = 0.5): no heat.
  BOOST_TEST(ring(Vec3(0.0, 0.4, 0.0), Vec3(-1.0, 3.0, 0.0)) == 0.0);
  // Sliding at 2 along t: m s (v0 . t).
  BOOST_TEST(ring(Vec3(0.0, 2.0, 0.0), Vec3(-1.0, 3.0, 0.0)) == 2.0 * 0.5 * 2.0);
}

BOOST_AUTO_TEST_CASE(the_result_does_not_depend_on_which_faces_meet) {
  // The same edge contact on the x-/z- edge and, with the axes permuted, on the y-/z- and x-/y-
  // edges: the outcomes are the same permutation of each other.
  const Vec3 v(-1.0, 2.5, -0.5);  // into x- and z-, sliding along y
  Grid a = wall_grid({kXm, kZm}, 0.3);
  const Outcome xz = hold(a, {0, 2, 0}, v, bit(kXm) | bit(kZm));
  Grid b = wall_grid({kYm, kZm}, 0.3);
  const Outcome yz = hold(b, {2, 0, 0}, Vec3(v(1), v(0), v(2)), bit(kYm) | bit(kZm));
  Grid c = wall_grid({kXm, kYm}, 0.3);
  const Outcome xy = hold(c, {0, 0, 2}, Vec3(v(2), v(0), v(1)), bit(kXm) | bit(kYm));
  BOOST_TEST(yz.v(0) == xz.v(1));
  BOOST_TEST(xy.v(2) == xz.v(1));
  BOOST_TEST(xz.v(1) == 2.5 - 0.3 * (1.0 + 0.5), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(xz.v(0) == 0.0);
  BOOST_TEST(xz.v(2) == 0.0);
  BOOST_TEST(yz.heat == xz.heat);
  BOOST_TEST(xy.heat == xz.heat);
}

BOOST_AUTO_TEST_CASE(a_face_the_body_does_not_touch_holds_nothing) {
  Grid G = wall_grid({kXm, kZm}, 0.5);
  // Moving into both faces, touching only x-: x- holds, and its friction acts on v_z, which is
  // tangential to it (the body slides along x- towards z-): s = min(0.5 * 1, 1) = 0.5.
  const Outcome x_only = hold(G, {0, 2, 0}, Vec3(-1.0, 0.0, -1.0), bit(kXm));
  BOOST_TEST(x_only.v(0) == 0.0);
  BOOST_TEST(x_only.v(2) == -0.5);
  BOOST_TEST(x_only.heat == 2.0 * 0.5 * 1.0);
  // Touching neither: free, whatever its velocity.
  const Outcome none = hold(G, {0, 2, 0}, Vec3(-1.0, 0.0, -1.0), 0);
  BOOST_TEST(none.v == Vec3(-1.0, 0.0, -1.0));
  BOOST_TEST(none.heat == 0.0);
  // Touching but leaving: free (the wall never pulls).
  const Outcome leaving = hold(G, {0, 2, 1}, Vec3(1.0, 3.0, 0.0), bit(kXm));
  BOOST_TEST(leaving.v == Vec3(1.0, 3.0, 0.0));
}

BOOST_AUTO_TEST_CASE(the_ghost_outside_a_touched_face_follows_the_face_nodes_hold) {
  // While the step holds the face node, the ghost's normal velocity is the mirror image of the
  // interior node's; once the face node is free, it moves inward at |v_n| of the interior node:
  // the image of an approaching body, the velocity of a leaving one. Its tangential velocity
  // stays its own.
  Grid G = wall_grid({kXm}, 0.0);
  const int face = G.index(0, 2, 2), ghost = G.index(-1, 2, 2), inner = G.index(1, 2, 2);
  const auto run = [&](const Vec3& face_velocity, std::uint8_t touch, double inner_vx,
                       double ghost_vx) {
    G.velocity_new[inner] = Vec3(inner_vx, 1.0, 0.5);
    G.velocity[inner] = Vec3(-2.0, 1.0, 0.5);
    G.velocity_new[ghost] = Vec3(ghost_vx, 7.0, 8.0);  // its own (free) values
    G.velocity[ghost] = Vec3(-4.0, 6.0, 8.0);
    G.mass[face] = 1.0;
    G.wall_touch[face] = touch;
    G.wall_held[face] = 0;  // reset each step by particles-to-grid
    G.velocity_new[face] = face_velocity;
    G.apply_walls(&G.velocity, G.velocity_new, WallPass::step);
  };
  run(Vec3(-1.0, 0.0, 0.0), bit(kXm), -3.0, -4.0);  // approaching: held
  BOOST_TEST(G.velocity_new[face] == Vec3(0.0, 0.0, 0.0));
  BOOST_TEST(G.velocity_new[ghost] == Vec3(3.0, 7.0, 8.0));  // the image, start and end
  BOOST_TEST(G.velocity[ghost] == Vec3(2.0, 6.0, 8.0));
  // Touching while the face node moves away: the face is free, the particles still crossing
  // the plane see the image of the approaching interior.
  run(Vec3(1.0, 0.0, 0.0), bit(kXm), -3.0, -4.0);
  BOOST_TEST(G.velocity_new[face] == Vec3(1.0, 0.0, 0.0));
  BOOST_TEST(G.velocity_new[ghost] == Vec3(3.0, 7.0, 8.0));
  // The interior leaving at 2: the ghost moves out with it, not at the image -2 (which would
  // pull the particles still crossing the plane back), and not at its own -4 (a light ghost's
  // inward acceleration under a compressed face, which kicked particles through the wall).
  run(Vec3(1.0, 0.0, 0.0), bit(kXm), 2.0, -4.0);
  BOOST_TEST(G.velocity_new[ghost] == Vec3(2.0, 7.0, 8.0));
  // The face node held (pressed on) while the interior rings away from the wall at 2: the
  // mirror image -2, start and end. Inward at 2 the image was rectified: the ghost moved inward
  // whichever way the interior rang, and a block resting on the wall climbed off it
  // (resting_contact_test).
  run(Vec3(-1.0, 0.0, 0.0), bit(kXm), 2.0, -4.0);
  BOOST_TEST(G.velocity_new[face] == Vec3(0.0, 0.0, 0.0));
  BOOST_TEST(G.velocity_new[ghost] == Vec3(-2.0, 7.0, 8.0));
  BOOST_TEST(G.velocity[ghost] == Vec3(2.0, 6.0, 8.0));
  // Not touching: the ghost keeps its own velocity, as on a free face.
  run(Vec3(-1.0, 0.0, 0.0), 0, -3.0, -4.0);
  BOOST_TEST(G.velocity_new[face] == Vec3(-1.0, 0.0, 0.0));
  BOOST_TEST(G.velocity_new[ghost] == Vec3(-4.0, 7.0, 8.0));
  BOOST_TEST(G.velocity[ghost] == Vec3(-4.0, 6.0, 8.0));
}

BOOST_AUTO_TEST_CASE(no_friction_acts_on_what_another_walls_ghost_image_sets) {
  // Node (0, 2, -1) lies on the x- wall's face layer and beyond the z- wall, in its ghost layer:
  // with z- touched at (0, 2, 0), its v_z is the image of (0, 2, 1)'s. The x- wall holds v_x and
  // its friction acts on v_y only; v_z (tangential to x- but set by the image) takes none. Booked
  // on v_z, the heat of a bisector impact into a corner at mu 2 was 97 % of it.
  Grid G = wall_grid({kXm, kZm}, 0.5);
  const int beyond = G.index(0, 2, -1);
  G.wall_touch[G.index(0, 2, 0)] = bit(kZm);
  G.velocity_new[G.index(0, 2, 1)] = G.velocity[G.index(0, 2, 1)] = Vec3(0.0, 0.0, -2.0);
  const Outcome o = hold(G, {0, 2, -1}, Vec3(-1.0, 0.0, -1.0), bit(kXm));
  BOOST_TEST(o.heat == 0.0);
  BOOST_TEST(G.velocity_new[beyond] == Vec3(0.0, 0.0, 2.0));  // v_x held, v_z the image
  // With a slip along y as well, friction takes mu j = 0.5 off it alone: (0, 2.5, 2) and heat
  // m s (v0 . t) = 2 * 0.5 * 3.
  const Outcome y = hold(G, {0, 2, -1}, Vec3(-1.0, 3.0, -1.0), bit(kXm));
  BOOST_TEST(G.velocity_new[beyond] == Vec3(0.0, 2.5, 2.0));
  BOOST_TEST(y.heat == 2.0 * 0.5 * 3.0);
}

BOOST_AUTO_TEST_CASE(a_corner_node_held_by_three_faces_stops) {
  Grid G = wall_grid({kXm, kYm, kZm}, 1.0);
  const Outcome o = hold(G, {0, 0, 0}, Vec3(-1.0, -2.0, -3.0), bit(kXm) | bit(kYm) | bit(kZm));
  BOOST_TEST(o.v.isZero(0.0));
  BOOST_TEST(o.heat == 0.0);
}

BOOST_AUTO_TEST_CASE(a_particle_touches_the_walls_its_domain_reaches_within_the_step) {
  Grid G = wall_grid({kXm, kZm}, 0.0);
  const Vec3 l(0.25, 0.25, 0.25);
  // Domain edge exactly on x- (seeded against it): touches; 0.1 away at rest: does not.
  BOOST_TEST(G.touched_walls(Vec3(0.25, 2.0, 2.0), Vec3::Zero(), l, 0.1) == bit(kXm));
  BOOST_TEST(G.touched_walls(Vec3(0.35, 2.0, 2.0), Vec3::Zero(), l, 0.1) == 0);
  // 0.1 away moving at -1 for dt = 0.1: reaches it; for dt = 0.09: does not.
  BOOST_TEST(G.touched_walls(Vec3(0.35, 2.0, 2.0), Vec3(-1.0, 0.0, 0.0), l, 0.1) == bit(kXm));
  BOOST_TEST(G.touched_walls(Vec3(0.35, 2.0, 2.0), Vec3(-1.0, 0.0, 0.0), l, 0.09) == 0);
  // In the corner: both.
  BOOST_TEST(G.touched_walls(Vec3(0.2, 2.0, 0.2), Vec3::Zero(), l, 0.1) == (bit(kXm) | bit(kZm)));
}

BOOST_AUTO_TEST_SUITE_END()
