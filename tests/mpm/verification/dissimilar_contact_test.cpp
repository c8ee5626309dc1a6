// Contact between dissimilar elastic bodies keeps its books (issue 53):
// data/scenes/verification/rod_plate_elastic.json, a steel rod (4340, rho 7850 kg/m^3) at
// 100 m/s onto a free aluminium plate (6061, 2700 kg/m^3), both elastic (flow stress 1e15 Pa, no
// damage, heating or artificial viscosity), frictionless multi-field contact, axisymmetric, uGIMP,
// 6 cells per rod radius, run to 20 us (the rod has rebounded once and is ringing on the plate).
//
// Nothing dissipates in this scene but the contact's nodal collision, so the ledger's residual
// can only be a loss: a gain is energy the method made. The contact's strain pass
// (contact/contact.hpp, ContactPass::strain) holds the nodes the step held. When it decided
// contact again from the velocity the strain is built from, this scene gained +17 % of its energy
// by 20 us with MUSL and +14 % with USL (+30 % / +22 % by 40 us, first order in dt: +15.5 /
// +8.2 % at multipliers 0.25 / 0.125). Measured now (`mpm run` of the scene, --set
// '{"time":{"max_time":2e-5}}'): MUSL between -0.40 and +0.21 %, USL between -1.22 and +0.15 %
// (the gain is the stress power's mid-step term, which a single field has too).
// Asserted: no gain above 0.5 % of E0, no loss beyond 3 %, the axial momentum exchanged to
// round-off (p_x - p_x(0) is the faces' impulse J_x: the mirror overwrites what the rod's
// particles give the ghost layer beyond the axis).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Books {
  double largest_gain = 0.0;    // max energy_error over the run
  double largest_loss = 0.0;    // -min energy_error
  double momentum_drift = 0.0;  // max |p_x - J_x - p_x(0)| / p_x(0), J the faces' impulse
};

Books run_scene(const Json& overlay, const std::string& label);

Books run(const char* scheme) {
  return run_scene({{"time", {{"max_time", 2.0e-5}}}, {"solver", {{"scheme", scheme}}}}, scheme);
}

Books run_scene(const Json& overlay, const std::string& label) {
  const Scene scene = test::verification_scene("rod_plate_elastic.json", overlay);
  BOOST_REQUIRE(scene.materials.size() == 2);
  Simulation sim(scene);
  const double p0 = sim.ledger().initial_momentum()(0);
  Books b;
  while (!sim.finished()) {
    sim.step();
    const LedgerRow row = sim.ledger().row();
    b.largest_gain = std::max(b.largest_gain, row.energy_error);
    b.largest_loss = std::max(b.largest_loss, -row.energy_error);
    b.momentum_drift = std::max(b.momentum_drift,
                                std::abs((row.momentum(0) - row.boundary_impulse(0)) / p0 - 1.0));
  }
  BOOST_TEST_MESSAGE(label << ": energy_error between " << -b.largest_loss << " and "
                           << b.largest_gain << ", |p_x - J_x - p0| " << b.momentum_drift
                           << " of p0, " << sim.steps() << " steps");
  return b;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(dissimilar_contact)

BOOST_AUTO_TEST_CASE(a_steel_rod_on_an_aluminium_plate_makes_no_energy) {
  for (const char* scheme : {"musl", "usl"}) {
    const Books b = run(scheme);
    BOOST_TEST(b.largest_gain < 0.005, scheme);
    BOOST_TEST(b.largest_loss < 0.03, scheme);
    BOOST_TEST(b.momentum_drift < 1e-12, scheme);
  }
}

// Issue 53 asked for the coarse rod on plate's books below 5 % at 3 cells per rod radius and
// falling with h: it had ended at +0.42 (axisymmetric) and +0.19 (3D quarter). The whole scene
// (40 us: impact, separation at about 23 us, free flight) by `separation` with the fitted plane,
// at 3, 6 and 12 cells per radius (history rows: 0.68, 0.45, 0.33 %). By `approach` the same
// ladder gives 0.67, 0.44 and 2.3 % (1.4 % at 24): the gain comes after the bodies have parted,
// with no contact node left, in the plate alone, and is first order in dt (+0.98 % at
// multiplier 0.25); which state the earlier contact leaves to make it is not found yet
// (docs/verification.md).
BOOST_AUTO_TEST_CASE(the_rod_on_plates_books_close_better_as_h_falls_by_separation) {
  double worst[3];
  int k = 0;
  for (const int radius_cells : {3, 6, 12}) {
    const Json overlay = {{"grid", {{"cells", {radius_cells * 50 / 3, radius_cells * 20 / 3}}}},
                          {"physics",
                           {{"contact",
                             {{"type", "friction"},
                              {"mu", 0.0},
                              {"detection", "separation"},
                              {"normal", "logistic_regression"}}}}}};
    const Books b =
        run_scene(overlay, std::to_string(radius_cells) + " cells per radius, separation");
    worst[k++] = std::max(b.largest_gain, b.largest_loss);
    BOOST_TEST(b.momentum_drift < 1e-12);
  }
  for (int i = 0; i < 3; ++i) BOOST_TEST(worst[i] < 0.01);
  BOOST_TEST(worst[1] < 0.85 * worst[0]);
  BOOST_TEST(worst[2] < 0.85 * worst[1]);
}

// The 3D quarter at 3 cells per rod radius, by the default `approach` (symmetric y- and z- faces).
BOOST_AUTO_TEST_CASE(the_coarse_3d_quarter_rod_on_plate_keeps_its_books) {
  const Json overlay = {{"objects",
                         {{"rod", {{"particles_per_cell", {2, 2, 2}}}},
                          {"plate", {{"particles_per_cell", {2, 2, 2}}}}}},
                        {"grid",
                         {{"geometry", "3d"},
                          {"lower", {-0.0215, 0.0, 0.0}},
                          {"upper", {0.02, 0.0166, 0.0166}},
                          {"cells", {50, 20, 20}},
                          {"boundary", {{"z-", "symmetric"}, {"z+", "free"}}}}}};
  const Books b = run_scene(overlay, "3D quarter, 3 cells per radius, approach");
  BOOST_TEST(std::max(b.largest_gain, b.largest_loss) < 0.01);
  BOOST_TEST(b.momentum_drift < 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
