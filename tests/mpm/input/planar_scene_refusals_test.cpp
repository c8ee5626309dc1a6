// 2D scenes the reader refuses (docs/scenes.md#2d-grids): a body without the 2D form of its grid
// (below or off the axis, a box in axisymmetry, a sphere in plane strain), a z face, [x, y, z]
// where [x, y] is expected, an axis face that is not a mirror, a grid that does not start at the
// axis, velocities and gravity out of the plane. Each message names the file, the key path and
// the reason; and the valid twins of these scenes are read.
#include <boost/test/unit_test.hpp>
#include <string>

#include "helpers/scene_refusal.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

using impact::testing::axisymmetric_rod;
using impact::testing::check_refused;
using impact::testing::scene_error_of;

// A box spanning z = 0 on a plane-strain grid (a valid scene).
Json plane_strain_block() {
  Json doc = axisymmetric_rod();
  doc["grid"]["geometry"] = "plane_strain";
  doc["grid"]["lower"] = {0.0, -0.01};
  doc["objects"]["rod"]["geometry"] = {
      {"type", "box"}, {"lower", {0.0, -0.005, -0.5}}, {"upper", {0.02, 0.005, 0.5}}};
  doc["objects"]["rod"]["velocity"] = {30.0, -20.0, 0.0};
  return doc;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_planar_scene_refusals)

BOOST_AUTO_TEST_CASE(the_valid_twins_are_read) {
  const Scene axi = read_scene(axisymmetric_rod(), "test.json");
  BOOST_TEST((axi.grid.geometry == GridGeometry::axisymmetric));
  BOOST_TEST(axi.grid.cells[2] == 1);
  BOOST_TEST(axi.grid.lower(2) == -0.5);
  BOOST_TEST(axi.grid.upper(2) == 0.5);
  BOOST_TEST((axi.grid.faces[2] == FaceCondition::symmetric));
  BOOST_TEST(axi.objects[0].particles_per_cell[2] == 1);
  const Scene plane = read_scene(plane_strain_block(), "test.json");
  BOOST_TEST((plane.grid.geometry == GridGeometry::plane_strain));
}

BOOST_AUTO_TEST_CASE(a_body_below_the_axis_is_refused) {
  Json doc = axisymmetric_rod();
  doc["objects"]["rod"]["geometry"]["bottom"] = {0.0, -0.003, 0.0};
  doc["objects"]["rod"]["geometry"]["top"] = {0.02, -0.003, 0.0};
  check_refused(doc, {"/objects/rod/geometry: a cylinder from [0, -0.003, 0] to [0.02, -0.003, 0] "
                      "is not a body of revolution about the x axis (it lies at y < 0); expected "
                      "bottom and top on the axis, [x, 0, 0] (grid.geometry \"axisymmetric\")"});
  doc = axisymmetric_rod();
  doc["objects"]["rod"]["geometry"] = {
      {"type", "sphere"}, {"center", {0.01, -0.002, 0.0}}, {"radius", 0.002}};
  check_refused(doc, {"/objects/rod/geometry: a sphere centred at [0.01, -0.002, 0] is off the "
                      "axis of symmetry (the x axis, y = z = 0), at y < 0; expected its centre on "
                      "the axis, [x, 0, 0]"});
}

BOOST_AUTO_TEST_CASE(an_off_axis_sphere_and_a_box_have_no_axisymmetric_form) {
  Json doc = axisymmetric_rod();
  doc["objects"]["rod"]["geometry"] = {
      {"type", "sphere"}, {"center", {0.01, 0.004, 0.0}}, {"radius", 0.003}};
  check_refused(doc, {"/objects/rod/geometry: a sphere centred at [0.01, 0.004, 0] is off the axis "
                      "of symmetry (the x axis, y = z = 0); expected its centre on the axis"});
  doc["objects"]["rod"]["geometry"] = {
      {"type", "box"}, {"lower", {0.0, 0.0, -0.005}}, {"upper", {0.02, 0.005, 0.005}}};
  check_refused(doc, {"/objects/rod/geometry: a box is not a body of revolution about the x axis; "
                      "expected a cylinder or hollow_cylinder along x on the axis"});
  // A cylinder on the axis but along y is no body of revolution about x either.
  doc["objects"]["rod"]["geometry"] = {{"type", "cylinder"},
                                       {"bottom", {0.01, 0.0, 0.0}},
                                       {"top", {0.01, 0.005, 0.0}},
                                       {"radius", 0.002}};
  check_refused(doc, {"/objects/rod/geometry: a cylinder from [0.01, 0, 0] to [0.01, 0.005, 0] is "
                      "not a body of revolution about the x axis"});
}

