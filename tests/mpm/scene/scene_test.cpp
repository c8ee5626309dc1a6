// Scene reading: `extends` merge-patch rule, defaults, seeding volume against exact volumes, and
// input errors that name the file and the JSON key path.
#include "mpm/scene/scene.hpp"

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "helpers/scene_error.hpp"
#include "mpm/particles/particles.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

const std::string kScenes = std::string(IMPACT_SOURCE_DIR) + "/data/scenes/";

using impact::testing::scene_error_of;

Json base() {
  return load_scene_document(kScenes + "verification/rigid_translation.json");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_scene)

BOOST_AUTO_TEST_CASE(extends_applies_the_file_as_a_merge_patch_over_its_base) {
  const Json doc = base();
  // From the base: the material and the time multiplier; from the file: max_time and the object.
  BOOST_TEST(doc["materials"]["elastic_al"]["overrides"]["constitutive_model"]["flow_stress"]["A"]
                 .get<double>() == 1e15);
  BOOST_TEST(doc["time"]["multiplier"].get<double>() == 0.5);
  BOOST_TEST(doc["time"]["max_time"].get<double>() == 2e-4);
  BOOST_TEST(!doc.contains("extends"));
  // The base's relative material path is resolved against the base's own directory.
  BOOST_TEST(std::filesystem::exists(doc["materials"]["elastic_al"]["file"].get<std::string>()));
  // A null in a patch deletes: uniaxial_compression replaces the elastic material.
  const Json uc = load_scene_document(kScenes + "verification/uniaxial_compression.json");
  BOOST_TEST(!uc["materials"].contains("elastic_al"));
  BOOST_TEST(uc["materials"].contains("jc_al"));
}

BOOST_AUTO_TEST_CASE(absent_keys_take_their_documented_defaults) {
  const Scene s = read_scene(base(), "rigid_translation.json");
  BOOST_TEST(s.time.min_dt == 0.0);
  BOOST_TEST(std::isinf(s.time.max_dt));
  BOOST_TEST(std::isinf(s.time.initial_dt));
  BOOST_TEST(s.output.interval == s.time.max_time / 100.0);
  BOOST_TEST(s.objects[0].particles_per_cell[0] == 2);
  BOOST_TEST(s.objects[0].temperature == 294.0);
  BOOST_TEST(s.solver.interpolation == "gimp");
  BOOST_TEST((s.solver.scheme == Scheme::musl));
  BOOST_TEST(s.solver.gravity.isZero());
}

