// Multi-material contact at one node (mpm/contact/contact.cpp) against the correction worked by
// hand: two bodies of mass 0.5 at node (2, 2, 2) of a unit-cell grid, their mass gradients from
// the neighbouring nodes (central differences), mu = 0.3, the step pass.
//   stick   v_0 = (1, 0.1, 0), v_1 = (-1, 0, 0): u = v - v_cm = +-(1, 0.05, 0), u_n = 1, |u_t| =
//           0.05 <= mu u_n: both move with v_cm = (0, 0.05, 0) and no heat is booked (static
//           friction does no work). Booked on the start slip, m s |u0_t|, it was 2.5e-3 J.
//   slip    v_0 = (1, 2, 0): u = +-(1, 1, 0), s = mu u_n = 0.3: v_0 = (0, 1.7, 0), v_1 = (0, 0.3,
//           0); heat m s (u0 . t) = 0.5 * 0.3 * 1 per body (the start velocities equal the end
//           ones here), 0.3 J: the friction impulse 0.15 N s times the relative slip at the start
//           of the step, 2 m/s. Booked on the slip that remains it was 0.21 J.
//   normal  body 0's corner (its mass falls off along x and along y) on body 1's flat face
//           (along x only), body 0 sliding along y with no approach: with `larger_volume` the
//           normal is body 1's face and nothing is corrected; with `mass_gradients` (the sum
//           of the gradients) the normal tilts towards y and the slide is taken as an approach.
// All values are exact in binary or within 1e-15.
#include <boost/test/unit_test.hpp>

#include "mpm/contact/contact.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// A dense grid of unit cells with free faces: 4 x 4 x 4, or on a 2D grid 4 x 4 and one cell of 1 m
// along z centred on z = 0.
GridSpec unit_cells(GridGeometry geometry = GridGeometry::three_d) {
  GridSpec spec;
  spec.geometry = geometry;
  const bool planar = geometry != GridGeometry::three_d;
  spec.lower = planar ? Vec3(0.0, 0.0, -0.5) : Vec3::Zero();
  spec.upper = planar ? Vec3(4.0, 4.0, 0.5) : Vec3::Constant(4.0);
  spec.cells = {4, 4, planar ? 1 : 4};
  spec.faces.fill(FaceCondition::free);
  spec.active_blocks = false;
  return spec;
}

// One thread, two velocity fields (each its own body).
GridSettings two_fields() {
  GridSettings s;
  s.fields = 2;
  return s;
}

// The 4 x 4 x 4 grid with two velocity fields and a heat array.
Grid two_field_grid() {
  Grid G(unit_cells(), two_fields());
  G.heat.assign(G.entry_count(), 0.0);
  return G;
}

int entry(const Grid& G, int field, int i, int j, int k) {
  return field * G.node_count() + G.index(i, j, k);
}

// Body 0 on the left (nodes x = 1, 2), body 1 on the right (x = 2, 3): a flat interface at x = 2.
Grid flat_interface() {
  Grid G = two_field_grid();
  G.mass[entry(G, 0, 1, 2, 2)] = 1.0;
  G.mass[entry(G, 0, 2, 2, 2)] = 0.5;
  G.mass[entry(G, 1, 2, 2, 2)] = 0.5;
  G.mass[entry(G, 1, 3, 2, 2)] = 1.0;
  return G;
}