// The grid is named as it was typed, [x, y], not with the z extent the reader gives it.
BOOST_AUTO_TEST_CASE(a_body_beyond_a_2d_grid_is_named_with_the_grid_as_typed) {
  Json doc = axisymmetric_rod();
  doc["objects"]["rod"]["geometry"]["bottom"] = {0.05, 0.0, 0.0};
  doc["objects"]["rod"]["geometry"]["top"] = {0.07, 0.0, 0.0};
  check_refused(doc, {"/objects/rod/geometry: lies wholly outside the grid [0, 0] to [0.04, 0.01] "
                      "m (its bounding box [0.05, -0.005, -0.005] to [0.07, 0.005, 0.005] m): no "
                      "particle would be seeded"});
}

BOOST_AUTO_TEST_CASE(a_sphere_has_no_plane_strain_form) {
  Json doc = plane_strain_block();
  doc["objects"]["rod"]["geometry"] = {
      {"type", "sphere"}, {"center", {0.01, 0.0, 0.0}}, {"radius", 0.004}};
  check_refused(doc, {"/objects/rod/geometry: a sphere has no plane-strain form",
                      "expected a cylinder along z for a disc (grid.geometry \"plane_strain\")"});
  doc = plane_strain_block();
  doc["objects"]["rod"]["geometry"]["lower"] = {0.0, -0.005, 0.1};
  check_refused(doc, {"/objects/rod/geometry: a box from z = 0.1 to 0.5 m misses the plane z = 0 "
                      "that a plane-strain grid models"});
}

BOOST_AUTO_TEST_CASE(a_face_along_z_is_refused) {
  for (Json doc : {axisymmetric_rod(), plane_strain_block()}) {
    doc["grid"]["boundary"]["z-"] = "symmetric";
    doc["grid"]["boundary"]["z+"] = "free";
    const std::string geometry = doc["grid"]["geometry"];
    check_refused(doc, {"/grid/boundary/z-: a 2D grid (grid.geometry \"" + geometry +
                            "\") has no face along z; expected faces x-, x+, y- and y+ only",
                        "/grid/boundary/z+: a 2D grid"});
  }
}

