// The MPI domain decomposition (mpm/parallel/, docs/mpi.md), run under mpirun on 2 and 4 ranks
// (CTest: mpm_ranks_test_np2, _np4). Every rank also runs the scene alone (one rank, no
// MPI call) as the reference, so each comparison is made in one process:
//   - the recommended sphere-cylinder (one velocity field, symmetric faces) and Case 1 (two
//     materials with friction contact, artificial viscosity, erosion and particle conversion) and
//     two blocks in friction contact on a box boundary: the ledger's energies equal the one-rank
//     run's to 1e-9 of E0 and its momentum to 1e-9 of sqrt(2 M E0) at every step (what differs is
//     the order of the sums at the shared nodes and of the reductions: round-off), and the
//     momentum closes as well as on one rank;
//   - the recommended scene with solver.ranks_per_axis "least_loaded": the boxes the run counts
//     its way to are the search's on the whole seeding in one process, less loaded than the
//     split cutting the fewest faces, and it books as above;
//   - Case 1 split in boxes across y and z (1 x 2 x 1 and 1 x 1 x 2 on 2 ranks, 2 x 2 x 1 and
//     1 x 2 x 2 on 4: nodes along the box edges shared by four ranks) likewise;
//   - every verification scene, its first 60 steps, to 1e-9 likewise;
//   - a rigid block flying in +x through every slab boundary, and one flying diagonally through
//     fixed boxes (across a box corner on 4 ranks): the particle count and the mass are
//     unchanged, every particle's position (found by its id) is exact to 1e-12 m, and the
//     kinetic energy and momentum equal the one-rank run's to 1e-12;
//   - the logistic-regression contact normal with the contact face on a box boundary, in slabs
//     and in boxes, 3D and axisymmetric: as on one rank to 1e-9 (the clouds' ghost particles);
//   - the same scene on the same rank count twice: the same bits;
//   - each rank's grid stores only its box's nodes and the halo, also after re-balancing.
// Without the node-layer sums the shared nodes miss the neighbour's mass and force (energies off
// by percents within a few steps; without the y and z sums the split cases and the verification
// scenes split across y fail); without the contact layer beyond them Case 1's contact normals
// differ at the box boundaries; without migration the block's particles leave their box and are
// lost to the sums.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/input/scene_reader.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/parallel/split_search.hpp"
#include "mpm/simulation/simulation.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// MPI_Init from the test module's command line (mpirun passes none of its own).
struct MpiFixture {
  MpiFixture()
      : session(boost::unit_test::framework::master_test_suite().argc,
                boost::unit_test::framework::master_test_suite().argv) {}
  MpiSession session;
};
MpiFixture* fixture = nullptr;
struct GlobalSetup {
  GlobalSetup() { fixture = new MpiFixture; }
  ~GlobalSetup() { delete fixture; }
};
BOOST_TEST_GLOBAL_FIXTURE(GlobalSetup);

Scene scene_from(const std::string& file, const Json& patch) {
  Json doc = load_scene_document(std::string(IMPACT_SOURCE_DIR) + "/data/scenes/" + file);
  doc.merge_patch({{"output", {{"snapshots", false}}}});
  doc.merge_patch(patch);
  return read_scene(doc, file);
}

// Each rank's grid stores its box's nodes and the halo only (never the whole grid): the nodes
// [c0 - kHaloPlanes, c1 + kHaloPlanes] per axis within [-1, cells + 1], for the current boxes.
void expect_box_grid(const Simulation& ranks) {
  const int r = ranks.rank();
  const NodeBox stored = ranks.grid().stored();
  int count = 1;
  for (std::size_t d = 0; d < 3; ++d) {
    const int cells = ranks.scene().grid.cells[d];
    const bool one_plane = d == 2 && ranks.scene().grid.planar();  // a 2D grid's z: k = 0 only
    const int first = one_plane ? 0 : std::max(ranks.boxes().first_cell(r)[d] - kHaloPlanes, -1);
    const int last =
        one_plane ? 0 : std::min(ranks.boxes().end_cell(r)[d] + kHaloPlanes, cells + 1);
    BOOST_TEST(stored.first[d] == first);
    BOOST_TEST(stored.last[d] == last);
    count *= last - first + 1;
  }
  BOOST_TEST(ranks.grid().node_count() == count);
}

