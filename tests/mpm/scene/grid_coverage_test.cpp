// Objects and the grid (mpm/scene/grid_coverage.hpp, the check in scene.cpp): the fraction of a
// body inside the grid against closed forms (a box cut by a face, a sphere cut into a spherical
// cap), the mirror images of symmetric faces, and the scene's answers: a body wholly outside, a
// body typed in mm on a grid in m and a body too small for a seed point are refused naming their
// key path; a clipped body is read with a warning giving the fraction; a quarter model (clipped
// by two symmetric faces) and every shipped scene are read without one.
#include "mpm/scene/grid_coverage.hpp"

#include <boost/test/unit_test.hpp>
#include <filesystem>

#include "helpers/scene_error.hpp"
#include "mpm/particles/particles.hpp"

using namespace impact;
using namespace impact::mpm;
namespace tt = boost::test_tools;

namespace {

const std::string kScenes = std::string(IMPACT_SOURCE_DIR) + "/data/scenes/";

// rigid_translation.json: a grid [0, 0.06]^3 m of 12^3 cells, every face free, one block
// [0.02, 0.04]^3 m with 2 x 2 x 2 particles per cell.
Json base() {
  return load_scene_document(kScenes + "verification/rigid_translation.json");
}

using impact::testing::scene_error_of;

GridSpec grid_of(const char* face_condition) {
  Json doc = base();
  for (const char* f : kFaceNames) doc["grid"]["boundary"][f] = face_condition;
  return read_scene(doc, "test.json").grid;
}

// The fraction of a sphere of radius r beyond a plane at distance d < r from its centre: the
// cap of height h = r - d, pi h^2 (3 r - h) / 3, over 4/3 pi r^3.
double cap_fraction(double r, double d) {
  const double h = r - d;
  return h * h * (3.0 * r - h) / (4.0 * r * r * r);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_grid_coverage)

BOOST_AUTO_TEST_CASE(a_body_inside_the_grid_is_wholly_covered_exactly) {
  const GridCoverage c =
      grid_coverage(Geometry{Box{Vec3(0.02, 0.02, 0.02), Vec3(0.04, 0.04, 0.06)}}, grid_of("free"));
  BOOST_TEST(c.inside_bound == 1.0);
  BOOST_TEST(!c.sampled);  // the box touches z+: inside, nothing to sample
  BOOST_TEST(c.inside == 1.0);
  BOOST_TEST(c.lost == 0.0);
}

// A box 0.02 m wide from x = 0.045 crosses x+ = 0.06: 0.015 / 0.02 = 0.75 inside; the lattice's
// planes fall on 0.75 exactly (36 of 48).
BOOST_AUTO_TEST_CASE(a_box_cut_by_a_free_face_is_three_quarters_inside) {
  const Geometry box{Box{Vec3(0.045, 0.02, 0.02), Vec3(0.065, 0.04, 0.04)}};
  const GridCoverage c = grid_coverage(box, grid_of("free"));
  BOOST_TEST(c.inside_bound == 0.75, tt::tolerance(1e-12));
  BOOST_TEST(c.sampled);
  BOOST_TEST(c.inside == 0.75, tt::tolerance(1e-12));
  BOOST_TEST(c.lost == 0.25, tt::tolerance(1e-12));
  BOOST_TEST((c.lost_through == std::array<bool, 6>{false, true, false, false, false, false}));
}

// A sphere of radius 0.01 m centred 0.005 m inside x+ (the cap beyond: 0.15625 of it), then on
// the face (half). The lattice of 48^3 points measured 0.844165 inside (exact 0.84375: 4.9e-4
// relative) and 0.155835 beyond (2.7e-3 relative); the tolerances are 2e-3 and 1e-2.
BOOST_AUTO_TEST_CASE(a_sphere_cut_by_a_face_matches_the_spherical_cap) {
  const double r = 0.01;
  for (const double d : {0.5 * r, 0.0}) {
    const Geometry sphere{Sphere{Vec3(0.06 - d, 0.03, 0.03), r}};
    const double beyond = cap_fraction(r, d);
    const GridCoverage free_face = grid_coverage(sphere, grid_of("free"));
    BOOST_TEST_MESSAGE("d = " << d << " m: inside " << free_face.inside << " (exact "
                              << 1.0 - beyond << "), lost " << free_face.lost);
    BOOST_TEST(free_face.inside == 1.0 - beyond, tt::tolerance(2e-3));
    BOOST_TEST(free_face.lost == beyond, tt::tolerance(1e-2));
    // A symmetric face models the cap beyond by the mirror image of the part inside.
    const GridCoverage mirror = grid_coverage(sphere, grid_of("symmetric"));
    BOOST_TEST(mirror.inside == free_face.inside);
    BOOST_TEST(mirror.lost == 0.0);
  }
}

// The sphere of a quarter model: centred on the edge of the symmetric faces y- and z-, a quarter
// inside. With those faces free three quarters are lost through y- and z-.
BOOST_AUTO_TEST_CASE(a_quarter_model_loses_nothing_through_symmetric_faces) {
  const Geometry sphere{Sphere{Vec3(0.03, 0.0, 0.0), 0.01}};
  const GridCoverage quarter = grid_coverage(sphere, grid_of("symmetric"));
  BOOST_TEST(quarter.inside == 0.25, tt::tolerance(1e-12));  // the lattice is symmetric too
  BOOST_TEST(quarter.lost == 0.0);
  const GridCoverage free_faces = grid_coverage(sphere, grid_of("free"));
  BOOST_TEST(free_faces.lost == 0.75, tt::tolerance(1e-12));
  BOOST_TEST(
      (free_faces.lost_through == std::array<bool, 6>{false, false, true, false, true, false}));
}

BOOST_AUTO_TEST_CASE(a_body_wholly_outside_the_grid_is_refused_with_its_key_path) {
  Json doc = base();
  doc["objects"]["block"]["geometry"] = {
      {"type", "box"}, {"lower", {0.1, 0.1, 0.1}}, {"upper", {0.12, 0.12, 0.12}}};
  std::string e = scene_error_of(doc);
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("test.json: /objects/block/geometry: lies wholly outside the grid [0, 0, 0] "
                    "to [0.06, 0.06, 0.06] m (its bounding box [0.1, 0.1, 0.1] to [0.12, 0.12, "
                    "0.12] m): no particle would be seeded") != std::string::npos);
  // Its bounding box holds 6.4e-3 of its volume in the grid's corner; the sphere, 0.0121 m from
  // the corner, has nothing there (the lattice finds no point).
  doc["objects"]["block"]["geometry"] = {
      {"type", "sphere"}, {"center", {-0.007, -0.007, -0.007}}, {"radius", 0.01}};
  e = scene_error_of(doc);
  BOOST_TEST(e.find("/objects/block/geometry: lies wholly outside the grid") != std::string::npos);
}

