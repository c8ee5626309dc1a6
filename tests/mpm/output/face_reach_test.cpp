// Material that reaches an outer face no body was near at the start (mpm/output/face_reach.hpp,
// docs/mpm.md#output): on rigid_translation.json's block ([0.02, 0.04]^3 m in a [0, 0.06]^3 grid
// of 5 mm cells, so 20 mm, four cells, from every face):
// - moved by hand: a face is reached when a particle comes within one cell of it, at the first
//   sampled time, with the most particles seen in the layer; a face the block lay against at the
//   start (a symmetry plane through a quarter model), a wall and the axis of an axisymmetric grid
//   are not watched; the state goes through a checkpoint;
// - in a run: the block at 2000 m/s toward the free face x+: its front particle column (x0 =
//   0.03875 m) enters the face's layer (x >= 0.055 m) at (0.055 - 0.03875) / 2000 = 8.125 us, so
//   summary.json names x+ (free) at the first history row after it (rows every 0.5 us); a run
//   stopped at 5 us (the front at 0.04875 m) reports none.
#include "mpm/output/face_reach.hpp"

#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "mpm/input/scene_reader.hpp"
#include "mpm/run/run.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;

namespace {

Json block_scene() {
  return load_scene_document(std::string(IMPACT_SOURCE_DIR) +
                             "/data/scenes/verification/rigid_translation.json");
}

Scene scene_of(const Json& patch) {
  Json doc = block_scene();
  doc.merge_patch(patch);
  return read_scene(doc, std::string(IMPACT_SOURCE_DIR) + "/data/scenes/verification/t.json");
}

Particles shifted(Particles P, const Vec3& by) {
  for (Vec3& x : P.x) x += by;
  return P;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_face_reach)

BOOST_AUTO_TEST_CASE(a_face_is_reached_when_a_particle_comes_within_one_cell) {
  const Scene s = scene_of({{"grid", {{"boundary", {{"x+", "symmetric"}}}}}});
  const Particles P0 = seed_particles(s);
  FaceReach reach(s, P0, Communicator::one_rank());
  BOOST_TEST(reach.sample(P0, 0.0).empty());
  // 14.9 mm along x: the last particle column (x = 0.04 - 1.25 mm) stops short of 0.055 m.
  BOOST_TEST(reach.sample(shifted(P0, Vec3(0.0149, 0, 0)), 1e-6).empty());
  // 16.5 mm: the outer particle columns lie within 5 mm of x+ = 0.06; x+ only (the others free and
  // far, the block moved along x).
  const std::vector<int> now = reach.sample(shifted(P0, Vec3(0.0165, 0, 0)), 2e-6);
  BOOST_REQUIRE(now.size() == 1u);
  BOOST_TEST(now[0] == 1);                                                  // x+
  BOOST_TEST(reach.sample(shifted(P0, Vec3(0.0190, 0, 0)), 3e-6).empty());  // not again
  const Json j = reach.summary();
  BOOST_TEST_MESSAGE(j.dump());
  BOOST_REQUIRE(j.size() == 1u);
  BOOST_TEST(j[0].at("face") == "x+");
  BOOST_TEST(j[0].at("condition") == "symmetric");
  BOOST_TEST(j[0].at("first_time [s]").get<double>() == 2e-6);
  // The block has 8 x 8 = 64 particles per column along x (2 per cell, x0 = 0.02125 ...
  // 0.03875 m): one column lies in the layer [0.055, 0.06] after 16.5 mm (x = 0.05525), two after
  // 19 mm (0.05775, 0.05525): the most seen, 128.
  BOOST_TEST(j[0].at("particles").get<std::int64_t>() == 128);
  BOOST_TEST(reach.warning(1).find("material reached the x+ face (symmetric") != std::string::npos);
  // Through a checkpoint's state.
  FaceReach again(s, P0, Communicator::one_rank());
  again.restore(reach.state());
  BOOST_TEST(again.summary() == j);
  BOOST_CHECK_THROW(again.restore({1.0}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(faces_a_body_lay_against_walls_and_the_axis_are_not_watched) {
  // The block against x- at the start (a symmetry plane through a quarter model), x- a mirror:
  // moving further along -x is no news; a wall x+ is contact by design.
  Json patch = {{"objects", {{"block", {{"geometry", {{"lower", {0.0, 0.02, 0.02}}}}}}}},
                {"grid", {{"boundary", {{"x-", "symmetric"}, {"x+", "wall"}}}}}};
  const Scene s = scene_of(patch);
  const Particles P0 = seed_particles(s);
  FaceReach reach(s, P0, Communicator::one_rank());
  BOOST_TEST(reach.sample(shifted(P0, Vec3(-0.003, 0, 0)), 1e-6).empty());
  BOOST_TEST(reach.sample(shifted(P0, Vec3(0.0199, 0, 0)), 2e-6).empty());  // wall x+
  BOOST_TEST(reach.summary().empty());
}

// Issue 52: "near at the start" was one cell, so a body 2.5 mm from x- of the 60 mm grid was near
// at 12 cells (5 mm) and far at 120 (0.5 mm): the warning came and went with the resolution.
// Near is now within max(one cell, 5 % of the extent = 3 mm): not watched at either. A body
// 10 mm away (four 2.5 mm cells at 24 cells, 20 at 120) is watched at both.
BOOST_AUTO_TEST_CASE(whether_a_face_is_watched_does_not_change_with_the_grid) {
  for (const int cells : {12, 120}) {
    for (const double gap : {0.0025, 0.010}) {
      const Json patch = {
          {"grid", {{"cells", {cells, 12, 12}}, {"boundary", {{"x-", "symmetric"}}}}},
          {"objects",
           {{"block",
             {{"geometry",
               {{"lower", {gap, 0.02, 0.02}}, {"upper", {gap + 0.02, 0.04, 0.04}}}}}}}}};
      const Scene s = scene_of(patch);
      const Particles P0 = seed_particles(s);
      FaceReach reach(s, P0, Communicator::one_rank());
      // Moved onto the face: reached only where the face was watched.
      const std::vector<int> now = reach.sample(shifted(P0, Vec3(-gap, 0, 0)), 1e-6);
      BOOST_TEST(now.size() == (gap > 0.003 ? 1u : 0u), "cells " << cells << ", gap " << gap);
    }
  }
}

BOOST_AUTO_TEST_CASE(a_run_into_a_far_mirror_face_says_so) {
  const fs::path dir = fs::temp_directory_path() / ("mpm_face_reach_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  RunOptions options;
  options.threads = 1;
  options.out_dir = (dir / "reached").string();
  const Json patch = {{"objects", {{"block", {{"velocity", {2000.0, 0.0, 0.0}}}}}},
                      {"time", {{"max_time", 9e-6}}},
                      {"output", {{"interval", 5e-7}}}};
  BOOST_REQUIRE(run(scene_of(patch), options) == 0);
  std::ifstream in(dir / "reached" / "summary.json");
  const Json faces = Json::parse(in).at("material_reached_faces");
  BOOST_TEST_MESSAGE(faces.dump());
  BOOST_REQUIRE(faces.size() == 1u);
  BOOST_TEST(faces[0].at("face") == "x+");
  BOOST_TEST(faces[0].at("condition") == "free");
  const double first = faces[0].at("first_time [s]").get<double>();
  BOOST_TEST((first >= 8.125e-6 && first <= 9e-6), "first " << first);

  Json short_patch = patch;
  short_patch["time"]["max_time"] = 5e-6;  // 10 mm: the block stops 5 mm short of the layer
  options.out_dir = (dir / "short").string();
  BOOST_REQUIRE(run(scene_of(short_patch), options) == 0);
  std::ifstream in2(dir / "short" / "summary.json");
  BOOST_TEST(Json::parse(in2).at("material_reached_faces").empty());
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
