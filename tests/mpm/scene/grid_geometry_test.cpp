// The grid-geometry catalogue (mpm/scene/grid_geometry.hpp): every struct has every member (the
// header's static_assert on CataloguedGeometry, asserted here again with the struct named), each
// struct's values against what it means (one kExpected line per struct: a struct without one
// does not compile), the enum and the catalogue agree, names round-trip through the scene
// reader, and visit_geometry calls the struct of the value it is given.
#include "mpm/scene/grid_geometry.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "mpm/input/scene_reader.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

// What each geometry must be, written out by hand.
struct Expected {
  std::string_view name;
  int mesh_axes;
  int nodes_along_z_of_3;  ///< for a shape of 3 nodes per axis
  bool hoop, rings, per_metre;
  std::array<double, 3> momentum;
  int faces_read, axis_face;
  double particle_volume;  ///< at x = (0, 0.3, 0) with a cell share of 1e-6 m^3 [m^3]
  double cylinder_volume;  ///< of a cylinder of radius 0.1 and length 2 along the mesh's axis [m^3]
};

constexpr double kPi = std::numbers::pi;

template <class G>
constexpr Expected kExpected = G::kNoSuchGeometryInThisTest;
template <>
constexpr Expected kExpected<ThreeDGrid> = {"3d",      3, 3,  false, false,           false,
                                            {1, 1, 1}, 6, -1, 1e-6,  kPi * 0.01 * 2.0};
template <>
constexpr Expected kExpected<AxisymmetricGrid> = {
    "axisymmetric",  2, 1, true, true, false, {1, 0, 0}, 4, 2, 2.0 * kPi * 0.3 * 1e-6,
    kPi * 0.01 * 2.0};  // the revolved body
template <>
constexpr Expected kExpected<PlaneStrainGrid> = {
    "plane_strain", 2, 1,  false, false,     true,
    {1, 1, 1},      4, -1, 1e-6,  kPi * 0.01};  // per metre of thickness: the section's area times
                                                // 1 m

// A cylinder of radius 0.1 m and length 2 m on the axis x (revolution) or along z (prism).
Geometry cylinder_along(int axis) {
  Vec3 top = Vec3::Zero();
  top(axis) = 2.0;
  return Geometry{Cylinder{Vec3::Zero(), top, 0.1}};
}

template <class G>
void check_struct() {
  static_assert(CataloguedGeometry<G>, "the struct lacks a catalogue member");
  constexpr Expected e = kExpected<G>;
  const std::string who(G::kName);
  BOOST_TEST(G::kName == e.name);
  BOOST_TEST(G::kMeshAxes == e.mesh_axes, who);
  BOOST_TEST(G::template kNodesAlongZ<3> == e.nodes_along_z_of_3, who);
  BOOST_TEST(G::kHoop == e.hoop, who);
  BOOST_TEST(G::kRings == e.rings, who);
  BOOST_TEST(G::kPerMetreOfThickness == e.per_metre, who);
  for (int d = 0; d < 3; ++d)
    BOOST_TEST(G::kMomentumComponents[std::size_t(d)] == e.momentum[std::size_t(d)], who);
  BOOST_TEST(G::kFacesRead == e.faces_read, who);
  BOOST_TEST(G::kAxisFace == e.axis_face, who);
  BOOST_TEST(G::particle_volume(Vec3(0.0, 0.3, 0.0), 1e-6) == e.particle_volume);
  const Geometry body = cylinder_along(G::kPerMetreOfThickness ? 2 : 0);
  BOOST_TEST(G::form_problem(body) == "", who);
  BOOST_TEST(G::modelled_volume(body) == e.cylinder_volume, boost::test_tools::tolerance(1e-12));
  // A 2D geometry refuses a body without its form; 3D takes any.
  const Geometry sideways = cylinder_along(1);
  BOOST_TEST(G::form_problem(sideways).empty() == (G::kMeshAxes == 3), who);
  // The motions it models: along x always; across the plane only in 3D.
  BOOST_TEST(G::moves_in_model(Vec3(5.0, 0.0, 0.0)), who);
  BOOST_TEST(G::moves_in_model(Vec3(0.0, 0.0, 5.0)) == (G::kMeshAxes == 3), who);
  BOOST_TEST(G::kExpectedMotion.empty() == (G::kMeshAxes == 3), who);
}

template <class... G>
struct CheckAll {
  static void run() { (check_struct<G>(), ...); }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_grid_geometry)

BOOST_AUTO_TEST_CASE(every_catalogued_geometry_is_what_it_means) {
  WithEveryGeometry<CheckAll>::run();
}