// A 40 mm cube typed in mm on the 0.06 m grid: at most 0.06^3 / 40^3 = 3.375e-9 of it inside.
BOOST_AUTO_TEST_CASE(a_body_typed_in_millimetres_on_a_grid_in_metres_is_refused) {
  Json doc = base();
  doc["objects"]["block"]["geometry"] = {
      {"type", "box"}, {"lower", {0.0, 0.0, 0.0}}, {"upper", {40.0, 40.0, 40.0}}};
  const Scene valid = read_scene(base(), "test.json");
  const GridCoverage c =
      grid_coverage(Geometry{Box{Vec3::Zero(), Vec3::Constant(40.0)}}, valid.grid);
  BOOST_TEST(c.inside_bound == 3.375e-9, tt::tolerance(1e-12));
  const std::string e = scene_error_of(doc);
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("test.json: /objects/block/geometry: at most 3.38e-09 of its volume (6.4e+04 "
                    "m^3) lies inside the grid [0, 0, 0] to [0.06, "
                    "0.06, 0.06] m") != std::string::npos);
  BOOST_TEST(e.find("expected at least 0.001 (lengths in m; its largest extent 40 looks like mm "
                    "(40 mm = 0.04 m)") != std::string::npos);
}

// Seed points of the block's cells sit at 1.25 mm + k 2.5 mm: a 0.1 mm cube between them gets
// none; a body inside an earlier one (objects in name order) gets none either.
BOOST_AUTO_TEST_CASE(a_body_that_would_get_no_particle_is_refused) {
  Json doc = base();
  doc["objects"]["block"]["geometry"] = {
      {"type", "box"}, {"lower", {0.0201, 0.0201, 0.0201}}, {"upper", {0.0202, 0.0202, 0.0202}}};
  std::string e = scene_error_of(doc);
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("test.json: /objects/block/geometry: no particle would be seeded: none of the "
                    "seed points (sub-cell centres, spacing [0.0025, 0.0025, 0.0025] m)") !=
             std::string::npos);
  doc = base();
  doc["objects"]["inner"] = doc["objects"]["block"];
  doc["objects"]["inner"]["geometry"] = {
      {"type", "box"}, {"lower", {0.025, 0.025, 0.025}}, {"upper", {0.03, 0.03, 0.03}}};
  e = scene_error_of(doc);
  BOOST_TEST(e.find("/objects/inner/geometry: no particle would be seeded") != std::string::npos);
  BOOST_TEST(e.find("/objects/block/") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_clipped_body_is_read_with_a_warning_giving_the_fraction) {
  Json doc = base();
  doc["objects"]["block"]["geometry"]["lower"] = {0.045, 0.02, 0.02};
  doc["objects"]["block"]["geometry"]["upper"] = {0.065, 0.04, 0.04};
  const Scene s = read_scene(doc, "test.json");
  BOOST_TEST_REQUIRE(s.warnings.size() == 1u);
  BOOST_TEST_MESSAGE(s.warnings[0]);
  BOOST_TEST(s.warnings[0].find("test.json: /objects/block/geometry: clipped by the grid: about "
                                "0.75 of its volume lies inside the grid [0, 0, 0] to [0.06, "
                                "0.06, 0.06] m; 0.25 lies beyond the face(s) x+ and is not "
                                "seeded") == 0u);
  // What is seeded: the three of the block's four cell layers along x inside the grid.
  const Particles p = seed_particles(s);
  BOOST_TEST(p.size() == 3u * 4u * 4u * 8u);
  // Touching the face (upper x = 0.06) is no clipping.
  doc["objects"]["block"]["geometry"]["lower"] = {0.04, 0.02, 0.02};
  doc["objects"]["block"]["geometry"]["upper"] = {0.06, 0.04, 0.04};
  BOOST_TEST(read_scene(doc, "test.json").warnings.empty());
}

