// The ledger of an axisymmetric grid books the axial momentum only (ledger.hpp
// momentum_components): the radial and hoop components of momentum, impulses and outflow are
// +0, never -0 (history.csv prints the sign: a product of a negative sum with 0 wrote "-0" in the
// momentum_y column at every step where the particles' radial momentum sum was negative), and the
// axial component is booked as given, bit for bit; a 3D ledger books every component unchanged.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "mpm/ledger/ledger.hpp"

using namespace impact;
using namespace impact::mpm;

BOOST_AUTO_TEST_SUITE(axisymmetric_ledger)

BOOST_AUTO_TEST_CASE(off_axis_components_are_plus_zero) {
  Ledger axi(false, true, Vec3(1.0, 0.0, 0.0));
  axi.start(0.0, 1.0, Vec3(-2.5, -3.0, -4.0));
  axi.record_step(1e-6, 1.0, Vec3(-2.25, -1.0, -0.5), 0.0, Vec3(0.25, -0.5, -0.75),
                  Vec3(-1.0, -1.0, -1.0), 0.0);
  axi.add_outflow(0.1, Vec3(-0.125, -0.25, -0.5), 0.01);
  const LedgerRow row = axi.row();
  for (const Vec3* v : {&row.momentum, &row.boundary_impulse, &row.outflow_momentum}) {
    BOOST_TEST(((*v)(1) == 0.0 && !std::signbit((*v)(1))));
    BOOST_TEST(((*v)(2) == 0.0 && !std::signbit((*v)(2))));
  }
  BOOST_TEST(row.momentum(0) == -2.25);
  BOOST_TEST(row.boundary_impulse(0) == 0.25);
  BOOST_TEST(row.outflow_momentum(0) == -0.125);
  BOOST_TEST(axi.initial_momentum() == Vec3(-2.5, 0.0, 0.0));
  BOOST_TEST(!std::signbit(axi.initial_momentum()(1)));

  Ledger three_d(false, true);
  three_d.start(0.0, 1.0, Vec3(-2.5, -0.0, -4.0));
  three_d.record_step(1e-6, 1.0, Vec3(-2.25, -0.0, -0.5), 0.0, Vec3(0.25, -0.5, -0.75),
                      Vec3::Zero(), 0.0);
  BOOST_TEST(three_d.row().momentum == Vec3(-2.25, -0.0, -0.5));
  BOOST_TEST(std::signbit(three_d.row().momentum(1)));  // as the particles' sum: unchanged
  BOOST_TEST(three_d.row().boundary_impulse == Vec3(0.25, -0.5, -0.75));
}

BOOST_AUTO_TEST_SUITE_END()
