// Two elastic blocks (data/scenes/verification/contact_blocks.json: two scene materials, so two
// velocity fields unless the contact is single_velocity) touching at t = 0 and approaching at
// 2 x 10 m/s along x with +-5 m/s along y, free grid faces, run with each contact model.
// Asserted, at every step, for every model:
//   - total momentum: |p - p0 - boundary impulse| <= 1e-12 p_block (p_block = one block's initial
//     |m v|): P2G/G2P conserve momentum, the internal forces of a field sum to zero and the
//     contact corrections of a node pair are equal and opposite (colinear normals); on free faces
//     the boundary impulse is zero exactly. Measured ~5e-15.
// single_velocity (one shared field, ordinary MPM), run 16 us: the blocks stick. In one field
//   they become one elastic body that keeps vibrating (nothing releases the interface), so the
//   centroids' relative velocity itself does not decay (it swings between about +-10 m/s, period
//   ~5 us). Asserted instead: the mean separation speed (least-squares slope of the centroid
//   distance over the last three quarters of the run) is below 5 % of the 20 m/s approach speed
//   (measured 0.08 m/s, 0.4 %), and the centroid distance never moves by more than 2 % of a cell
//   (measured 1.1 %, the vibration; the rebounding models open 8-10 % of a cell in 8 us).
// friction (mu = 0.3) and approach (mu = 0), run 8 us: the blocks rebound: the relative normal
//   velocity (left minus right, +20 m/s at the start) ends below -10 m/s, the mean separation
//   speed exceeds 10 m/s (measured 14.6 and 14.6 m/s) and the centroid distance grows.
// friction: Coulomb at every step: the tangential impulse on the left block never exceeds mu
//   times its normal impulse, |Dp_y| <= mu |Dp_x| + 1e-9 p_block (each node's correction has
//   |Dv_t| <= mu |Dv_n| with the normal along x on the contact face; 1e-9 p_block covers round-off
//   in the sums over nodes and steps). Measured: max |Dp_y|/|Dp_x| = 0.29989 (the contact slips
//   at the Coulomb limit), excess over mu |Dp_x| never positive.
// approach with mu = 0: the corrections are along the normals only, along x on the contact face,
//   so each block keeps its tangential momentum to within 1 % of p_y0. Not to round-off: at the
//   two y-edges of the contact face the mass-gradient normal tilts towards y as the blocks slide
//   past each other (0.08 cell in 8 us); measured max |Dp_y|/p_y0 = 0.24 %. (With the normal
//   `larger_volume`, the heavier block's own edge tilts it: 61 %; that normal is for a small body
//   on a large flat one, contact_friction_test.cpp.)
// approach with mu = 0: the ledger closes, |energy_error| < 2 % of E0 at the end; friction:
//   below 3 % at multipliers 0.5 and 0.1 (measured -1.9 % and -2.3 %), and the friction heat
//   converged in dt: within 1 % between multipliers 0.1 and 0.05 (measured 1.615 and 1.600 % of
//   E0, 0.9 % apart; 1.590 and 1.589 % before the strain pass kept the step's stick). A
//   separating pair is never pulled back (mpm/contact/contact.cpp, detection).
// friction: friction_heat (the Coulomb work in slip, m s (u0 . t) per node and field)
//   never decreases, step by step, is positive (the blocks slip: 10 m/s relative along y), and
//   stays below the kinetic energy of the relative tangential motion, 1/2 m1 m2/(m1 + m2)
//   |v_t1 - v_t2|^2 = 0.2 E0, which is all that friction can take; approach (mu = 0) books none
//   (no column).
// Reported (BOOST_TEST_MESSAGE), not asserted: single_velocity's energy_error (oscillating +-5 %:
// eq. 14's strain energy on this coarse impact).
#include <algorithm>
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct BlockTotals {
  double mass[2] = {0.0, 0.0};
  Vec3 momentum[2] = {Vec3::Zero(), Vec3::Zero()};
  Vec3 centroid[2] = {Vec3::Zero(), Vec3::Zero()};
};

