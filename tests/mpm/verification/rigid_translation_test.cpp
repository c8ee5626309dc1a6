// A stress-free block translating uniformly on a free grid, through more than a cell: with exact
// partition of unity the grid velocity is the block's velocity, so positions are exact, the
// velocity gradient and hence the stress vanish, and the energy is constant. Tolerances: positions
// 1e-12 m, stress 1e-3 Pa (against rho c |v| = 6e8 Pa), energy 1e-12 relative. All four
// shape/scheme combinations: linear/USL relies on the light-node limiter of its velocity
// gradient (docs/mpm.md#usl-and-light-nodes-klightnodemassfraction-stepstephpp), without which
// round-off grows ~1e37-fold.
// On a graded grid (grid.refine, issue 56) the same holds to round-off: the tartan shapes keep
// partition of unity and reproduce linear fields on unequal cells, so the block crosses the
// grading steps (cells 5 mm -> 1 mm, growth 1.5) unchanged, with particles of a 1 mm cell beside
// particles 125 times heavier (a box too wide for its cells: tests/mpm/shape/tartan_test.cpp).
// Linear/USL at factor 2
// rests on the light-node rule's graded threshold, each node's mean particle mass
// (NodeData::mass_moment): with the lightest particle's, as on a uniform grid, it stopped unstable
// at step 158 of 206. (At factor 5 it runs, but round-off grows slowly: 0.024 Pa of stress by
// 50 us, 4e-11 of rho c |v|; its light nodes carry particles 125 times apart in mass.)
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

void check_rigid_translation(const char* interpolation, const char* scheme,
                             const Json& grid = Json::object(), const Json& time = Json::object()) {
  Json patch = test::with_solver(interpolation, scheme);
  if (!grid.empty()) patch["grid"] = grid;
  if (!time.empty()) patch["time"] = time;
  const Scene scene = test::verification_scene("rigid_translation.json", patch);
  Simulation sim(scene);
  const std::vector<Vec3> x0 = sim.particles().x;
  const Vec3 v0 = scene.objects[0].velocity;
  const double e0 = sim.ledger().initial_energy();
  double worst_x = 0.0, worst_stress = 0.0, worst_energy = 0.0;
  while (!sim.finished()) {
    sim.step();
    const Particles& P = sim.particles();
    for (std::size_t p = 0; p < P.size(); ++p) {
      worst_x = std::max(worst_x, (P.x[p] - x0[p] - v0 * sim.time()).cwiseAbs().maxCoeff());
      worst_stress = std::max(worst_stress, P.state[p].stress.cwiseAbs().maxCoeff());
    }
    worst_energy = std::max(worst_energy, std::abs(sim.ledger().row().total_energy / e0 - 1.0));
  }
  BOOST_TEST_MESSAGE(interpolation << "/" << scheme << ": " << sim.steps() << " steps, position "
                                   << worst_x << " m, stress " << worst_stress << " Pa, energy "
                                   << worst_energy);
  BOOST_TEST(worst_x < 1e-12);
  BOOST_TEST(worst_stress < 1e-3);
  BOOST_TEST(worst_energy < 1e-12);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_rigid_translation)

BOOST_AUTO_TEST_CASE(gimp_musl_translates_exactly_without_stress) {
  check_rigid_translation("gimp", "musl");
}
BOOST_AUTO_TEST_CASE(gimp_usl_translates_exactly_without_stress) {
  check_rigid_translation("gimp", "usl");
}
BOOST_AUTO_TEST_CASE(linear_musl_translates_exactly_without_stress) {
  check_rigid_translation("linear", "musl");
}
BOOST_AUTO_TEST_CASE(linear_usl_translates_exactly_without_stress) {
  check_rigid_translation("linear", "usl");
}

// The block's leading corner runs through a box of finer cells over 50 us (1.9 mm); particles
// seeded in 5 mm cells enter the growing cells and the box, others leave it.
Json graded(double factor) {
  return {{"refine",
           {{"lower", {0.037, 0.033, 0.033}},
            {"upper", {0.043, 0.039, 0.039}},
            {"factor", factor},
            {"growth", 1.5}}},
          {"cells", {12, 12, 12}}};
}
const Json kShort = {{"max_time", 5e-5}};

BOOST_AUTO_TEST_CASE(gimp_musl_translates_exactly_across_a_graded_grid) {
  check_rigid_translation("gimp", "musl", graded(5.0), kShort);
}
BOOST_AUTO_TEST_CASE(linear_usl_translates_exactly_across_a_graded_grid) {
  check_rigid_translation("linear", "usl", graded(2.0), kShort);
}

// Two boxes (grid.refine as a list): the leading corner's box above and one at the trailing
// corner refined 3 times; along each axis the 10 mm between their strips grade from both ends.
BOOST_AUTO_TEST_CASE(gimp_musl_translates_exactly_across_two_refined_boxes) {
  Json grid = graded(5.0);
  grid["refine"] = Json::array({grid["refine"],
                                {{"lower", {0.017, 0.021, 0.017}},
                                 {"upper", {0.023, 0.027, 0.023}},
                                 {"factor", 3.0},
                                 {"growth", 1.5}}});
  check_rigid_translation("gimp", "musl", grid, kShort);
}

BOOST_AUTO_TEST_SUITE_END()
