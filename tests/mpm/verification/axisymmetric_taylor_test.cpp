// The Taylor rod H8 (House et al. 1995: 6061-T6, D0 7.595 mm, L0 15.19 mm, 328 m/s onto the
// rigid frictionless anvil, failure off) in axisymmetry (Sulsky & Schreyer 1996) against the 3D
// quarter model at the same 6 cells per radius: data/scenes/taylor/h8_axisymmetric.json and its
// twin h8_quarter.json as shipped, the same rod, material and physics, differing only in the grid.
// Measured as campaigns/taylor/taylor.py does (docs/taylor.md): Lf the largest particle x plus the
// axial seed offset, Dm twice the largest radius within 0.5 mm of the anvil plus the radial one,
// each offset taken from the model's own seeding at t = 0 (the measures are exact there; the 2D
// section's outermost row lies h/2 inside the rim, the 3D quarter's staircase closer to it).
// Asserted, with what was measured:
//   - Lf within 0.5 % (2D 11.3025 mm, quarter 11.2999 mm: +0.023 %; the campaign's table1 H8 at
//     6 cells per radius, docs/taylor.md: 11.300);
//   - Dm within 2 % (13.3256 / 13.3254 mm: +0.002 %; campaign 13.33);
//   - the books alike: every 2D total is the whole rod's, so E0 = 4 times the quarter's within 2 %
//     (+0.98 %: the seeded quarter holds 0.990 of the exact volume, the rings of the 2D section
//     exactly 1); the strain energy at the end as a fraction of E0 within 1 % (0.9437 / 0.9428);
//     energy_error within 0.005 of each other (+0.00022 / -0.00088).
// 1355 and 1358 steps, 576 and 5376 particles. At 4 cells per radius (grid patched; not part of
// the test) Lf +0.18 %, Dm -1.6 %. With the material's failure stack (physics.erosion as shipped)
// the two models fail different particles and Dm parts by 5 % at 4 cells per radius: the
// comparison is of the mechanics, with failure off as the campaign's default.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;
namespace tt = boost::test_tools;

namespace {

constexpr double kRadius = 0.5 * 7.595e-3, kLength = 15.19e-3;  // House H8 [m]
constexpr double kAnvilLayer = 0.5e-3;  // Dm from the particles this close to the anvil [m]

struct Rod {
  double final_length = 0.0, mushroom_diameter = 0.0;  ///< Lf, Dm [m]
  double initial_energy = 0.0, strain = 0.0, energy_error = 0.0;
};

Rod impact_rod(const std::string& scene_file) {
  Simulation sim(test::shipped_scene("taylor/" + scene_file),
                 1);  // no barrier waits on a busy host
  const std::vector<Vec3> X = sim.particles().x;
  // The radius about the x axis: on the 2D grid the particles sit at z = 0, so it is y.
  const auto radius = [](const Vec3& x) { return std::hypot(x(1), x(2)); };
  double top = 0.0, rim = 0.0;
  for (const Vec3& x : X) top = std::max(top, x(0)), rim = std::max(rim, radius(x));
  while (!sim.finished()) sim.step();
  const Particles& P = sim.particles();
  double length = 0.0, mushroom = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    length = std::max(length, P.x[p](0));
    if (P.x[p](0) < kAnvilLayer) mushroom = std::max(mushroom, radius(P.x[p]));
  }
  Rod rod;
  rod.final_length = length + (kLength - top);
  rod.mushroom_diameter = 2.0 * (mushroom + (kRadius - rim));
  const LedgerRow row = sim.ledger().row();
  rod.initial_energy = sim.ledger().initial_energy();
  rod.strain = row.strain_energy;
  rod.energy_error = row.energy_error;
  BOOST_TEST_MESSAGE(scene_file << ": " << P.size() << " particles, " << sim.steps()
                                << " steps, Lf " << rod.final_length << " m, Dm "
                                << rod.mushroom_diameter << " m, E0 " << rod.initial_energy
                                << " J, strain " << rod.strain << " J, kinetic "
                                << row.kinetic_energy << " J, energy_error " << rod.energy_error);
  return rod;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_axisymmetric_taylor)

BOOST_AUTO_TEST_CASE(h8_in_axisymmetry_matches_the_quarter_model) {
  const Rod ring = impact_rod("h8_axisymmetric.json");
  const Rod quarter = impact_rod("h8_quarter.json");
  BOOST_TEST(ring.final_length / quarter.final_length - 1.0 == 0.0, tt::tolerance(0.005));
  BOOST_TEST(ring.mushroom_diameter / quarter.mushroom_diameter - 1.0 == 0.0, tt::tolerance(0.02));
  BOOST_TEST(ring.initial_energy / (4.0 * quarter.initial_energy) - 1.0 == 0.0,
             tt::tolerance(0.02));
  BOOST_TEST(
      (ring.strain / ring.initial_energy) / (quarter.strain / quarter.initial_energy) - 1.0 == 0.0,
      tt::tolerance(0.01));
  BOOST_TEST(ring.energy_error - quarter.energy_error == 0.0, tt::tolerance(0.005));
}

BOOST_AUTO_TEST_SUITE_END()