// Steps both runs to the end; returns the migrations summed over the steps and ranks.
long step_both_to_the_end(Simulation& ranks, Simulation& alone, const Communicator& comm) {
  long migrated = 0;
  while (!alone.finished()) {
    alone.step();
    ranks.step();
    migrated += static_cast<long>(comm.sum(std::int64_t(ranks.migrated())));
  }
  return migrated;
}

// Steps both runs to the end (or `max_steps`), comparing the ledgers at every step. Energies are
// compared against E = the largest kinetic + strain energy of the one-rank run (E0, unless work
// is done on the bodies from rest), momenta against sqrt(2 M E) (|p0| is zero for two bodies
// meeting head-on).
void compare_with_one_rank(const Scene& scene, double tolerance, long max_steps = 1L << 40) {
  const Communicator comm(&fixture->session);
  BOOST_TEST_REQUIRE(comm.size() > 1);
  Simulation ranks(scene, 1, comm), alone(scene, 1);
  const double e0 = alone.ledger().initial_energy();
  double mass = 0.0;
  for (double m : alone.particles().mass) mass += m;
  BOOST_TEST(std::abs(ranks.ledger().initial_energy() - e0) <= 1e-12 * e0);  // summed by slab
  double energy = e0, d_energy = 0.0, d_momentum = 0.0, closure = 0.0, closure_alone = 0.0;
  long migrated = 0;
  while (!alone.finished() && alone.steps() < max_steps) {
    alone.step();
    ranks.step();
    // The step follows the fastest signal speed, which round-off can move.
    BOOST_TEST_REQUIRE(std::abs(ranks.time() - alone.time()) <= 1e-9 * alone.time());
    const LedgerRow a = alone.ledger().row(), r = ranks.ledger().row();
    energy = std::max(energy, a.kinetic_energy + std::abs(a.strain_energy));
    d_energy = std::max({d_energy, std::abs(r.kinetic_energy - a.kinetic_energy),
                         std::abs(r.strain_energy - a.strain_energy),
                         std::abs(r.total_energy - a.total_energy)});
    d_momentum = std::max(d_momentum, (r.momentum - a.momentum).norm());
    closure = std::max(
        closure, (r.momentum - ranks.ledger().initial_momentum() - r.boundary_impulse).norm());
    closure_alone =
        std::max(closure_alone,
                 (a.momentum - alone.ledger().initial_momentum() - a.boundary_impulse).norm());
    migrated += static_cast<long>(comm.sum(std::int64_t(ranks.migrated())));
  }
  const double p_scale = std::sqrt(2.0 * mass * energy);
  BOOST_TEST_MESSAGE(scene.file << " on " << comm.size() << " ranks (boxes "
                                << ranks.boxes().describe() << "), " << alone.steps()
                                << " steps: energies within " << d_energy / energy
                                << " of E, momentum within " << d_momentum / p_scale << ", closure "
                                << closure / p_scale << " (one rank " << closure_alone / p_scale
                                << "), " << migrated << " migrations");
  // Products, not ratios: a scene at rest (the elastic bar and the compression test without the
  // velocity field their own tests prescribe) has E = 0 and must then agree exactly.
  BOOST_TEST(d_energy <= tolerance * energy);
  BOOST_TEST(d_momentum <= tolerance * p_scale);
  expect_box_grid(ranks);
  BOOST_TEST(closure <= std::max(1e-12 * p_scale, 10.0 * closure_alone));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_parallel_ranks)

BOOST_AUTO_TEST_CASE(the_recommended_sphere_cylinder_on_n_ranks_books_as_on_one) {
  compare_with_one_rank(
      scene_from("sphere_cylinder/recommended.json", {{"time", {{"max_time", 2.0e-6}}}}), 1e-9);
}