BOOST_AUTO_TEST_CASE(the_light_node_rule_takes_the_lightest_particle_or_ring) {
  const std::vector<double> mass = {4.0, 3.0, 6.0};
  const std::vector<Vec3> x = {Vec3(0, 2.0, 0), Vec3(0, 1.0, 0), Vec3(0, 0.5, 0)};
  // The minima over the ranks, as called: every rank must make the same calls in the same order.
  std::vector<double> asked;
  const auto over_ranks = [&](double v) {
    asked.push_back(v);
    return v;
  };
  const LightNode cube = ThreeDGrid::light_node(mass, x, over_ranks);
  BOOST_TEST(cube.lightest == 3.0);
  BOOST_TEST(cube.radius == 0.0);
  BOOST_TEST(asked == std::vector<double>({3.0}), boost::test_tools::per_element());
  // Rings: mass per radius 2, 3, 12 -> 2 per metre, at the innermost radius 0.5 -> 1 kg; the
  // per-radius minimum first, then the radius.
  asked.clear();
  const LightNode ring = AxisymmetricGrid::light_node(mass, x, over_ranks);
  BOOST_TEST(ring.lightest == 1.0);
  BOOST_TEST(ring.radius == 0.5);
  BOOST_TEST(asked == std::vector<double>({2.0, 0.5}), boost::test_tools::per_element());
  // A rank without particles still takes part in both minima (else the others wait forever),
  // and with none anywhere there is no light mass.
  asked.clear();
  const LightNode none =
      AxisymmetricGrid::light_node(std::vector<double>{}, std::vector<Vec3>{}, over_ranks);
  BOOST_TEST(asked.size() == 2u);
  BOOST_TEST(std::isinf(none.lightest));
  asked.clear();
  BOOST_TEST(
      std::isinf(PlaneStrainGrid::light_node(std::vector<double>{}, std::vector<Vec3>{}, over_ranks)
                     .lightest));
  BOOST_TEST(asked.size() == 1u);
  BOOST_TEST(PlaneStrainGrid::light_node(mass, x, [](double v) { return v; }).lightest == 3.0);
}

BOOST_AUTO_TEST_CASE(the_enum_the_table_and_the_names_agree) {
  for (std::size_t i = 0; i < kGeometryCount; ++i) {
    const auto g = static_cast<GridGeometry>(i);
    BOOST_TEST(int(facts(g).id) == int(i));
    BOOST_TEST(int(geometry_named(facts(g).name).value()) == int(i));
    const GridGeometry visited =
        visit_geometry(g, [](auto geometry) { return decltype(geometry)::kId; });
    BOOST_TEST(int(visited) == int(i));
    // facts() is the struct's.
    visit_geometry(g, [&](auto geometry) {
      using G = decltype(geometry);
      BOOST_TEST(facts(g).name == G::kName);
      BOOST_TEST(facts(g).mesh_axes == G::kMeshAxes);
      BOOST_TEST(facts(g).planar() == (G::kMeshAxes < 3));
      for (int f = 0; f < 6; ++f)
        BOOST_TEST(facts(g).is_domain_face(f) == (f < G::kFacesRead && f != G::kAxisFace));
    });
  }
  BOOST_TEST(!geometry_named("2d").has_value());
  BOOST_TEST(!geometry_named("").has_value());
  BOOST_TEST(geometry_names().front() == "3d");  // the default
  BOOST_TEST(geometry_names().size() == kGeometryCount);
  // The key table's text: today's three, and every 2D geometry's name with its meaning.
  const std::string text = geometry_description();
  BOOST_TEST(text.rfind("3d, or a 2D grid in the x-y plane: axisymmetric (x the axis, y the radius "
                        ">= 0; totals of the revolved body) or plane_strain (per metre along z)",
                        0) == 0u);
  for (const GeometryFacts& f : kGeometryFacts)
    if (f.planar())
      BOOST_TEST(text.find(std::string(f.name) + " (" + std::string(f.meaning) + ")") !=
                 std::string::npos);
  // The shapes' geometry constants are the struct's.
  static_assert(GeometryOf<kAxisymmetric>::kHoop && !GeometryOf<kPlaneStrain>::kHoop);
}

BOOST_AUTO_TEST_CASE(the_domain_faces_are_those_read_but_the_axis) {
  // Written out: 3D every face; axisymmetric x-, x+ and y+ (y- is the axis, z has no faces);
  // plane strain the four faces in the plane.
  const bool expected[3][6] = {{true, true, true, true, true, true},
                               {true, true, false, true, false, false},
                               {true, true, true, true, false, false}};
  for (int g = 0; g < 3; ++g)
    for (int f = 0; f < 6; ++f)
      BOOST_TEST(facts(GridGeometry(g)).is_domain_face(f) == expected[g][f], g << " " << f);
}

BOOST_AUTO_TEST_CASE(every_name_reads_back_from_a_scene) {
  for (const std::string_view name : geometry_names()) {
    const bool planar = facts(*geometry_named(name)).planar();
    Json doc = {
        {"materials",
         {{"al", {{"file", std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json"}}}}},
        {"objects",
         {{"rod",
           {{"material", "al"},
            {"geometry",
             {{"type", "cylinder"},
              {"bottom",
               planar && name != "axisymmetric" ? Json{0.02, 0.02, -0.01} : Json{0.0, 0.0, 0.0}},
              {"top",
               planar && name != "axisymmetric" ? Json{0.02, 0.02, 0.01} : Json{0.02, 0.0, 0.0}},
              {"radius", 0.005}}},
            {"velocity", {1.0, 0.0, 0.0}}}}}},
        {"grid",
         {{"geometry", std::string(name)},
          {"lower", planar ? Json{0.0, 0.0} : Json{-0.01, -0.01, -0.01}},
          {"upper", planar ? Json{0.04, 0.04} : Json{0.04, 0.04, 0.04}},
          {"cells", planar ? Json{8, 8} : Json{8, 8, 8}}}},
        {"time", {{"max_time", 1e-6}}}};
    const Scene s = read_scene(doc, "geometry.json");
    BOOST_TEST(facts(s.grid.geometry).name == name);
    BOOST_TEST(s.grid.planar() == planar);
  }
}

BOOST_AUTO_TEST_SUITE_END()
