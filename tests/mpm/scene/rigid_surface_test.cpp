// The surface contact meets a rigid object at (mpm/scene/rigid_surface.hpp): its geometry, with a
// face on a still `symmetric` or `wall` face of the grid continued by its image (the body goes on
// there, as the normals' mirrored masses read it), and none where an earlier object cuts it.
// On sliding_block_rigid.json: a rigid floor box x in [0, 1] mm under a block, the grid from x = 0.
#include "mpm/scene/rigid_surface.hpp"

#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"
#include "mpm/geometry/surface_distance.hpp"

using namespace impact;
using namespace impact::mpm;
namespace tt = boost::test_tools;

namespace {

// The floor's field (its material's) and its surface.
std::optional<Geometry> floor_surface(const Json& patch) {
  const Scene s = test::verification_scene("sliding_block_rigid.json", patch);
  const std::vector<std::optional<Geometry>> surfaces = rigid_field_surfaces(s);
  for (const SceneObject& o : s.objects)
    if (o.name == "floor") return surfaces.at(std::size_t(s.parent_field(o.material)));
  return std::nullopt;
}

// The floor's bottom face, x = 0, on the grid's x- face.
double lower_x(const Geometry& g) {
  return std::get<Box>(g.shape).lower(0);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(rigid_surface)

BOOST_AUTO_TEST_CASE(a_face_on_a_mirror_face_of_the_grid_is_continued_by_its_image) {
  // A free x- face: the floor's bottom is a surface; a wall or a mirror: it is continued.
  const std::optional<Geometry> free = floor_surface(Json::object());
  BOOST_TEST_REQUIRE(free.has_value());
  BOOST_TEST(lower_x(*free) == 0.0);
  for (const char* face : {"wall", "symmetric"}) {
    const std::optional<Geometry> g = floor_surface({{"grid", {{"boundary", {{"x-", face}}}}}});
    BOOST_TEST_REQUIRE(g.has_value());
    BOOST_TEST(lower_x(*g) == -0.001, tt::tolerance(1e-12));
    // Just above the bottom face the nearest surface is now the floor's top.
    const SurfaceDistance d = surface_distance(*g, Vec3(1e-4, 0.005, 0.003));
    BOOST_TEST(d.outward(0) == 1.0);
  }
  // A floor moving away from the wall leaves it: no continuation.
  const std::optional<Geometry> moving =
      floor_surface({{"grid", {{"boundary", {{"x-", "wall"}}}}},
                     {"objects", {{"floor", {{"velocity", {0.1, 0, 0}}}}}}});
  BOOST_TEST_REQUIRE(moving.has_value());
  BOOST_TEST(lower_x(*moving) == 0.0);
}

// An earlier rigid object of another material that takes part of the floor (an anvil reaching
// into it): the seeded floor is not its geometry, and the mass gradient serves. A second part of
// the floor's own material (one field, one bowl) does not cut it: their union is the surface.
BOOST_AUTO_TEST_CASE(a_rigid_object_an_earlier_object_cuts_has_no_surface) {
  const Json anvil = {
      {"rigid", true},
      {"geometry",
       {{"type", "box"}, {"lower", {0.0, 0.0, 0.0}}, {"upper", {0.0015, 0.001, 0.006}}}}};
  Json other = anvil, own = anvil;
  other["material"] = "anvil_al";
  own["material"] = "floor_al";
  const Json material = {
      {"file", std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json"}};
  BOOST_TEST(
      !floor_surface({{"materials", {{"anvil_al", material}}}, {"objects", {{"anvil", other}}}})
           .has_value());
  const std::optional<Geometry> bowl = floor_surface({{"objects", {{"anvil", own}}}});
  BOOST_TEST_REQUIRE(bowl.has_value());
  BOOST_TEST(std::holds_alternative<Union>(bowl->shape));
}

// A rigid bowl (a floor x <= 1 mm and a wall 0.5 <= y <= 2 mm, one field) and a node inside the
// floor half a millimetre (a cell) below its top and a cell beside the wall, met by a body above
// the floor (its gradient along +x): the surface it meets is the floor's top, whose normal into the
// bowl is -x. The node's own nearest face is the top too; moved at once by its depth and two cells
// (an audit's catch) it was next to the wall, and took the wall's normal. Outside the bowl the
// node's own nearest surface serves whatever the body.
BOOST_AUTO_TEST_CASE(a_node_inside_a_bowl_meets_the_face_the_body_is_on) {
  const Json bowl = {
      {"type", "union"},
      {"lower", nullptr},
      {"upper", nullptr},
      {"parts",
       {{"bottom", {{"type", "box"}, {"lower", {0, 0, 0}}, {"upper", {0.001, 0.01, 0.006}}}},
        {"side", {{"type", "box"}, {"lower", {0, 0.0005, 0}}, {"upper", {0.004, 0.002, 0.006}}}}}}};
  const Simulation sim(test::verification_scene("sliding_block_rigid.json",
                                                {{"objects", {{"floor", {{"geometry", bowl}}}}}}));
  const Grid& G = sim.grid();
  int field = -1;
  for (int f = 0; f < G.fields(); ++f)
    if (G.is_rigid_field(f)) field = f;
  BOOST_TEST_REQUIRE(field >= 0);
  // Nodes are 0.5 mm apart from the origin: (1, 5) is x = 0.5 mm, y = 2.5 mm.
  const Vec3 inside = G.rigid_inward_normal(field, G.index(1, 5, 6), Vec3(1, 0, 0));
  BOOST_TEST((inside - Vec3(-1, 0, 0)).norm() < 1e-12);
  const Vec3 above = G.rigid_inward_normal(field, G.index(3, 7, 6), Vec3(0, 0, 1));
  BOOST_TEST((above - Vec3(-1, 0, 0)).norm() < 1e-12);
  // Beside the wall, above the floor: the wall's face is nearer (0.5 mm against 1 mm).
  const Vec3 beside = G.rigid_inward_normal(field, G.index(4, 5, 6), Vec3(1, 0, 0));
  BOOST_TEST((beside - Vec3(0, -1, 0)).norm() < 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