BlockTotals block_totals(const Particles& P) {
  BlockTotals b;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int o = P.object[p];
    b.mass[o] += P.mass[p];
    b.momentum[o] += P.mass[p] * P.v[p];
    b.centroid[o] += P.mass[p] * P.x[p];
  }
  for (int o = 0; o < 2; ++o) b.centroid[o] /= b.mass[o];
  return b;
}

struct Measured {
  double worst_momentum = 0.0;     ///< max_steps |p - p0 - J_b| / p_block
  double worst_coulomb = 0.0;      ///< max_steps (|Dp_y| - mu |Dp_x|) / p_block
  double worst_tangential = 0.0;   ///< max_steps |p_y - p_y0| / |p_y0| of the left block
  double final_relative_vx = 0.0;  ///< (v_left - v_right)_x at the end [m/s]
  double separation_speed = 0.0;   ///< least-squares slope of the centroid distance [m/s]
  double centroid_distance0 = 0.0, centroid_distance = 0.0, worst_distance_change = 0.0;
  double spacing = 0.0;
  double energy_error = 0.0;   ///< the ledger's energy_error at the end [-]
  double heat_decrease = 0.0;  ///< max_steps (friction_heat_{n-1} - friction_heat_n) [J]
  double heat_fraction = 0.0;  ///< friction_heat / E0 at the end [-]
  bool has_friction_column = false;
};

Measured collide(const char* type, double mu, double max_time, double multiplier = 0.5,
                 const char* normal = "mass_gradients", const Json& refine = Json()) {
  // single_velocity reads no mu (and refuses one): only the friction model is given it.
  const Json contact = std::string(type) == "single_velocity"
                           ? Json{{"type", type}}
                           : Json{{"type", type}, {"mu", mu}, {"normal", normal}};
  Json patch = {{"physics", {{"contact", contact}}},
                {"time", {{"max_time", max_time}, {"multiplier", multiplier}}}};
  if (!refine.is_null()) patch["grid"]["refine"] = refine;
  const Scene scene = test::verification_scene("contact_blocks.json", patch);
  Simulation sim(scene);
  const Particles& P = sim.particles();
  const BlockTotals b0 = block_totals(P);
  const double p_block = b0.momentum[0].norm();
  const double v_approach = (b0.momentum[0] / b0.mass[0] - b0.momentum[1] / b0.mass[1])(0);
  Measured m;
  m.spacing = scene.grid.spacing()(0);
  m.centroid_distance0 = (b0.centroid[1] - b0.centroid[0])(0);
  const Vec3 p0 = sim.ledger().initial_momentum();
  double max_dpx = 0.0, max_dpy = 0.0, max_ratio = 0.0;
  // Least-squares line through the centroid distance d(t) for t > max_time / 4 (after the first
  // passage of the waves, 2 L / c = 2 us): its slope is the mean separation speed, insensitive to
  // the vibration the blocks keep after the impact.
  double s_n = 0.0, s_t = 0.0, s_d = 0.0, s_tt = 0.0, s_td = 0.0;
  const auto& names = sim.ledger().sink_names();
  m.has_friction_column = std::find(names.begin(), names.end(), "friction_heat") != names.end();
  double heat = 0.0;
  const double e0 = sim.ledger().initial_energy();
  while (!sim.finished()) {
    sim.step();
    const LedgerRow row = sim.ledger().row();
    const double heat_now = test::ledger_sink(sim.ledger(), "friction_heat");
    m.heat_decrease = std::max(m.heat_decrease, heat - heat_now);
    heat = heat_now;
    m.worst_momentum =
        std::max(m.worst_momentum, (row.momentum - p0 - row.boundary_impulse).norm() / p_block);
    const BlockTotals b = block_totals(P);
    const Vec3 dp = b.momentum[0] - b0.momentum[0];
    max_dpx = std::max(max_dpx, std::abs(dp(0)));
    max_dpy = std::max(max_dpy, std::abs(dp(1)));
    m.worst_coulomb = std::max(m.worst_coulomb, (std::abs(dp(1)) - mu * std::abs(dp(0))) / p_block);
    if (std::abs(dp(0)) > 1e-3 * p_block)
      max_ratio = std::max(max_ratio, std::abs(dp(1)) / std::abs(dp(0)));
    m.worst_tangential =
        std::max(m.worst_tangential, std::abs(dp(1)) / std::abs(b0.momentum[0](1)));
    const Vec3 relative = b.momentum[0] / b.mass[0] - b.momentum[1] / b.mass[1];
    m.final_relative_vx = relative(0);
    m.centroid_distance = (b.centroid[1] - b.centroid[0])(0);
    m.worst_distance_change =
        std::max(m.worst_distance_change, std::abs(m.centroid_distance - m.centroid_distance0));
    if (sim.time() > 0.25 * scene.time.max_time) {
      const double t = sim.time(), d = m.centroid_distance;
      s_n += 1.0;
      s_t += t;
      s_d += d;
      s_tt += t * t;
      s_td += t * d;
    }
  }
  m.separation_speed = (s_n * s_td - s_t * s_d) / (s_n * s_tt - s_t * s_t);
  const LedgerRow row = sim.ledger().row();
  m.energy_error = row.energy_error;
  m.heat_fraction = heat / e0;
  BOOST_TEST_MESSAGE(
      type << " (mu " << mu << ", multiplier " << multiplier << "): " << P.size() << " particles, "
           << sim.steps() << " steps, fields " << sim.grid().fields()
           << "; max |p - p0 - J_b|/p_block " << m.worst_momentum << "; final relative v_x "
           << m.final_relative_vx << " m/s (was " << v_approach
           << "), mean separation speed (slope of the centroid distance) " << m.separation_speed
           << " m/s; centroid distance " << m.centroid_distance0 * 1e3 << " -> "
           << m.centroid_distance * 1e3 << " mm (max change " << m.worst_distance_change / m.spacing
           << " cells); left block max |Dp_x| " << max_dpx / p_block << ", max |Dp_y| "
           << max_dpy / p_block << " p_block, max |Dp_y|/|Dp_x| " << max_ratio
           << ", max (|Dp_y| - mu |Dp_x|)/p_block " << m.worst_coulomb << ", max |Dp_y|/p_y0 "
           << m.worst_tangential << "; energy_error " << row.energy_error << ", friction_heat "
           << test::ledger_sink(sim.ledger(), "friction_heat") << " J of E0 "
           << sim.ledger().initial_energy() << " J");
  return m;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_contact_blocks)