// solver.ranks_per_axis "least_loaded": each rank counts the seed points of a share of the cell
// columns, the tables of the search (mpm/parallel/split_search.hpp) are summed over the ranks,
// and every rank makes the same boxes. They must be the boxes the search makes here on one
// process from the whole seeding, and their busiest box, counted particle by particle, must hold
// fewer particles than that of the split cutting the fewest node faces (recommended grid: 2
// ranks 15 032 against 15 143, 4 ranks 7 586 against 8 263). The run then books as on one rank.
BOOST_AUTO_TEST_CASE(the_least_loaded_boxes_are_found_by_counting_and_book_as_on_one_rank) {
  const Communicator comm(&fixture->session);
  const Scene scene = scene_from(
      "sphere_cylinder/recommended.json",
      {{"time", {{"max_time", 1.0e-6}}}, {"solver", {{"ranks_per_axis", "least_loaded"}}}});
  const GridSpec& g = scene.grid;
  const Particles all = seed_particles(scene);
  AxisCounts counts;
  std::vector<CellCount> counted;
  for (std::size_t d = 0; d < 3; ++d) counts[d].assign(std::size_t(g.cells[d]), 0);
  for (const Vec3& x : all.x) {
    const std::array<int, 3> c = g.cell_of(x);
    for (std::size_t d = 0; d < 3; ++d) ++counts[d][std::size_t(c[d])];
    count_cell(counted, c);
  }
  const SplitChoice expected = least_loaded_split(g.cells, counts, comm.size(), counted,
                                                  [](const std::vector<double>& t) { return t; });
  const auto busiest = [&](const BoxDecomposition& boxes) {
    std::vector<double> held(std::size_t(comm.size()), 0.0);
    for (const Vec3& x : all.x) held[std::size_t(boxes.owner_of_cell(g.cell_of(x)))] += 1.0;
    return *std::max_element(held.begin(), held.end());
  };
  const Simulation run(scene, 1, comm);
  BOOST_TEST((run.boxes() == expected.boxes));
  const double fewest_cut = busiest(
      BoxDecomposition::balanced(counts, BoxDecomposition::ranks_per_axis(g.cells, comm.size())));
  BOOST_TEST_MESSAGE("least loaded boxes " << run.boxes().describe() << ": busiest "
                                           << busiest(run.boxes()) << " particles, against "
                                           << fewest_cut << " cutting the fewest node faces");
  BOOST_TEST(busiest(run.boxes()) == expected.busiest);
  BOOST_TEST(busiest(run.boxes()) < fewest_cut);
  compare_with_one_rank(scene, 1e-9);
}

BOOST_AUTO_TEST_CASE(case01_with_contact_erosion_and_conversion_books_as_on_one_rank) {
  compare_with_one_rank(
      scene_from("sphere_cylinder/case01.json", {{"time", {{"max_time", 1.0e-6}}}}), 1e-9);
}

// Two blocks pressed together at x = 10 mm, the middle of the grid: the balanced slabs' boundary
// falls on the contact face, so friction contact's normals (mass gradients) and compression test
// (nodal stress) at the face read the neighbour's planes.
BOOST_AUTO_TEST_CASE(friction_contact_on_a_slab_boundary_books_as_on_one_rank) {
  compare_with_one_rank(
      scene_from("verification/contact_blocks.json",
                 {{"physics", {{"contact", {{"type", "friction"}, {"mu", 0.3}}}}}}),
      1e-9);
}

// Friction against a rigid floor at the particles (rigid_contact = "particles", mu 0.25): the
// block of sliding_block_rigid.json straddles the slabs' boundary and slides along it at 200 m/s,
// so particles change rank with their stick springs' anchors (Particles::friction_anchor), and
// each rank books the slip heat of its own particles.
BOOST_AUTO_TEST_CASE(friction_at_the_particles_across_ranks_books_as_on_one_rank) {
  compare_with_one_rank(scene_from("verification/sliding_block_rigid.json",
                                   {{"physics", {{"contact", {{"rigid_contact", "particles"}}}}},
                                    {"objects", {{"block", {{"velocity", {0.0, 200.0, 0.0}}}}}}}),
                        1e-9, 150);
}