BOOST_AUTO_TEST_CASE(geometry_volumes_are_exact) {
  constexpr double pi = std::numbers::pi;
  const Geometry tube{
      HollowCylinder{Vec3(15e-3, 0, 0), Vec3(119e-3, 0, 0), 31.8e-3, 3.2e-3, 13.919e-3}};
  const double ri = 31.8e-3 - 3.2e-3;
  BOOST_TEST(volume(tube) == pi * (31.8e-3 * 31.8e-3 - ri * ri) * 104e-3 + pi * ri * ri * 13.919e-3,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(inside(tube, Vec3(20e-3, 0, 0)));       // in the cap
  BOOST_TEST(!inside(tube, Vec3(60e-3, 0, 0)));      // in the bore
  BOOST_TEST(inside(tube, Vec3(60e-3, 30e-3, 0)));   // in the wall
  BOOST_TEST(!inside(tube, Vec3(60e-3, 32e-3, 0)));  // outside
  const Geometry cyl{Cylinder{Vec3(0, 0, 0), Vec3(0, 0, 2), 0.5}};
  BOOST_TEST(volume(cyl) == pi * 0.25 * 2, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(seeded_box_volume_and_mass_equal_the_exact_ones) {
  const Scene s = read_scene(base(), "rigid_translation.json");
  const Particles p = seed_particles(s);
  double v = 0.0, m = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    v += p.volume0[i];
    m += p.mass[i];
  }
  BOOST_TEST(p.size() == 4u * 4u * 4u * 8u);  // 4 cells per side, 2 x 2 x 2 per cell
  BOOST_TEST(v == 8e-6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m == 2700.0 * 8e-6, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(seeded_sphere_volume_converges_to_the_exact_volume) {
  Json doc = load_scene_document(kScenes + "verification/two_spheres.json");
  double previous = 1.0;
  for (int ppc : {1, 2, 4}) {
    doc["objects"]["left"]["particles_per_cell"] = {ppc, ppc, ppc};
    const Scene s = read_scene(doc, "two_spheres.json");
    const Particles p = seed_particles(s);
    double v = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) v += p.object[i] == 0 ? p.volume0[i] : 0.0;
    const double err = std::abs(v / volume(s.objects[0].geometry) - 1.0);
    BOOST_TEST_MESSAGE("ppc " << ppc << ": particle/exact volume - 1 = " << err);
    BOOST_TEST(err < std::max(previous, 0.02));
    previous = err;
  }
  BOOST_TEST(previous < 0.01);
}

BOOST_AUTO_TEST_CASE(errors_name_the_key_path_and_what_was_expected) {
  Json doc = base();
  doc["grid"]["cell"] = {1, 2, 3};               // misspelt key
  doc["time"]["multiplier"] = 2.0;               // out of range
  doc["objects"]["block"]["velocity"] = "fast";  // wrong type
  doc["solver"]["scheme"] = "usf";               // unknown name
  const std::string e = scene_error_of(doc);
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("test.json: /grid/cell: unknown key (did you mean cells?)") !=
             std::string::npos);
  BOOST_TEST(e.find("/time/multiplier: expected a number in (0, 1.5], got 2") != std::string::npos);
  BOOST_TEST(e.find("/objects/block/velocity: expected an array of 3 numbers") !=
             std::string::npos);
  BOOST_TEST(e.find("/solver/scheme: unknown name \"usf\"; known: usl, musl") != std::string::npos);
}

// solver.ranks_per_axis: three integers >= 1 (their product checked against the rank count when
// a run starts, mpm/parallel/decomposition_plan.cpp), [0, 0, 0] for the automatic split cutting the
// fewest node faces (the default, also "fewest_cut_faces"), or "least_loaded".
BOOST_AUTO_TEST_CASE(ranks_per_axis_is_all_positive_or_all_zero_or_a_rule) {
  Json doc = base();
  BOOST_TEST((read_scene(doc, "test.json").solver.ranks_per_axis == std::array<int, 3>{0, 0, 0}));
  BOOST_TEST((read_scene(doc, "test.json").solver.split == SplitRule::fewest_cut_faces));
  doc["solver"]["ranks_per_axis"] = {2, 1, 2};
  BOOST_TEST((read_scene(doc, "test.json").solver.ranks_per_axis == std::array<int, 3>{2, 1, 2}));
  doc["solver"]["ranks_per_axis"] = "least_loaded";
  BOOST_TEST((read_scene(doc, "test.json").solver.ranks_per_axis == std::array<int, 3>{0, 0, 0}));
  BOOST_TEST((read_scene(doc, "test.json").solver.split == SplitRule::least_loaded));
  doc["solver"]["ranks_per_axis"] = "fewest_cut_faces";
  BOOST_TEST((read_scene(doc, "test.json").solver.split == SplitRule::fewest_cut_faces));
  doc["solver"]["ranks_per_axis"] = "balanced";
  std::string e = scene_error_of(doc);
  BOOST_TEST(e.find("/solver/ranks_per_axis: unknown name \"balanced\"; known: fewest_cut_faces, "
                    "least_loaded") != std::string::npos);
  doc["solver"]["ranks_per_axis"] = {2, 0, 1};
  e = scene_error_of(doc);
  BOOST_TEST(e.find("/solver/ranks_per_axis: expected three integers >= 1 ([px, py] on a 2D "
                    "grid), [0, 0, 0] for the automatic split ([0, 0] on a 2D grid), or "
                    "\"least_loaded\"") != std::string::npos);
  doc["solver"]["ranks_per_axis"] = {2, -1, 1};
  e = scene_error_of(doc);
  BOOST_TEST(e.find("/solver/ranks_per_axis: expected integers in [0, 1048576]") !=
             std::string::npos);
}

// solver.shuffle_particles: 0 (seed order, the default) or a whole seed k in [1, 1e15].
BOOST_AUTO_TEST_CASE(shuffle_particles_is_zero_or_a_whole_seed) {
  Json doc = base();
  BOOST_TEST(read_scene(doc, "test.json").solver.shuffle_particles == 0u);
  doc["solver"]["shuffle_particles"] = 12;
  BOOST_TEST(read_scene(doc, "test.json").solver.shuffle_particles == 12u);
  doc["solver"]["shuffle_particles"] = 2.5;
  BOOST_TEST(scene_error_of(doc).find("/solver/shuffle_particles: expected a whole number (0: "
                                      "seed order; k >= 1: the shuffle's seed)") !=
             std::string::npos);
  doc["solver"]["shuffle_particles"] = -1;
  BOOST_TEST(scene_error_of(doc).find("/solver/shuffle_particles") != std::string::npos);
  doc["solver"]["shuffle_particles"] = 1e16;
  BOOST_TEST(scene_error_of(doc).find("/solver/shuffle_particles") != std::string::npos);
}

// Multipliers in (1, 1.5] are admissible (to test where the CFL limit fails) but warned about;
// time.max_energy_growth defaults to 1 (+100 %) and must be positive.
BOOST_AUTO_TEST_CASE(a_multiplier_above_one_is_read_with_a_warning) {
  Json doc = base();
  BOOST_TEST(read_scene(doc, "test.json").warnings.empty());
  BOOST_TEST(read_scene(doc, "test.json").time.max_energy_growth == 1.0);
  doc["time"]["multiplier"] = 1.2;
  doc["time"]["max_energy_growth"] = 0.5;
  const Scene s = read_scene(doc, "test.json");
  BOOST_TEST(s.time.multiplier == 1.2);
  BOOST_TEST(s.time.max_energy_growth == 0.5);
  BOOST_TEST_REQUIRE(s.warnings.size() == 1u);
  BOOST_TEST_MESSAGE(s.warnings[0]);
  BOOST_TEST(s.warnings[0].find("test.json: /time/multiplier: 1.2 is above 1") == 0u);
  doc["time"]["max_energy_growth"] = 0.0;
  BOOST_TEST(scene_error_of(doc).find("/time/max_energy_growth: expected a number in (0, inf)") !=
             std::string::npos);
}

// A graded grid's cells where the box's strips cross coarse cells are up to factor:1; the
// warning starts above 4 times the base cells' shape. At factor 4 exactly the smallest cell is a
// round-off under h0 / 4, which used to warn (the trial: every factor-2 ladder's level 2).
BOOST_AUTO_TEST_CASE(elongated_graded_cells_are_warned_of_above_four_to_one) {
  // The Taylor verification rod's grid (cells of 1.2658 mm), its impact end refined.
  Json doc = load_scene_document(kScenes + "verification/taylor_rod.json");
  doc["grid"]["refine"] = {{"lower", {0.0, 0.0, 0.0}},
                           {"upper", {0.0038, 0.0038, 0.0038}},
                           {"factor", 4},
                           {"growth", 1.5}};
  const auto elongated = [](const Scene& s) {
    return std::count_if(s.warnings.begin(), s.warnings.end(), [](const std::string& w) {
      return w.find("/grid/refine/factor: where the refined box's strips cross") !=
             std::string::npos;
    });
  };
  BOOST_TEST(elongated(read_scene(doc, "test.json")) == 0);
  doc["grid"]["refine"]["factor"] = 4.5;
  const Scene s = read_scene(doc, "test.json");
  BOOST_TEST(elongated(s) == 1);
  for (const auto& w : s.warnings) BOOST_TEST_MESSAGE(w);
}

// Two boxes one base cell apart, refined 8 and 2 times (the trial's): the gap is too short to
// grade at 1.2, so its equal cells meet the finer ones at a steeper ratio, warned with its value.
// Five base cells apart the gap grades within 1.2, no warning.
BOOST_AUTO_TEST_CASE(a_gap_between_boxes_too_short_to_grade_is_warned_of) {
  Json doc = load_scene_document(kScenes + "verification/rigid_translation.json");
  const auto boxes = [](double second_lower) {
    return Json::array(
        {{{"lower", {0.01, 0.01, 0.01}},
          {"upper", {0.015, 0.015, 0.015}},
          {"factor", 8},
          {"growth", 1.2}},
         {{"lower", {second_lower, second_lower, second_lower}},
          {"upper", {second_lower + 0.005, second_lower + 0.005, second_lower + 0.005}},
          {"factor", 2},
          {"growth", 1.2}}});
  };
  const auto steep = [](const Scene& s) {
    return std::count_if(s.warnings.begin(), s.warnings.end(), [](const std::string& w) {
      return w.find("/grid/refine: along axis 0 neighbouring cells differ by") != std::string::npos;
    });
  };
  doc["grid"]["refine"] = boxes(0.02);
  const Scene s = read_scene(doc, "test.json");
  for (const auto& w : s.warnings) BOOST_TEST_MESSAGE(w);
  BOOST_TEST(steep(s) == 1);
  doc["grid"]["refine"] = boxes(0.04);
  BOOST_TEST(steep(read_scene(doc, "test.json")) == 0);
}

// A factor that does not divide a box's base cells into whole cells is rounded (the trial's 2.5
// on one base cell of 5 mm gave cells of h0 / 3 without a word): warned where the factor moves by
// more than 5 %, with what it became. 2.5 on two base cells is 5 whole cells; 1.5 on 17 (a ladder
// level's 1.53) is within 5 %. The axes that round alike are named together.
BOOST_AUTO_TEST_CASE(a_factor_rounded_to_whole_cells_is_warned_of) {
  Json doc = load_scene_document(kScenes + "verification/rigid_translation.json");  // h0 5 mm
  const auto rounded = [&](double upper, double factor) {
    doc["grid"]["refine"] = {
        {"lower", {0.02, 0.02, 0.02}}, {"upper", {upper, 0.025, 0.025}}, {"factor", factor}};
    const Scene s = read_scene(doc, "test.json");
    std::string found;
    for (const auto& w : s.warnings)
      if (w.find("/grid/refine/factor: factor") != std::string::npos) found += w;
    BOOST_TEST_MESSAGE(found);
    return found;
  };
  const std::string one = rounded(0.025, 2.5);
  BOOST_TEST(one.find("along axes 0, 1, 2 the box covers 1 base cell") != std::string::npos);
  BOOST_TEST(one.find("2.5 cells rounded to 3 of 0.00166667 m (a factor of 3)") !=
             std::string::npos);
  const std::string two = rounded(0.03, 2.5);  // 5 whole cells along x, 2.5 -> 3 along y, z
  BOOST_TEST(two.find("along axes 1, 2 the box covers 1 base cell") != std::string::npos);
  BOOST_TEST(two.find("axis 0") == std::string::npos);
  BOOST_TEST(rounded(0.025, 2.0).empty());
  doc["grid"]["cells"] = {17, 17, 17};  // 1.5 on the whole x axis's 17 cells: 26, a factor 1.53
  doc["grid"]["refine"] = {{"lower", {0.0, 0.02, 0.02}}, {"upper", {0.06, 0.03, 0.03}}};
  doc["grid"]["refine"]["factor"] = 1.5;
  const Scene s = read_scene(doc, "test.json");
  BOOST_TEST(s.grid.cells[0] == 26);
  for (const auto& w : s.warnings) BOOST_TEST(w.find("whole cells") == std::string::npos);
}

// Two boxes of factor 2.5 whose spans merge into 3 base cells get 8 cells (7.5 rounded), a
// factor of 2.67: each box alone gives whole cells (2 base cells, 5 cells), so only the merged
// check can say it (the trial's c46). Merging into 4 base cells (10 cells) is whole: no warning.
BOOST_AUTO_TEST_CASE(merged_spans_rounded_to_whole_cells_are_warned_of) {
  Json doc = load_scene_document(kScenes + "verification/rigid_translation.json");  // h0 5 mm
  const auto merged = [&](double second_lower) {
    const auto box = [](double lo) {
      return Json{
          {"lower", {lo, lo, lo}}, {"upper", {lo + 0.01, lo + 0.01, lo + 0.01}}, {"factor", 2.5}};
    };
    doc["grid"]["refine"] = Json::array({box(0.02), box(second_lower)});
    const Scene s = read_scene(doc, "test.json");
    std::string found;
    for (const auto& w : s.warnings)
      if (w.find("spans merge into one") != std::string::npos ||
          w.find("whole cells") != std::string::npos)
        found += w + "\n";
    BOOST_TEST_MESSAGE(found);
    return found;
  };
  const std::string three = merged(0.025);
  // The three axes came out alike: one warning names them together.
  BOOST_TEST(three.find("/grid/refine: along axes 0, 1, 2 the boxes' spans merge into one whose "
                        "cells are 0.001875 m, a factor of 2.66667 against the finest 2.5") !=
             std::string::npos);
  BOOST_TEST(three.find("along axis ") == std::string::npos);
  BOOST_TEST(three.find("does not divide") == std::string::npos);  // no box rounds alone
  BOOST_TEST(merged(0.03).empty());
}

// Each box's cells along an axis are bounded (100000); two boxes whose spans merge along x at
// factor 64 get 128000 cells together, refused at /grid/refine (each alone passes).
BOOST_AUTO_TEST_CASE(merged_boxes_are_held_to_the_cells_per_axis_bound) {
  Json doc = load_scene_document(kScenes + "verification/rigid_translation.json");
  doc["grid"]["cells"] = {2000, 12, 12};
  const auto box = [](double lo, double hi) {
    return Json{{"lower", {lo, 0.02, 0.02}}, {"upper", {hi, 0.025, 0.025}}, {"factor", 64}};
  };
  doc["grid"]["refine"] = Json::array({box(0.0, 0.03)});
  BOOST_TEST(read_scene(doc, "test.json").grid.cells[0] > 64000);
  doc["grid"]["refine"] = Json::array({box(0.0, 0.03), box(0.03, 0.06)});
  const std::string e = scene_error_of(doc);
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("/grid/refine: along axis 0 the boxes' refined spans together get 128000 "
                    "cells: expected at most 100000") != std::string::npos);
}

// A refusal of a graded grid's size advises on its refinement: one box, its factor and extent;
// in a list, the box whose removal takes away the most cells (the trial: a tiny factor-8 box
// inside a wide factor-2 box's y and z spans refines them 8 times; the memory refusal did not say
// which box did it).
BOOST_AUTO_TEST_CASE(a_refusal_names_the_box_that_adds_the_most_cells) {
  Json doc = load_scene_document(kScenes + "verification/rigid_translation.json");
  BOOST_TEST(read_scene(doc, "test.json").grid.refinement_advice().empty());
  const Json wide = {{"lower", {0.01, 0.01, 0.01}}, {"upper", {0.05, 0.05, 0.05}}, {"factor", 2}};
  const Json tiny = {
      {"lower", {0.03, 0.03, 0.03}}, {"upper", {0.035, 0.035, 0.035}}, {"factor", 8}};
  doc["grid"]["refine"] = wide;
  BOOST_TEST(read_scene(doc, "test.json").grid.refinement_advice() ==
             ", lower grid.refine.factor or narrow the refined box,");
  for (const auto& [list, costliest] :
       {std::pair{Json::array({wide, tiny}), 1}, std::pair{Json::array({tiny, wide}), 0}}) {
    doc["grid"]["refine"] = list;
    const std::string advice = read_scene(doc, "test.json").grid.refinement_advice();
    BOOST_TEST_MESSAGE(advice);
    BOOST_TEST(advice.find("(/grid/refine/" + std::to_string(costliest) + " adds the most cells") !=
               std::string::npos);
  }
}

// grid.refine neither a box nor a list (the trial's "abc"): one problem, at /grid/refine, not
// three more for the keys of a box that is not there.
BOOST_AUTO_TEST_CASE(a_refine_that_is_neither_a_box_nor_a_list_is_one_problem) {
  Json doc = base();
  doc["grid"]["refine"] = "abc";
  const std::string e = scene_error_of(doc);
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("/grid/refine") != std::string::npos);
  BOOST_TEST(e.find("missing") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(an_unknown_material_reference_lists_the_known_ones) {
  Json doc = base();
  doc["objects"]["block"]["material"] = "steel";
  BOOST_TEST(scene_error_of(doc).find("/objects/block/material: unknown material \"steel\"; known: "
                                      "elastic_al") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_bad_material_override_names_the_scene_entry_and_the_material_key) {
  Json doc = base();
  doc["materials"]["elastic_al"]["overrides"]["density"] = -2700.0;
  const std::string e = scene_error_of(doc);
  BOOST_TEST(e.find("/materials/elastic_al/file") != std::string::npos);
  BOOST_TEST(e.find("/density") != std::string::npos);
}

// Multi-field contact handles at most 64 velocity fields at a node (its per-node arrays): one per
// material, two with particle conversion (a companion each). 64 fields are read; 65 (65
// materials, or 33 with conversion: 66) are refused at /materials with the limit, where the
// contact used to ignore the fields beyond the 64th.
// A mistyped contact type, or a contact block that is not an object, is one error: before, the
// reader fell back to single_velocity and blamed the scene's mu and its rigid object as well
// (a new-user trial, on sliding_block_rigid.json).
BOOST_AUTO_TEST_CASE(a_mistyped_contact_type_is_one_error_not_three) {
  Json doc = load_scene_document(kScenes + "verification/sliding_block_rigid.json");
  const auto count = [](const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
  };
  doc["physics"]["contact"]["type"] = "frictional";
  std::string e = scene_error_of(doc);
  BOOST_TEST(e.find("/physics/contact/type: unknown name \"frictional\"") != std::string::npos, e);
  BOOST_TEST(count(e, ": /") == 1u, e);
  doc["physics"]["contact"] = "friction";
  e = scene_error_of(doc);
  BOOST_TEST(e.find("/physics/contact: expected") != std::string::npos, e);
  BOOST_TEST(count(e, ": /") == 1u, e);
}

// A rigid object's Coulomb coefficient (objects.<name>.mu) is its field's, the deformable fields
// keep contact.mu, and the friction switches see it with contact.mu 0 (block_on_block_rigid.json:
// the floor's mu 0 beside contact.mu 0.25).
BOOST_AUTO_TEST_CASE(a_rigid_objects_mu_is_its_fields_and_switches_friction_on) {
  const std::string file = kScenes + "verification/block_on_block_rigid.json";
  Json doc = load_scene_document(file);
  const auto field_of = [](const Scene& s, const std::string& name) {
    for (const SceneObject& o : s.objects)
      if (o.name == name) return std::size_t(s.parent_field(o.material));
    return std::size_t(-1);
  };
  Scene s = read_scene(doc, file);
  BOOST_TEST(s.rigid_field_friction()[field_of(s, "floor")] == 0.0);
  BOOST_TEST(s.rigid_field_friction()[field_of(s, "left")] == 0.25);
  BOOST_TEST(s.contact_friction());
  doc["objects"]["floor"].erase("mu");  // left out: contact.mu
  BOOST_TEST(read_scene(doc, file).rigid_field_friction()[field_of(s, "floor")] == 0.25);
  doc["objects"]["floor"]["mu"] = 0.4;
  doc["physics"]["contact"]["mu"] = 0.0;
  s = read_scene(doc, file);
  BOOST_TEST(s.rigid_field_friction()[field_of(s, "floor")] == 0.4);
  BOOST_TEST(s.rigid_friction() == 0.4);
  BOOST_TEST(s.contact_friction());  // the ledger's friction_heat, the grid's heat
  doc["physics"]["contact"]["rigid_contact"] = "particles";
  BOOST_TEST(read_scene(doc, file).friction_at_particles());  // the anchors
  doc["objects"]["floor"]["mu"] = 0.0;
  BOOST_TEST(!read_scene(doc, file).friction_at_particles());
  BOOST_TEST(!read_scene(doc, file).contact_friction());
}

// A rigid object's velocity given as an expression is refused; the warning that an initial
// velocity reads t at 0 only was printed beside the refusal, noise to a user who must replace
// the expression anyway (a new-user trial).
BOOST_AUTO_TEST_CASE(a_rigid_velocity_expression_is_refused_without_the_t_warning) {
  Json doc = load_scene_document(kScenes + "verification/sliding_block_rigid.json");
  doc["objects"]["floor"]["velocity"] = {"1e-3*t", 0.0, 0.0};
  const std::string e = scene_error_of(doc);
  BOOST_TEST(e.find("/objects/floor/velocity: a rigid object moves at one velocity for ever") !=
                 std::string::npos,
             e);
  BOOST_TEST(e.find("its t is always 0") == std::string::npos, e);
}

BOOST_AUTO_TEST_CASE(more_than_64_contact_fields_are_refused) {
  const auto with_materials = [](int n, bool conversion) {
    Json doc = base();
    const Json material = doc["materials"]["elastic_al"];
    for (int i = 1; i < n; ++i) doc["materials"]["copy_" + std::to_string(i)] = material;
    doc["physics"]["contact"] = {{"type", "friction"}, {"mu", 0.1}};
    doc["physics"]["create_new_particles"] = conversion;
    return doc;
  };
  BOOST_TEST(read_scene(with_materials(64, false), "test.json").field_count() == 64);
  BOOST_TEST(read_scene(with_materials(32, true), "test.json").field_count() == 64);
  std::string e = scene_error_of(with_materials(65, false));
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("test.json: /materials: 65 materials make 65 velocity fields under "
                    "physics.contact.type \"friction\": expected at most 64 fields (64 "
                    "materials), or contact \"single_velocity\" (one field)") != std::string::npos);
  e = scene_error_of(with_materials(33, true));
  BOOST_TEST_MESSAGE(e);
  BOOST_TEST(e.find("test.json: /materials: 33 materials make 66 velocity fields (each with a "
                    "companion field: physics.create_new_particles) under physics.contact.type "
                    "\"friction\": expected at most 64 fields (32 materials)") !=
             std::string::npos);
  // One shared field whatever the materials: single_velocity contact has no limit.
  Json single = with_materials(65, true);
  single["physics"]["contact"]["type"] = "single_velocity";
  single["physics"]["contact"].erase("mu");  // read by friction only (refused with one field)
  BOOST_TEST(read_scene(single, "test.json").field_count() == 1);
}

BOOST_AUTO_TEST_SUITE_END()