BOOST_AUTO_TEST_CASE(single_velocity_conserves_momentum_and_the_blocks_stick) {
  const Measured m = collide("single_velocity", 0.0, 16e-6);
  BOOST_TEST(m.worst_momentum <= 1e-12);
  BOOST_TEST(m.worst_distance_change < 0.02 * m.spacing);
  BOOST_TEST(std::abs(m.separation_speed) < 0.05 * 20.0);
}

BOOST_AUTO_TEST_CASE(friction_conserves_momentum_obeys_coulomb_and_the_blocks_rebound) {
  const double mu = 0.3;
  const Measured m = collide("friction", mu, 8e-6);
  BOOST_TEST(m.worst_momentum <= 1e-12);
  BOOST_TEST(m.worst_coulomb <= 1e-9);
  // The Coulomb work in slip, m s (u0 . t) on the start slip, converges with dt: 1.141 / 1.575 /
  // 1.615 / 1.600 % of E0 at multipliers 0.5 / 0.2 / 0.1 / 0.05 (0.87 / 1.53 / 1.590 / 1.589 %
  // before the strain pass kept the step's stick). Booked on the slip that remains after the
  // correction it was 13.2 / 7.2 / 3.8 % at 0.5 / 0.25 / 0.1 (first order, too much), and on the
  // start slip without the stick test it also counted heat in stick. What remains of
  // energy_error, -1.9 % to -2.3 %, is the projection of the fields onto their centre of mass
  // at the contact nodes (a grid-scale loss; approach with mu 0 below: -0.1 %).
  BOOST_TEST(std::abs(m.energy_error) < 0.03);
  const Measured fine = collide("friction", mu, 8e-6, 0.1);
  const Measured finer = collide("friction", mu, 8e-6, 0.05);
  BOOST_TEST(std::abs(fine.heat_fraction / finer.heat_fraction - 1.0) < 0.01);
  BOOST_TEST(std::abs(fine.energy_error) < 0.03);
  BOOST_TEST(m.has_friction_column);
  BOOST_TEST(m.heat_decrease == 0.0);
  BOOST_TEST(m.heat_fraction > 0.0);
  BOOST_TEST(m.heat_fraction < 0.2);
  BOOST_TEST(m.final_relative_vx < -0.5 * 20.0);
  BOOST_TEST(m.separation_speed > 0.5 * 20.0);
  BOOST_TEST(m.centroid_distance > m.centroid_distance0);
}