// The walls met at the particles (grid.wall_contact = "particles", wall friction 0.25, damping
// 0.3): the block of sliding_block.json slides along its x- wall at 200 m/s across the slabs'
// boundaries, so particles change rank with their anchors, and each rank books its own particles'
// pushes, slip heat and dashpots.
BOOST_AUTO_TEST_CASE(walls_at_the_particles_across_ranks_book_as_on_one_rank) {
  compare_with_one_rank(
      scene_from("verification/sliding_block.json",
                 {{"grid", {{"wall_contact", "particles"}, {"wall_penalty_damping", 0.3}}},
                  {"objects", {{"block", {{"velocity", {0.0, 200.0, 0.0}}}}}}}),
      1e-9, 150);
}

// The separating plane of contact.normal = "logistic_regression" fitted on a box boundary: the
// clouds of the nodes around it hold the neighbour ranks' particles (the ghosts of
// step/contact_planes.cpp), so each rank fits the planes one rank fits. The two blocks meet on the
// balanced slabs' boundary (x = 10 mm); split across y (and z) the boundary crosses their
// interface. The small block on the large one (block_on_block.json, 1 us) split as the run
// chooses (across y) and in boxes 1 x 1 x 2 / 2 x 2 x 1; the Hertz spheres (axisymmetric) split
// along x at their contact, with the gap along the planes (`detection: separation`) compared
// too. The blocks and the spheres for their first 30 steps: every step fits
// every plane anew, so a plane that differs shows at once (the fits cost 8.8 s of this test's
// 33 s on 2 ranks with 99 steps each, 19 s of 69 s on 4). Without the ghosts the nodes within two
// layers of a boundary fell back to the mass gradients: contact_blocks then booked as with the
// gradients, -0.4686 % against -0.4562 % (1e-4 of E0). After one step, every plane a rank fitted
// equals the one-rank run's at the same node, bit for bit, and every node its particles weigh on,
// [c0 - 1, c1 + 1], that has a plane alone has one here.
void expect_the_planes_of_one_rank(const Scene& scene) {
  const Communicator comm(&fixture->session);
  Simulation ranks(scene, 1, comm), alone(scene, 1);
  ranks.step();
  alone.step();
  const Grid& G = ranks.grid();
  const std::array<int, 3> c0 = ranks.boxes().first_cell(ranks.rank()),
                           c1 = ranks.boxes().end_cell(ranks.rank());
  const int axes = scene.grid.planar() ? 2 : 3;
  const bool gaps = scene.physics.contact.detection == ContactDetection::separation;
  BOOST_REQUIRE(G.contact_gap.empty() != gaps);
  long fitted = 0, differ = 0, missing = 0;
  for (const int I : G.active_nodes()) {
    const std::array<int, 3> n = G.ijk(I);
    const Vec3& mine = G.contact_plane[I];
    const Vec3& one = alone.grid().contact_plane[alone.grid().index(n[0], n[1], n[2])];
    bool inside = true;
    for (int d = 0; d < axes; ++d) inside = inside && n[d] >= c0[d] - 1 && n[d] <= c1[d] + 1;
    if (mine != Vec3::Zero()) {
      ++fitted;
      if (mine != one) ++differ;
      // `detection: separation`: the gap along it too (the ghosts carry their F and half-widths)
      if (gaps &&
          G.contact_gap[I] != alone.grid().contact_gap[alone.grid().index(n[0], n[1], n[2])])
        ++differ;
    } else if (inside && one != Vec3::Zero()) {
      ++missing;
    }
  }
  const long all = comm.sum(std::int64_t(fitted));
  BOOST_TEST_MESSAGE(scene.file << ": " << all << " planes fitted on " << comm.size()
                                << " ranks after one step");
  BOOST_TEST(all > 0);
  BOOST_TEST(comm.sum(std::int64_t(differ)) == 0);
  BOOST_TEST(comm.sum(std::int64_t(missing)) == 0);
}