BOOST_AUTO_TEST_CASE(a_quarter_model_is_read_without_a_warning) {
  Json doc = base();
  doc["objects"]["block"]["geometry"] = {
      {"type", "sphere"}, {"center", {0.03, 0.0, 0.0}}, {"radius", 0.01}};
  doc["grid"]["boundary"]["y-"] = "symmetric";
  doc["grid"]["boundary"]["z-"] = "symmetric";
  BOOST_TEST(read_scene(doc, "test.json").warnings.empty());
  doc["grid"]["boundary"]["z-"] = "free";  // half of the quarter's mirror image is missing
  const Scene s = read_scene(doc, "test.json");
  BOOST_TEST_REQUIRE(s.warnings.size() == 1u);
  BOOST_TEST(s.warnings[0].find("0.5 lies beyond the face(s) y-, z-") != std::string::npos);
}

// On an axisymmetric grid a body is its revolved self: a sphere on the axis, cut by the face x+
// at r/2 from its centre (on a boundary of the lattice's layers), is the cap fraction beyond that
// face and the rest inside, however the lattice's points lie about the axis (a new user's trial,
// issue 54: the half below the axis was reported outside, "0.422 inside", and y-, the axis, among
// the faces it crossed).
BOOST_AUTO_TEST_CASE(an_axisymmetric_body_is_measured_revolved) {
  Json doc = base();
  doc["grid"] = {{"geometry", "axisymmetric"},
                 {"lower", {0.0, 0.0}},
                 {"upper", {0.06, 0.03}},
                 {"cells", {12, 6}},
                 {"boundary", {{"x-", "free"}, {"x+", "free"}, {"y+", "free"}}}};
  doc["objects"]["block"]["geometry"] = {
      {"type", "sphere"}, {"center", {0.055, 0.0, 0.0}}, {"radius", 0.01}};
  doc["objects"]["block"]["particles_per_cell"] = {2, 2};
  doc["objects"]["block"]["velocity"] = {30.0, 0.0, 0.0};
  const Scene s = read_scene(doc, "test.json");
  const GridCoverage c = grid_coverage(s.objects[0].geometry, s.grid);
  const double beyond = cap_fraction(0.01, 0.005);  // 0.15625
  BOOST_TEST(c.sampled);
  BOOST_TEST(c.lost == beyond, tt::tolerance(0.01));
  BOOST_TEST(c.inside == 1.0 - beyond, tt::tolerance(0.01));
  for (std::size_t f = 0; f < 6; ++f) BOOST_TEST(c.lost_through[f] == (f == 1), f);
  BOOST_TEST_REQUIRE(s.warnings.size() == 1u);
  BOOST_TEST_MESSAGE(s.warnings[0]);
  BOOST_TEST(s.warnings[0].find("beyond the face(s) x+ and") != std::string::npos);
  // The same sphere wholly inside: exact, and no warning.
  doc["objects"]["block"]["geometry"]["center"] = {0.03, 0.0, 0.0};
  const Scene inside = read_scene(doc, "test.json");
  const GridCoverage whole = grid_coverage(inside.objects[0].geometry, inside.grid);
  BOOST_TEST(!whole.sampled);
  BOOST_TEST(whole.inside == 1.0);
  BOOST_TEST(inside.warnings.empty());
}

// The check must not fire on the scenes the project ships (ratios 0.97-1.03 are the seeding's
// staircase, not clipping).
BOOST_AUTO_TEST_CASE(every_shipped_scene_is_read_without_a_warning) {
  int n = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;
    const Json doc = load_scene_document(entry.path().string());
    if (!doc.contains("grid") || !doc.contains("objects")) continue;  // a base (elastic_base)
    const Scene s = read_scene(doc, entry.path().string());
    for (const std::string& w : s.warnings) BOOST_ERROR(w);
    ++n;
  }
  BOOST_TEST(n >= 27);  // 28 files, one of them a base
}

BOOST_AUTO_TEST_SUITE_END()