BOOST_AUTO_TEST_CASE(approach_conserves_momentum_keeps_tangential_momentum_and_rebounds) {
  const Measured m = collide("approach", 0.0, 8e-6);
  BOOST_TEST(m.worst_momentum <= 1e-12);
  BOOST_TEST(m.worst_tangential <= 0.01);
  BOOST_TEST(std::abs(m.energy_error) < 0.02);
  BOOST_TEST(!m.has_friction_column);
  BOOST_TEST(m.final_relative_vx < -0.5 * 20.0);
  BOOST_TEST(m.separation_speed > 0.5 * 20.0);
  BOOST_TEST(m.centroid_distance > m.centroid_distance0);
}

// On a graded grid (grid.refine, issue 56): the contact face x = 10 mm inside a box of cells
// twice as fine (x in [8, 12] mm, growth 1.5 outside it), so the blocks' far halves lie in
// coarser cells. The normals difference the nodal density (mass over the node's dual cell,
// contact.cpp dual_volume) over the nodes' distances: the same bounds as on the uniform grid.
BOOST_AUTO_TEST_CASE(approach_on_a_graded_grid_conserves_momentum_and_rebounds) {
  const Json box = {{"lower", {0.008, 0.0, 0.0}},
                    {"upper", {0.012, 0.012, 0.008}},
                    {"factor", 2},
                    {"growth", 1.5}};
  const Measured m = collide("approach", 0.0, 8e-6, 0.5, "mass_gradients", box);
  BOOST_TEST(m.worst_momentum <= 1e-12);
  BOOST_TEST(m.worst_tangential <= 0.01);
  BOOST_TEST(std::abs(m.energy_error) < 0.02);
  BOOST_TEST(m.final_relative_vx < -0.5 * 20.0);
  BOOST_TEST(m.separation_speed > 0.5 * 20.0);
  BOOST_TEST(m.centroid_distance > m.centroid_distance0);
}

// The plane separating the two bodies' particles (`logistic_regression`, Nairn, Hammerquist &
// Smith 2020) is right where the blocks' edges meet: the tangential momentum stays within 1 % as
// with the sum of the gradients, where `larger_volume` took the heavier block's tilted edge and
// lost more than 10 % (measured in the messages).
BOOST_AUTO_TEST_CASE(the_separating_plane_keeps_tangential_momentum_at_two_equal_edges) {
  const Measured plane = collide("approach", 0.0, 8e-6, 0.5, "logistic_regression");
  const Measured larger = collide("approach", 0.0, 8e-6, 0.5, "larger_volume");
  BOOST_TEST_MESSAGE("tangential momentum change: logistic_regression "
                     << plane.worst_tangential << ", larger_volume " << larger.worst_tangential
                     << "; energy_error " << plane.energy_error);
  BOOST_TEST(plane.worst_momentum <= 1e-12);
  BOOST_TEST(plane.worst_tangential <= 0.01);
  BOOST_TEST(larger.worst_tangential > 0.1);
  BOOST_TEST(std::abs(plane.energy_error) < 0.02);
  BOOST_TEST(plane.final_relative_vx < -0.5 * 20.0);
}

BOOST_AUTO_TEST_SUITE_END()