BOOST_AUTO_TEST_CASE(the_logistic_regression_normal_on_box_boundaries_books_as_on_one_rank) {
  const Communicator comm(&fixture->session);
  const Json lr = {{"normal", "logistic_regression"}};
  const Scene blocks = scene_from(
      "verification/contact_blocks.json",
      {{"physics", {{"contact", {{"type", "approach"}, {"normal", "logistic_regression"}}}}}});
  expect_the_planes_of_one_rank(blocks);
  compare_with_one_rank(blocks, 1e-9, 30);
  const std::array<int, 3> boxes =
      comm.size() == 2 ? std::array<int, 3>{1, 1, 2} : std::array<int, 3>{2, 2, 1};
  for (const Json& ranks_per_axis : {Json::array({0, 0, 0}), Json(boxes)}) {
    BOOST_TEST_CONTEXT("block_on_block, ranks_per_axis " << ranks_per_axis.dump()) {
      compare_with_one_rank(scene_from("verification/block_on_block.json",
                                       {{"physics", {{"contact", lr}}},
                                        {"time", {{"max_time", 1.0e-6}}},
                                        {"solver", {{"ranks_per_axis", ranks_per_axis}}}}),
                            1e-9);
    }
  }
  // The spheres with the bodies' gap measured along the planes (contact.detection).
  const Json separation = {{"normal", "logistic_regression"}, {"detection", "separation"}};
  const Scene spheres =
      scene_from("verification/hertz_spheres.json",
                 {{"physics", {{"contact", separation}}}, {"time", {{"max_time", 2.0e-6}}}});
  BOOST_REQUIRE(spheres.physics.contact.detection == ContactDetection::separation);
  expect_the_planes_of_one_rank(spheres);
  compare_with_one_rank(spheres, 1e-9, 30);
}

// 40 cells of 5 mm along x; the block (cells 2-9) flies 20 cells in 100 us. `rebalance_above`:
// solver.rebalance_above.
Scene flying_block(double rebalance_above, const Json& ranks_per_axis = {0, 0, 0}) {
  return scene_from(
      "verification/rigid_translation.json",
      {{"objects",
        {{"block",
          {{"geometry", {{"lower", {0.01, 0.01, 0.01}}, {"upper", {0.05, 0.03, 0.03}}}},
           {"velocity", {1000.0, 0.0, 0.0}}}}}},
       {"grid", {{"upper", {0.2, 0.04, 0.04}}, {"cells", {40, 8, 8}}}},
       {"solver", {{"rebalance_above", rebalance_above}, {"ranks_per_axis", ranks_per_axis}}},
       {"time", {{"max_time", 1.0e-4}}}});
}

// The slabs follow the block: re-balanced whenever a rank holds more than 1.2 times the mean, so
// at the end the block is split over the ranks again; positions stay exact. Also with
// "least_loaded", whose re-balancing refines the boundaries (split_search.hpp; on 4 ranks it
// splits 2 x 2 x 1).
BOOST_AUTO_TEST_CASE(the_slabs_are_rebalanced_as_the_block_moves) {
  const Communicator comm(&fixture->session);
  for (const Json& rule : {Json::array({0, 0, 0}), Json("least_loaded")}) {
    const Scene scene = flying_block(1.2, rule);
    Simulation ranks(scene, 1, comm), alone(scene, 1);
    const BoxDecomposition first = ranks.boxes();
    while (!alone.finished()) {
      alone.step();
      ranks.step();
    }
    const std::vector<double> held = comm.gather_all(double(ranks.particles().size()));
    const double n = double(alone.particles().size());
    double largest = 0.0;
    for (double h : held) largest = std::max(largest, h);
    BOOST_TEST_MESSAGE(rule << ": rebalanced " << ranks.rebalances() << " times: boxes "
                            << first.describe() << " -> " << ranks.boxes().describe());
    BOOST_TEST(ranks.rebalances() > 0);
    BOOST_TEST(!(ranks.boxes() == first));
    expect_box_grid(ranks);  // the grid followed the boxes
    // As balanced as slabs of whole cell columns, at least kMinCells wide, allow: each column of
    // the block holds n / 8 particles.
    BOOST_TEST(largest <= std::max(1.2 * n / comm.size(), n / 8.0 * SlabDecomposition::kMinCells));
    double worst_x = 0.0;
    const Particles& P = ranks.particles();
    for (std::size_t p = 0; p < P.size(); ++p)
      worst_x = std::max(worst_x, (P.x[p] - alone.particles().x[P.id[p]]).cwiseAbs().maxCoeff());
    BOOST_TEST(comm.max(worst_x) < 1e-12);
    BOOST_TEST(comm.sum(std::int64_t(P.size())) == std::int64_t(n));
  }
}

