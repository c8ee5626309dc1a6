// The manufactured solutions (data/scenes/verification/mms_<field>.json, written by
// campaigns/verification/manufactured_solutions.py; Wallstedt & Guilkey 2008, J. Comput. Phys.
// 227:9628, sec. 4) on the compressible neo-Hookean solid, uGIMP + MUSL: the displacement error
// against the exact u(X, t) at the displacement's peak (t = L / 2c), mass-weighted rms over the
// particles, on two grids per geometry. In the small-strain limit (A = 1e-3 L) the method's
// asymptotic order shows: the paper's analysis expects 2 (second-order shapes' interpolation,
// the symplectic Euler step second order in the positions); asserted at least 1.5 on the pair.
// At the scenes' own amplitude (A = 0.05 L, |Grad u| up to 0.31, J from 0.33 to 2.2) the order is
// lost (docs/verification.md#manufactured-solutions: uGIMP's particle domain keeps its size while
// the material around it stretches and compresses by 2); here that run is only asserted to stay
// within a few percent of A, as the table measured.
//
// Measured (this test, --log_level=message): plane strain 16 -> 32 cells, order 2.22; axisymmetric
// 2.18; 3D 8 -> 16, 2.06. The table's finer pairs (campaigns/verification/mms_convergence.py) keep
// it: 2.21 (64 -> 128), 2.25 (64 -> 128) and 2.22 (16 -> 32). Coarse levels keep the test fast.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "../verification_helpers.hpp"
#include "mpm/output/displacement_error.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// {rms, max} displacement error [m] at the end of the scene with `cells` per axis.
// With `refine`, grid.refine is that box (a graded grid, issue 56).
std::vector<double> final_error(const std::string& file, int cells, double amplitude,
                                const Json& refine = Json()) {
  const bool three_d = file == "mms_axis_aligned.json";
  Json cells_json = three_d ? Json{cells, cells, cells} : Json{cells, cells};
  Json patch = {{"grid", {{"cells", cells_json}}}, {"constants", {{"A", amplitude}}}};
  if (!refine.is_null()) patch["grid"]["refine"] = refine;
  const Scene scene = test::verification_scene(file, patch);
  Simulation sim(scene);
  while (!sim.finished()) sim.step();
  DisplacementError error(scene, Communicator::one_rank());
  return error.read(sim.particles(), sim.time());
}

struct Ladder {
  std::string file;
  int coarse = 0, fine = 0;
};

}  // namespace

BOOST_AUTO_TEST_SUITE(manufactured_solution)

BOOST_AUTO_TEST_CASE(each_geometry_reaches_second_order_in_the_small_strain_limit) {
  const double L = 1.0, A = 1e-3 * L;
  for (const Ladder& l :
       {Ladder{"mms_plane_strain.json", 16, 32}, Ladder{"mms_axisymmetric.json", 16, 32},
        Ladder{"mms_axis_aligned.json", 8, 16}}) {
    const std::vector<double> coarse = final_error(l.file, l.coarse, A);
    const std::vector<double> fine = final_error(l.file, l.fine, A);
    const double order = std::log(coarse[0] / fine[0]) / std::log(double(l.fine) / l.coarse);
    BOOST_TEST_MESSAGE(l.file << ": rms error " << coarse[0] << " m at " << l.coarse << " cells, "
                              << fine[0] << " m at " << l.fine << " (max " << coarse[1] << ", "
                              << fine[1] << "), order " << order);
    BOOST_TEST_INFO(l.file);
    BOOST_TEST(order >= 1.5);
    BOOST_TEST(fine[0] < 0.02 * A);  // and small: 1.2 % of the amplitude in 3D at 16 cells
  }
}

// On a graded grid (grid.refine, issue 56): the middle of the square refined twice, on base grids
// of 16 and 32 cells (fine cells 1/32 and 1/64 of L), growth 2 (the box's cells meet the base
// cells directly), so the pair is a similar refinement. The order is the uniform grid's (2.20
// against 2.22; asserted at least 1.5 as there), and the error lies between the uniform grid's at
// the base cells and at the box's. (With growth 1.2 the growing cells are fitted to the base nodes
// differently on the two grids, 5 cells over 4 base cells and 4 over 8: not a similar pair, and
// the order measured 1.57.)
BOOST_AUTO_TEST_CASE(a_graded_grid_keeps_the_order_in_the_small_strain_limit) {
  const double A = 1e-3;
  const Json box = {
      {"lower", {0.25, 0.25}}, {"upper", {0.75, 0.75}}, {"factor", 2}, {"growth", 2.0}};
  const std::vector<double> coarse = final_error("mms_plane_strain.json", 16, A, box);
  const std::vector<double> fine = final_error("mms_plane_strain.json", 32, A, box);
  const double order = std::log(coarse[0] / fine[0]) / std::log(2.0);
  const double uniform_base = final_error("mms_plane_strain.json", 32, A)[0];
  const double uniform_fine = final_error("mms_plane_strain.json", 64, A)[0];
  BOOST_TEST_MESSAGE("plane strain, graded: rms error "
                     << coarse[0] << " m on base 16, " << fine[0] << " m on base 32, order "
                     << order << "; uniform 32 / 64 cells: " << uniform_base << " / "
                     << uniform_fine << " m");
  BOOST_TEST(order >= 1.5);
  BOOST_TEST(fine[0] < uniform_base);
  BOOST_TEST(fine[0] > uniform_fine);
}

BOOST_AUTO_TEST_CASE(at_large_deformation_the_shipped_scene_stays_within_a_few_percent) {
  // The scene as shipped (A = 0.05 m): the table's 16- and 32-cell rows.
  double rms_32 = 0.0;
  for (const int cells : {16, 32}) {
    const std::vector<double> e = final_error("mms_plane_strain.json", cells, 0.05);
    BOOST_TEST_MESSAGE("plane strain, A = 0.05 m, " << cells << " cells: rms " << e[0] << " m, max "
                                                    << e[1] << " m");
    BOOST_TEST(e[0] < 0.04 * 0.05);
    BOOST_TEST(e[1] < 0.1 * 0.05);
    rms_32 = e[0];
  }
  // The negative control: the hypoelastic model with the same mu, K and rho0 (6061-T6's file made
  // elastic) under the same body force misses the field by far more at 31 % strain. Measured:
  // rms 1.46e-2 m against 5.7e-4 m.
  const Json hypoelastic = {
      {"materials",
       {{"soft",
         {{"file", std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json"},
          {"overrides",
           {{"density", 1000.0},
            {"shear_modulus", 1e7 / 2.6},
            {"bulk_modulus", 1e7 / 1.2},
            {"constitutive_model",
             {{"flow_stress", {{"A", 1e15}}},
              {"damage", {{"type", "none"}}},
              {"adiabatic_heating", {{"enabled", false}}},
              {"erosion", {{"algorithm", "none"}}}}}}}}}}},
      {"grid", {{"cells", {32, 32}}}}};
  const Scene scene = test::verification_scene("mms_plane_strain.json", hypoelastic);
  Simulation sim(scene);
  while (!sim.finished()) sim.step();
  const double rms_hypo =
      DisplacementError(scene, Communicator::one_rank()).read(sim.particles(), sim.time())[0];
  BOOST_TEST_MESSAGE("the same with the hypoelastic model: rms " << rms_hypo << " m");
  BOOST_TEST(rms_hypo > 10.0 * rms_32);
}

BOOST_AUTO_TEST_SUITE_END()
