// A Taylor rod (House et al. 1995, shot H8: L0/D0 = 2, 328 m/s, 3 cells per radius; the scene
// data/scenes/verification/taylor_rod.json) with three failure settings:
//   off                physics.erosion = none (the reference shape);
//   shipped            the material file's stack (JC damage with the report's D1-D5, TEPLA,
//                      Drucker-Becker, AllowNoTension);
//   compression_aware  shipped plus damage.cutoff_triaxiality = -1/3 (Bao & Wierzbicki 2005),
//                      tepla.porosity_growth = tension, stability_check.outcome = report.
// The recovered rods of the experiment are whole. Asserted: as shipped, most of the core (initial
// radius <= R0/2) fails (measured 129 of 192: TEPLA 83, Drucker 46), some of it under pressure
// (12); with the options no core particle fails under pressure (a tensile mean stress at the
// failing step is recorded with the point, PointState::failed_in_tension; 2 rim particles do, at
// triaxialities between -1/3 and 0 where Bao & Wierzbicki do see fracture), and the final length
// stays within 1 % of the failure-off rod (measured -0.7 %). What still fails does so in tension:
// in the first 2 us the release waves from the free surface converge on the axis behind the
// impact face and put it in hydrostatic tension (3.4 GPa at 6-8 cells per radius, converged;
// docs/taylor.md), where the Johnson-Cook locus of Table 1 gives a fracture strain at its floor.
// The final length is the largest particle x plus half a particle spacing.
#include <array>
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Rod {
  double final_length = 0.0;  ///< [m]
  std::size_t core = 0, core_failed = 0, failed = 0, core_failed_in_compression = 0;
  std::size_t failed_in_compression = 0;
  std::array<std::size_t, 5> core_by_cause{};  ///< FailureCause order
};

Rod impact_rod(const Json& patch) {
  const Scene scene = test::verification_scene("taylor_rod.json", patch);
  Simulation sim(scene);
  const std::vector<Vec3> X = sim.particles().x;
  while (!sim.finished()) sim.step();
  const Particles& P = sim.particles();
  const double radius = 0.5 * 7.595e-3, spacing = sim.grid().spacing()(0) / 2.0;
  Rod rod;
  for (std::size_t p = 0; p < P.size(); ++p) {
    rod.final_length = std::max(rod.final_length, P.x[p](0) + 0.5 * spacing);
    const bool core = std::hypot(X[p](1), X[p](2)) <= 0.5 * radius;
    rod.core += core;
    rod.core_failed += core && P.state[p].failed;
    rod.failed += P.state[p].failed;
    const bool under_pressure = P.state[p].failed && !P.state[p].failed_in_tension;
    rod.core_failed_in_compression += core && under_pressure;
    rod.failed_in_compression += under_pressure;
    if (core && P.state[p].failed) ++rod.core_by_cause[std::size_t(P.state[p].failure_cause)];
  }
  BOOST_TEST_MESSAGE(
      "Lf " << rod.final_length << " m, failed " << rod.failed << ", core " << rod.core_failed
            << " of " << rod.core << " (melting " << rod.core_by_cause[1] << ", tepla "
            << rod.core_by_cause[2] << ", drucker " << rod.core_by_cause[3] << ", becker "
            << rod.core_by_cause[4] << "), in compression " << rod.core_failed_in_compression
            << " (rod " << rod.failed_in_compression << ")");
  return rod;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_taylor_rod)

BOOST_AUTO_TEST_CASE(compression_aware_failure_leaves_the_core_whole_and_the_length_unchanged) {
  const Rod off = impact_rod(Json::parse(R"({"physics": {"erosion": "none"}})"));
  const Rod shipped = impact_rod(Json::object());
  const Rod aware = impact_rod(Json::parse(R"({"materials": {"al": {"overrides": {
      "constitutive_model": {"damage": {"cutoff_triaxiality": -0.3333333333333333},
                             "tepla": {"porosity_growth": "tension"},
                             "stability_check": {"outcome": "report"}}}}}})"));
  BOOST_TEST(off.failed == 0u);
  BOOST_TEST(shipped.core_failed > shipped.core / 2);   // the report's stack fails the core
  BOOST_TEST(shipped.core_failed_in_compression > 0u);  // some of it under pressure
  BOOST_TEST(aware.core_failed_in_compression == 0u);   // none of the core under pressure
  BOOST_TEST(aware.final_length / off.final_length - 1.0 == 0.0,
             boost::test_tools::tolerance(0.01));
}

BOOST_AUTO_TEST_SUITE_END()