// Graded grids (grid.refine, issue 56): the boxes are cut along the graded cells, the halo and
// the migration carry each particle's uGIMP half-width (Particles::half_width), the USL light-node
// threshold's mass moment is summed at the shared nodes, and the contact normals difference the
// nodal density over unequal cells across the box boundaries. The Taylor rod with its impact end
// refined, the two contact blocks meeting inside a refined box, and the rigid block crossing
// the grading (factor 2, linear/USL: the light-node rule at work; to the end of its run, so it
// migrates across the boxes), the others for their first 60 steps (the separating plane, whose
// fits on the refined interface cost 16 s of 60 steps on 2 ranks, for 20), book as on one rank
// to 1e-9.
namespace {
// The merge patch that refines the box [lower, upper] twice, the cells growing back by `growth`.
Json refined_twice(const Json& lower, const Json& upper, double growth) {
  return {{"grid",
           {{"refine", {{"lower", lower}, {"upper", upper}, {"factor", 2}, {"growth", growth}}}}}};
}
}  // namespace

BOOST_AUTO_TEST_CASE(graded_grids_book_as_on_one_rank) {
  const Json rod = refined_twice({0.0, 0.0, 0.0}, {0.0041, 0.0052, 0.0052}, 1.3);
  const Json blocks = refined_twice({0.008, 0.0, 0.0}, {0.012, 0.012, 0.008}, 1.3);
  // The separating plane too: its ghosts carry their own half-widths (step/contact_planes.cpp).
  Json plane = blocks;
  plane["physics"]["contact"] = {{"type", "friction"}, {"normal", "logistic_regression"}};
  Json block = refined_twice({0.037, 0.033, 0.033}, {0.043, 0.039, 0.039}, 1.5);
  block["solver"] = {{"interpolation", "linear"}, {"scheme", "usl"}};
  struct Case {
    const char* name;
    Json patch;
    long steps;
  };
  for (const auto& [name, patch, steps] :
       std::vector<Case>{{"taylor_rod.json", rod, 60},
                         {"contact_blocks.json", blocks, 60},
                         {"contact_blocks.json", plane, 20},
                         // To the end of its run: it crosses the boxes and the grading.
                         {"rigid_translation.json", block, 1L << 40}}) {
    const Scene scene = scene_from(std::string("verification/") + name, patch);
    BOOST_TEST_REQUIRE(scene.grid.graded());
    BOOST_TEST_CONTEXT(name) {
      compare_with_one_rank(scene, 1e-9, steps);
    }
  }
}

// Every verification scene (each splits into boxes of at least 3 cells per split axis on 2 and 4
// ranks: BoxDecomposition::ranks_per_axis; on 4 ranks the rigid translation, the sliding block
// and the 13 x 7 x 7 Taylor rod are split across y and z), for its first 60 steps, as the scene
// file has it (the elastic bar and the compression test start at rest without their tests' velocity
// fields: they must stay equal, here at zero).
BOOST_AUTO_TEST_CASE(every_verification_scene_books_as_on_one_rank) {
  const Communicator comm(&fixture->session);
  int compared = 0;
  // rigid_piston and spanning_block_rigid: rigid objects (their reaction booked at owned nodes).
  // Not sliding_block_rigid: its resting contact under gravity agrees to about 1e-5 only, a
  // contact decision flipping on round-off (docs/mpi.md#limits).
  for (const char* name : {"contact_blocks.json", "elastic_bar.json", "elastic_wave.json",
                           "flyer_plate.json", "rigid_piston.json", "rigid_translation.json",
                           "sliding_block.json", "spanning_block_rigid.json", "taylor_rod.json",
                           "two_spheres.json", "uniaxial_compression.json"}) {
    const Scene scene = scene_from(std::string("verification/") + name, Json::object());
    try {
      BoxDecomposition::ranks_per_axis(scene.grid.cells, comm.size());
    } catch (const std::invalid_argument& refused) {
      BOOST_TEST_MESSAGE(name << ": " << refused.what());
      continue;
    }
    BOOST_TEST_CONTEXT(name) {
      compare_with_one_rank(scene, 1e-9, 60);
    }
    ++compared;
  }
  BOOST_TEST(compared == 11);
}

