// Active-block grid (grid/grid.hpp, docs/performance.md#active-blocks): the grid loops
// visit only the 2x2x2-node blocks the particles' stencils touch. Skipping nodes without mass
// must not change a single bit of what the particles see:
// (a) the report's Case 1 deck (data/scenes/sphere_cylinder/case01.json: four velocity fields,
//     friction contact with nodal stress and friction heat, artificial viscosity, particle
//     conversion, six symmetric faces) for 40 steps with 2 threads, active blocks against the
//     dense grid: every particle position, velocity and stress equal (==), and every ledger
//     column equal except the contact and friction sums, whose per-thread partials are grouped
//     differently (node chunks differ): those to 1e-12 relative (measured 0 so far);
// (b) two spheres under gravity (external impulse and work summed serially over the nodes) with
//     1 thread: every ledger row equal (==);
// (c) the work follows the particles: on Case 1 the active nodes cover every stencil node and
//     skip the hollow cylinder's interior and the box's corners: 15 524 of 28 037 nodes after
//     the first step (0.554; 0.79 with 4x4x4 blocks, hence 2x2x2); asserted below 0.6.
#include <boost/test/unit_test.hpp>
#include <set>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Result {
  std::vector<Vec3> x, v;
  std::vector<Mat3> stress;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::size_t active = 0, nodes = 0;
};

Scene case01(bool active_blocks) {
  const std::string file =
      std::string(IMPACT_SOURCE_DIR) + "/data/scenes/sphere_cylinder/case01.json";
  Scene s = read_scene(load_scene_document(file), file);
  s.grid.active_blocks = active_blocks;
  return s;
}

Result run(const Scene& scene, int threads, int steps) {
  Simulation sim(scene, threads);
  BOOST_REQUIRE(sim.threads() == threads);
  Result r;
  r.columns = sim.ledger().columns();
  for (int i = 0; i < steps && !sim.finished(); ++i) {
    sim.step();
    r.rows.push_back(sim.ledger().values(sim.ledger().row()));
  }
  BOOST_REQUIRE(sim.steps() == steps);
  const Particles& P = sim.particles();
  r.x = P.x;
  r.v = P.v;
  for (const PointState& s : P.state) r.stress.push_back(s.stress);
  r.active = sim.grid().active_nodes().size();
  r.nodes = static_cast<std::size_t>(sim.grid().node_count());
  return r;
}

std::size_t differing_particles(const Result& a, const Result& b) {
  BOOST_REQUIRE(a.x.size() == b.x.size());
  std::size_t differ = 0;
  for (std::size_t p = 0; p < a.x.size(); ++p)
    if (!(a.x[p] == b.x[p]) || !(a.v[p] == b.v[p]) || !(a.stress[p] == b.stress[p])) ++differ;
  return differ;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_active_blocks)

BOOST_AUTO_TEST_CASE(case01_active_blocks_equal_dense_grid) {
  constexpr int kSteps = 40;
  const Result dense = run(case01(false), 2, kSteps);
  const Result sparse = run(case01(true), 2, kSteps);
  BOOST_TEST(dense.active == dense.nodes);
  BOOST_TEST(differing_particles(dense, sparse) == 0u);
  BOOST_REQUIRE(dense.rows.size() == sparse.rows.size());
  double worst = 0.0;
  for (std::size_t c = 0; c < dense.columns.size(); ++c) {
    const bool grouped = dense.columns[c].find("contact") != std::string::npos ||
                         dense.columns[c].find("friction") != std::string::npos;
    for (std::size_t i = 0; i < dense.rows.size(); ++i) {
      const double a = dense.rows[i][c], b = sparse.rows[i][c];
      if (grouped) {
        worst = std::max(worst, std::abs(a - b) / std::max(std::abs(a), 1e-300));
      } else {
        BOOST_TEST(a == b, dense.columns[c] << " at step " << i + 1);
      }
    }
  }
  BOOST_TEST_MESSAGE("case01, " << kSteps << " steps, 2 threads: contact/friction columns differ "
                                << "by " << worst << " relative");
  BOOST_TEST(worst < 1e-12);
}

BOOST_AUTO_TEST_CASE(gravity_sums_are_bit_identical_with_one_thread) {
  const Json gravity = {{"solver", {{"gravity", {0.0, -9.81e6, 0.0}}}}};
  Scene dense = test::verification_scene("two_spheres.json", gravity);
  Scene sparse = dense;
  dense.grid.active_blocks = false;
  sparse.grid.active_blocks = true;
  const Result a = run(dense, 1, 30), b = run(sparse, 1, 30);
  BOOST_TEST(differing_particles(a, b) == 0u);
  BOOST_REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i) BOOST_TEST(a.rows[i] == b.rows[i]);
  BOOST_TEST(b.active < b.nodes);
}

BOOST_AUTO_TEST_CASE(active_nodes_cover_the_stencils_and_skip_the_hollow) {
  const Scene scene = case01(true);
  Simulation sim(scene, 1);
  sim.step();
  const Grid& G = sim.grid();
  const std::vector<int>& active = G.active_nodes();
  BOOST_TEST(std::is_sorted(active.begin(), active.end()));
  const std::set<int> set(active.begin(), active.end());
  // Every node a GIMP stencil of a particle reaches (3 per axis around the particle's cell).
  const Particles& P = sim.particles();
  const Vec3 inv = G.spacing().cwiseInverse();
  std::size_t missing = 0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Vec3 xi = (P.x[p] - G.lower()).cwiseProduct(inv);
    const int i = static_cast<int>(std::floor(xi(0))), j = static_cast<int>(std::floor(xi(1))),
              k = static_cast<int>(std::floor(xi(2)));
    for (int a = i - 1; a <= i + 2; ++a)
      for (int b = j - 1; b <= j + 2; ++b)
        for (int c = k - 1; c <= k + 2; ++c) {
          const int ia = std::clamp(a, -1, G.cells()[0] + 1);
          const int ib = std::clamp(b, -1, G.cells()[1] + 1);
          const int ic = std::clamp(c, -1, G.cells()[2] + 1);
          if (G.mass[G.index(ia, ib, ic)] > 0.0 && !set.count(G.index(ia, ib, ic))) ++missing;
        }
  }
  BOOST_TEST(missing == 0u);
  // Every node with mass (any field) is active.
  std::size_t massive_outside = 0;
  for (int f = 0; f < G.fields(); ++f)
    for (int I = 0; I < G.node_count(); ++I)
      if (G.mass[f * G.node_count() + I] > 0.0 && !set.count(I)) ++massive_outside;
  BOOST_TEST(massive_outside == 0u);
  const double fraction = double(active.size()) / G.node_count();
  BOOST_TEST_MESSAGE("case01: " << active.size() << " of " << G.node_count() << " nodes active ("
                                << fraction << ")");
  BOOST_TEST(fraction < 0.6);
}

BOOST_AUTO_TEST_SUITE_END()