ContactSpec friction(double mu, ContactNormal normal = ContactNormal::mass_gradients) {
  ContactSpec c;
  c.type = ContactType::friction;
  c.mu = mu;
  c.normal = normal;
  return c;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(contact)

BOOST_AUTO_TEST_CASE(a_node_in_stick_moves_with_the_centre_of_mass_and_books_no_heat) {
  Grid G = flat_interface();
  const int a = entry(G, 0, 2, 2, 2), b = entry(G, 1, 2, 2, 2);
  G.velocity_new[a] = G.velocity[a] = Vec3(1.0, 0.1, 0.0);
  G.velocity_new[b] = G.velocity[b] = Vec3(-1.0, 0.0, 0.0);
  const ContactTotals t = apply_contact(G, friction(0.3), G.velocity_new, ContactPass::step);
  BOOST_TEST(t.contact_nodes == 1);
  BOOST_TEST((G.velocity_new[a] - Vec3(0.0, 0.05, 0.0)).norm() < 1e-15);
  BOOST_TEST((G.velocity_new[b] - Vec3(0.0, 0.05, 0.0)).norm() < 1e-15);
  BOOST_TEST(t.friction_heat == 0.0);
  BOOST_TEST(G.heat[a] == 0.0);
  BOOST_TEST(G.heat[b] == 0.0);
}

BOOST_AUTO_TEST_CASE(the_strain_pass_keeps_the_steps_stick) {
  // The step sticks the interface node (as above); MUSL re-maps the particles' FLIP velocities,
  // which read a slip and a gap: (-0.2, 0.3, 0) against (0.2, -0.1, 0), centre of mass (0, 0.1,
  // 0). The step's friction stuck the pair, so the strain pass moves both fields to that centre
  // of mass. Held along the normal only (separating, so no Coulomb), the strain rate sheared an
  // interface that had not slid, (0, 0.3, 0) against (0, -0.1, 0), and friction pumped a resting
  // stack of blocks until the energy check stopped it (stack_friction.json).
  Grid G = flat_interface();
  const int a = entry(G, 0, 2, 2, 2), b = entry(G, 1, 2, 2, 2);
  G.velocity_new[a] = G.velocity[a] = Vec3(1.0, 0.1, 0.0);
  G.velocity_new[b] = G.velocity[b] = Vec3(-1.0, 0.0, 0.0);
  apply_contact(G, friction(0.3), G.velocity_new, ContactPass::step);
  G.velocity_L[a] = Vec3(-0.2, 0.3, 0.0);
  G.velocity_L[b] = Vec3(0.2, -0.1, 0.0);
  apply_contact(G, friction(0.3), G.velocity_L, ContactPass::strain);
  BOOST_TEST((G.velocity_L[a] - Vec3(0.0, 0.1, 0.0)).norm() < 1e-15);
  BOOST_TEST((G.velocity_L[b] - Vec3(0.0, 0.1, 0.0)).norm() < 1e-15);
  // In slip the strain pass holds the normal only: the re-mapped slip stays.
  Grid H = flat_interface();
  H.velocity_new[a] = H.velocity[a] = Vec3(1.0, 2.0, 0.0);
  H.velocity_new[b] = H.velocity[b] = Vec3(-1.0, 0.0, 0.0);
  apply_contact(H, friction(0.3), H.velocity_new, ContactPass::step);
  H.velocity_L[a] = Vec3(-0.2, 0.3, 0.0);
  H.velocity_L[b] = Vec3(0.2, -0.1, 0.0);
  apply_contact(H, friction(0.3), H.velocity_L, ContactPass::strain);
  BOOST_TEST((H.velocity_L[a] - Vec3(0.0, 0.3, 0.0)).norm() < 1e-15);
  BOOST_TEST((H.velocity_L[b] - Vec3(0.0, -0.1, 0.0)).norm() < 1e-15);
}

BOOST_AUTO_TEST_CASE(a_slipping_node_books_the_impulse_times_the_slip_that_remains) {
  Grid G = flat_interface();
  const int a = entry(G, 0, 2, 2, 2), b = entry(G, 1, 2, 2, 2);
  G.velocity_new[a] = G.velocity[a] = Vec3(1.0, 2.0, 0.0);
  G.velocity_new[b] = G.velocity[b] = Vec3(-1.0, 0.0, 0.0);
  const ContactTotals t = apply_contact(G, friction(0.3), G.velocity_new, ContactPass::step);
  BOOST_TEST((G.velocity_new[a] - Vec3(0.0, 1.7, 0.0)).norm() < 1e-15);
  BOOST_TEST((G.velocity_new[b] - Vec3(0.0, 0.3, 0.0)).norm() < 1e-15);
  BOOST_TEST(t.friction_heat == 0.3, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(G.heat[a] == G.heat[b]);
  // The start and projection passes correct but book nothing.
  Grid H = flat_interface();
  H.velocity[a] = Vec3(1.0, 2.0, 0.0);
  H.velocity[b] = Vec3(-1.0, 0.0, 0.0);
  BOOST_TEST(apply_contact(H, friction(0.3), H.velocity, ContactPass::start).friction_heat == 0.0);
  BOOST_TEST(H.heat[a] == 0.0);
}

BOOST_AUTO_TEST_CASE(the_larger_body_gives_the_normal_at_the_corner_of_the_smaller) {
  for (const ContactNormal rule : {ContactNormal::larger_volume, ContactNormal::mass_gradients}) {
    Grid G = two_field_grid();
    // Body 0: a corner at (2, 2, 2), its interior towards -x and -y. Body 1: a face along x.
    G.mass[entry(G, 0, 1, 2, 2)] = 1.0;
    G.mass[entry(G, 0, 2, 1, 2)] = 1.0;
    G.mass[entry(G, 0, 2, 2, 2)] = 0.25;
    G.mass[entry(G, 1, 2, 2, 2)] = 0.5;
    G.mass[entry(G, 1, 3, 2, 2)] = 1.0;
    G.mass[entry(G, 1, 2, 1, 2)] = 0.5;  // body 1 continues along y: no y gradient of its own
    G.mass[entry(G, 1, 2, 3, 2)] = 0.5;
    const int a = entry(G, 0, 2, 2, 2), b = entry(G, 1, 2, 2, 2);
    G.velocity_new[a] = G.velocity[a] = Vec3(0.0, 1.0, 0.0);  // sliding along y
    G.velocity_new[b] = G.velocity[b] = Vec3::Zero();
    const ContactTotals t =
        apply_contact(G, friction(0.0, rule), G.velocity_new, ContactPass::step);
    if (rule == ContactNormal::larger_volume) {
      BOOST_TEST(t.contact_nodes == 0);
      BOOST_TEST(G.velocity_new[a] == Vec3(0.0, 1.0, 0.0));
    } else {  // grad m_1 - grad m_0 = (1, 0.5, 0): the slide has u_n > 0 along it
      BOOST_TEST(t.contact_nodes == 1);
      BOOST_TEST(G.velocity_new[a](1) < 1.0);
    }
  }
}

// On a 2D grid (one node plane, k = 0) the mass gradient has no z component: the flat interface
// of the first case with body 0's mass continuing along +y, approaching along x. Reading k +- 1 as
// nodes, the gradient took (m(2, 3) - m(2, 1)) / 2 m as its z component and the correction pushed
// the bodies out of the plane (v_z +1/3 and -1/3 here, the cells being as wide as the 1 m along
// z; on a rod-on-plate scene the particles drifted off z = 0 at up to 0.17 m/s).
BOOST_AUTO_TEST_CASE(a_2d_grid_has_no_mass_gradient_along_z) {
  Grid G(unit_cells(GridGeometry::plane_strain), two_fields());
  G.mass[entry(G, 0, 1, 2, 0)] = 1.0;
  G.mass[entry(G, 0, 2, 2, 0)] = 0.5;
  G.mass[entry(G, 0, 2, 3, 0)] = 1.0;
  G.mass[entry(G, 1, 2, 2, 0)] = 0.5;
  G.mass[entry(G, 1, 3, 2, 0)] = 1.0;
  const int a = entry(G, 0, 2, 2, 0), b = entry(G, 1, 2, 2, 0);
  G.velocity_new[a] = G.velocity[a] = Vec3(1.0, 0.0, 0.0);
  G.velocity_new[b] = G.velocity[b] = Vec3(-1.0, 0.0, 0.0);
  const ContactTotals t = apply_contact(G, friction(0.0), G.velocity_new, ContactPass::step);
  BOOST_TEST(t.contact_nodes == 1);
  BOOST_TEST(G.velocity_new[a](2) == 0.0);
  BOOST_TEST(G.velocity_new[b](2) == 0.0);
}

// Axisymmetric (x the axis, y the radius, unit cells): two bodies of uniform density stacked along
// the axis, body 0 below a flat interface at x = 2 where it holds 3/4 of the node's mass, body 1
// above, both from the axis out to r = 4. Their ring masses grow with r: m = w(r) = r off the
// axis (h/6 on it, a hat's share). The bodies slide radially against each other (v_0 = -1,
// v_1 = +1 along r) with no approach along the axis, frictionless: the normal is the axis, so
// nothing may be corrected. Differencing the mass, the normal at (2, 2) tilted by
// atan(0.5 / 2) = 14 degrees (grad_total - 2 grad_0 = (2, -0.5)), the slide read as an approach
// and both bodies were stopped radially; with the mass per unit radius the radial differences of
// a uniform body are zero, on the axis by symmetry and next to it one-sided.
BOOST_AUTO_TEST_CASE(an_axisymmetric_flat_interface_has_an_axial_normal) {
  Grid G(unit_cells(GridGeometry::axisymmetric), two_fields());
  const double alpha = 0.75;
  for (int j = 0; j <= 4; ++j) {
    const double w = j == 0 ? 1.0 / 6.0 : double(j);
    for (int i = 0; i <= 4; ++i) {
      if (i <= 2) G.mass[entry(G, 0, i, j, 0)] = i < 2 ? w : alpha * w;
      if (i >= 2) G.mass[entry(G, 1, i, j, 0)] = i > 2 ? w : (1.0 - alpha) * w;
    }
  }
  for (int j = 0; j <= 3; ++j) {
    const int a = entry(G, 0, 2, j, 0), b = entry(G, 1, 2, j, 0);
    G.velocity_new[a] = G.velocity[a] = Vec3(0.0, -1.0, 0.0);
    G.velocity_new[b] = G.velocity[b] = Vec3(0.0, 1.0, 0.0);
  }
  const ContactTotals t = apply_contact(G, friction(0.0), G.velocity_new, ContactPass::step);
  BOOST_TEST(t.contact_nodes == 0);
  for (int j = 0; j <= 3; ++j) {
    BOOST_TEST(G.velocity_new[entry(G, 0, 2, j, 0)] == Vec3(0.0, -1.0, 0.0), "r = " << j);
    BOOST_TEST(G.velocity_new[entry(G, 1, 2, j, 0)] == Vec3(0.0, 1.0, 0.0), "r = " << j);
  }
}

// A `symmetric` y- face: the flat interface at x = 2 meets the symmetry plane, body 0 holding 3/4
// of the interface nodes' mass, both bodies of uniform density continuing along y and beyond the
// face as their mirror images. Their particles reach only their own side, so the nodal masses
// near the face are what a body ending at the plane gives: the face layer j = 0 half the interior
// mass, j = 1 0.9 of it, the ghost layer j = -1 the particles' tails, 0.1 (with the image's
// share, m(j) + m(-j), every layer is 1). Approaching along x, frictionless, nodes (2, 0, 2) and
// (2, 1, 2) must stop the approach: both bodies move with the centre of mass, v_x = 0.5,
// v_y = 0. Differencing the masses as they were tilted the normal by 27 degrees at j = 0 and by
// 7 degrees at j = 1 (the ghost read as its mirror node fixed j = 0 only); the correction along
// it left the x velocities apart and put v_y on the nodes.
BOOST_AUTO_TEST_CASE(a_symmetric_face_adds_the_mirror_images_mass_to_its_normals) {
  GridSpec spec = unit_cells();
  spec.faces[2] = FaceCondition::symmetric;
  const double alpha = 0.75;
  for (const int node : {0, 1}) {
    Grid G(spec, two_fields());
    for (int j = -1; j <= 3; ++j) {
      const double w = j == -1 ? 0.1 : j == 0 ? 0.5 : j == 1 ? 0.9 : 1.0;
      for (int k = 1; k <= 3; ++k) {
        G.mass[entry(G, 0, 1, j, k)] = w;
        G.mass[entry(G, 0, 2, j, k)] = alpha * w;
        G.mass[entry(G, 1, 2, j, k)] = (1.0 - alpha) * w;
        G.mass[entry(G, 1, 3, j, k)] = w;
      }
    }
    const int a = entry(G, 0, 2, node, 2), b = entry(G, 1, 2, node, 2);
    G.velocity_new[a] = G.velocity[a] = Vec3(1.0, 0.0, 0.0);
    G.velocity_new[b] = G.velocity[b] = Vec3(-1.0, 0.0, 0.0);
    apply_contact(G, friction(0.0), G.velocity_new, ContactPass::step);
    BOOST_TEST((G.velocity_new[a] - Vec3(0.5, 0.0, 0.0)).norm() < 1e-15,
               "j = " << node << ": " << G.velocity_new[a].transpose());
    BOOST_TEST((G.velocity_new[b] - Vec3(0.5, 0.0, 0.0)).norm() < 1e-15,
               "j = " << node << ": " << G.velocity_new[b].transpose());
  }
}

BOOST_AUTO_TEST_SUITE_END()