// Boxes split across y and z as well as x (solver.ranks_per_axis): the nodes along the boxes'
// edges are shared by four ranks, summed one axis after another. Case 1 on 2 ranks split in y
// and in z, on 4 ranks 2 x 2 in x-y and in y-z: friction contact (the mass gradients read the
// copied layers beyond the shared ones, also at the edges), erosion and conversion, symmetric
// faces on the y = 0 and z = 0 boxes only.
BOOST_AUTO_TEST_CASE(case01_split_in_boxes_across_every_axis_books_as_on_one_rank) {
  const Communicator comm(&fixture->session);
  const std::vector<std::array<int, 3>> splits =
      comm.size() == 2 ? std::vector<std::array<int, 3>>{{1, 2, 1}, {1, 1, 2}}
                       : std::vector<std::array<int, 3>>{{2, 2, 1}, {1, 2, 2}};
  for (const std::array<int, 3>& p : splits) {
    BOOST_TEST_CONTEXT("ranks_per_axis " << p[0] << " " << p[1] << " " << p[2]) {
      compare_with_one_rank(scene_from("sphere_cylinder/case01.json",
                                       {{"time", {{"max_time", 1.0e-6}}},
                                        {"solver", {{"ranks_per_axis", {p[0], p[1], p[2]}}}}}),
                            1e-9);
    }
  }
}

// A rigid block flying diagonally (+x and +y) through fixed boxes, 1 x 2 on 2 ranks and 2 x 2 on
// 4 (one box's corner crossed): it starts across the boundaries (balanced by particle count)
// and ends inside the last box; count, mass, positions and motion are unchanged.
BOOST_AUTO_TEST_CASE(a_block_crossing_box_boundaries_diagonally_keeps_its_particles_and_motion) {
  const Communicator comm(&fixture->session);
  const int p = comm.size() == 2 ? 1 : 2;
  const Scene scene =
      scene_from("verification/rigid_translation.json",
                 {{"objects",
                   {{"block",
                     {{"geometry", {{"lower", {0.01, 0.01, 0.01}}, {"upper", {0.04, 0.04, 0.03}}}},
                      {"velocity", {500.0, 500.0, 0.0}}}}}},
                  {"grid", {{"upper", {0.12, 0.12, 0.04}}, {"cells", {24, 24, 8}}}},
                  {"solver", {{"rebalance_above", 1e300}, {"ranks_per_axis", {p, 2, 1}}}},
                  {"time", {{"max_time", 1.0e-4}}}});
  Simulation ranks(scene, 1, comm), alone(scene, 1);
  const std::size_t n = alone.particles().size();
  const std::vector<double> held_before = comm.gather_all(double(ranks.particles().size()));
  const long migrated = step_both_to_the_end(ranks, alone, comm);
  const Particles& P = ranks.particles();
  double m = 0.0, mass = 0.0, worst_x = 0.0;
  for (double mp : alone.particles().mass) mass += mp;
  for (std::size_t q = 0; q < P.size(); ++q) {
    m += P.mass[q];
    worst_x = std::max(worst_x, (P.x[q] - alone.particles().x[P.id[q]]).cwiseAbs().maxCoeff());
  }
  BOOST_TEST_MESSAGE("diagonal block: " << n << " particles, boxes " << ranks.boxes().describe()
                                        << ", " << migrated << " migrations");
  BOOST_TEST(comm.sum(std::int64_t(P.size())) == std::int64_t(n));
  BOOST_TEST(std::abs(comm.sum(m) - mass) <= 1e-13 * mass);
  BOOST_TEST(comm.max(worst_x) < 1e-12);
  const LedgerRow a = alone.ledger().row(), r = ranks.ledger().row();
  BOOST_TEST(std::abs(r.kinetic_energy - a.kinetic_energy) <= 1e-12 * a.kinetic_energy);
  BOOST_TEST((r.momentum - a.momentum).norm() <= 1e-12 * a.momentum.norm());
  expect_box_grid(ranks);
  const std::vector<double> held_after = comm.gather_all(double(P.size()));
  const int last = comm.size() - 1;
  for (int q = 0; q < comm.size(); ++q) {
    BOOST_TEST_INFO("rank " << q);
    BOOST_TEST(held_before[std::size_t(q)] > 0.0);  // the block starts across every boundary
    BOOST_TEST(held_after[std::size_t(q)] == (q == last ? double(n) : 0.0));
  }
}