BOOST_AUTO_TEST_CASE(friction_on_a_face_along_z_is_refused_as_that_face) {
  // Not "make z+ a wall": a 2D grid has no such face (a new user's trial, issue 54).
  Json doc = plane_strain_block();
  doc["grid"]["boundary"]["x-"] = "wall";
  doc["grid"]["wall_friction"] = {{"x-", 0.2}, {"z+", 0.3}};
  check_refused(doc, {"/grid/wall_friction/z+: a 2D grid (grid.geometry \"plane_strain\") has no "
                      "face along z; expected faces x-, x+, y- and y+ only"});
  BOOST_TEST(scene_error_of(doc).find("is not a wall") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_automatic_split_of_a_2d_grid_is_two_zeros) {
  // [0, 0] is [0, 0, 0], the automatic split; [2, 1] is two boxes along x, one along z.
  Json doc = axisymmetric_rod();
  doc["solver"]["ranks_per_axis"] = {0, 0};
  BOOST_TEST((read_scene(doc, "test.json").solver.ranks_per_axis == std::array<int, 3>{0, 0, 0}));
  doc["solver"]["ranks_per_axis"] = {2, 1};
  BOOST_TEST((read_scene(doc, "test.json").solver.ranks_per_axis == std::array<int, 3>{2, 1, 1}));
  doc["solver"]["ranks_per_axis"] = {2, 0};
  check_refused(doc, {"/solver/ranks_per_axis: expected three integers >= 1 ([px, py] on a 2D "
                      "grid), [0, 0, 0] for the automatic split ([0, 0] on a 2D grid)"});
}

BOOST_AUTO_TEST_CASE(an_off_axis_crater_names_the_key_that_is_off) {
  // axis_z, not axis_y (a new user's trial, issue 54); a missing one is its own problem only.
  Json doc = axisymmetric_rod();
  doc["output"]["crater"] = {{"object", "rod"}, {"face", 0.02}, {"axis_y", 0.0}, {"axis_z", 1e-3}};
  check_refused(doc, {"/output/crater/axis_z: the crater of an axisymmetric scene is centred on "
                      "the axis of symmetry"});
  BOOST_TEST(scene_error_of(doc).find("/output/crater/axis_y") == std::string::npos);
  doc["output"]["crater"].erase("axis_y");
  const std::string e = scene_error_of(doc);
  BOOST_TEST(e.find("/output/crater/axis_y") != std::string::npos, e);
  BOOST_TEST(e.find("centred on the axis") != std::string::npos, e);  // axis_z is still off
  doc["output"]["crater"]["axis_z"] = 0.0;
  BOOST_TEST(scene_error_of(doc).find("centred on the axis") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(three_numbers_where_two_are_expected_are_refused) {
  Json doc = axisymmetric_rod();
  doc["grid"]["lower"] = {0.0, 0.0, -0.005};
  doc["grid"]["cells"] = {8, 2, 2};
  doc["objects"]["rod"]["particles_per_cell"] = {2, 2, 2};
  doc["solver"]["ranks_per_axis"] = {1, 1, 1};
  check_refused(doc, {"/grid/lower: expected an array of 2 numbers [x, y] on a 2D grid "
                      "(grid.geometry \"axisymmetric\"), got [0.0,0.0,-0.005]",
                      "/grid/cells: expected an array of 2 numbers [x, y]",
                      "/objects/rod/particles_per_cell: expected an array of 2 numbers [x, y]",
                      "/solver/ranks_per_axis: expected an array of 2 numbers [x, y]"});
}

BOOST_AUTO_TEST_CASE(the_axis_face_is_a_mirror_and_the_grid_starts_at_the_axis) {
  for (const char* condition : {"free", "fixed", "wall"}) {
    Json doc = axisymmetric_rod();
    doc["grid"]["boundary"]["y-"] = condition;
    check_refused(doc, {std::string("/grid/boundary/y-: the face y- of an axisymmetric grid is the "
                                    "axis of symmetry, where the radial velocity is zero: "
                                    "expected \"symmetric\", got \"") +
                        condition + "\""});
  }
  Json doc = axisymmetric_rod();
  doc["grid"]["lower"] = {0.0, -0.01};
  check_refused(doc, {"/grid/lower/1: an axisymmetric grid starts at the axis, y = 0 (y is the "
                      "radius); expected 0, got -0.01"});
  // A tiny offset, e.g. from a generated scene, is named as the number it is, not as 0.000000.
  doc["grid"]["lower"] = {0.0, 1e-9};
  check_refused(doc, {"/grid/lower/1: an axisymmetric grid starts at the axis", "got 1e-09"});
}

BOOST_AUTO_TEST_CASE(velocities_and_gravity_out_of_the_plane_are_refused) {
  Json doc = axisymmetric_rod();
  doc["objects"]["rod"]["velocity"] = {30.0, 5.0, 0.0};
  doc["solver"]["gravity"] = {0.0, -9.81, 0.0};
  check_refused(doc, {"/objects/rod/velocity: initial velocity [30, 5, 0] on grid.geometry "
                      "\"axisymmetric\": expected [v, 0, 0]: a body of revolution moves along its "
                      "axis x",
                      "/solver/gravity: gravity [0, -9.81, 0] on grid.geometry \"axisymmetric\""});
  doc = plane_strain_block();
  doc["objects"]["rod"]["velocity"] = {30.0, -20.0, 1.0};
  check_refused(doc, {"/objects/rod/velocity: initial velocity [30, -20, 1] on grid.geometry "
                      "\"plane_strain\": expected [vx, vy, 0]: a plane-strain body moves in the "
                      "x-y plane"});
  // In plane strain the in-plane velocity is free.
  doc["objects"]["rod"]["velocity"] = {30.0, -20.0, 0.0};
  BOOST_TEST(scene_error_of(doc).empty());
}

BOOST_AUTO_TEST_SUITE_END()