BOOST_AUTO_TEST_CASE(a_block_crossing_every_slab_boundary_keeps_its_particles_and_motion) {
  const Communicator comm(&fixture->session);
  const Scene scene = flying_block(1e300);  // the first slabs kept: the block crosses them all
  Simulation ranks(scene, 1, comm), alone(scene, 1);
  const std::size_t n = alone.particles().size();
  const double mass = [&] {
    double m = 0.0;
    for (double mp : alone.particles().mass) m += mp;
    return m;
  }();
  // The block starts in cells 2-9, so some of it lies in the first slab (the slabs are balanced
  // by particle count), and ends in cells 22-29, inside the last: it crossed every boundary.
  const std::vector<double> held_before = comm.gather_all(double(ranks.particles().size()));
  const long migrated = step_both_to_the_end(ranks, alone, comm);
  const std::vector<double> held_after = comm.gather_all(double(ranks.particles().size()));
  const Particles& P = ranks.particles();
  BOOST_TEST(comm.sum(std::int64_t(P.size())) == std::int64_t(n));
  double m = 0.0, worst_x = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    m += P.mass[p];
    worst_x = std::max(worst_x, (P.x[p] - alone.particles().x[P.id[p]]).cwiseAbs().maxCoeff());
  }
  BOOST_TEST(std::abs(comm.sum(m) - mass) <= 1e-13 * mass);  // sums in another order
  BOOST_TEST(comm.max(worst_x) < 1e-12);
  const LedgerRow a = alone.ledger().row(), r = ranks.ledger().row();
  BOOST_TEST(std::abs(r.kinetic_energy - a.kinetic_energy) <= 1e-12 * a.kinetic_energy);
  BOOST_TEST((r.momentum - a.momentum).norm() <= 1e-12 * a.momentum.norm());
  BOOST_TEST_MESSAGE("block: " << n << " particles, boxes " << ranks.boxes().describe() << ", "
                               << migrated << " migrations, position error " << worst_x << " m");
  BOOST_TEST_REQUIRE(ranks.boxes().ranks_per_axis()[0] == comm.size());  // slabs along x
  BOOST_TEST_REQUIRE(ranks.boxes().axis(0).first_cell(comm.size() - 1) <= 22);
  const int last = comm.size() - 1;
  BOOST_TEST(held_before[0] > 0.0);
  for (int q = 0; q < comm.size(); ++q) {
    BOOST_TEST_INFO("rank " << q);
    BOOST_TEST(held_after[std::size_t(q)] == (q == last ? double(n) : 0.0));
  }
  BOOST_TEST(migrated >= long(n - std::size_t(held_before[std::size_t(last)])));
}

BOOST_AUTO_TEST_CASE(the_same_rank_count_gives_the_same_bits_run_to_run) {
  const Communicator comm(&fixture->session);
  const Scene scene =
      scene_from("sphere_cylinder/recommended.json", {{"time", {{"max_time", 1.0e-6}}}});
  Simulation first(scene, 1, comm), second(scene, 1, comm);
  while (!first.finished()) {
    first.step();
    second.step();
    const LedgerRow a = first.ledger().row(), b = second.ledger().row();
    BOOST_TEST_REQUIRE(a.total_energy == b.total_energy);
    BOOST_TEST_REQUIRE(a.momentum == b.momentum);
  }
  BOOST_TEST(first.particles().x == second.particles().x);
}

BOOST_AUTO_TEST_SUITE_END()
