// The grid geometries, one struct each, and their catalogue (docs/extending.md "A grid
// geometry"): 3D, axisymmetric (Sulsky & Schreyer 1996, CMAME 139:409) and plane strain. Each
// struct says once what its geometry means wherever the code needs it: its name, the mesh's
// axes, the hoop term, what a particle is, which momentum components are physical, the light-node
// rule, the volume it models, and the faces the scene reader takes. The step phases read it at
// compile time (shape/shape.hpp OnGrid); every other site reads facts(g) or visits the struct
// with visit_geometry(g, f). No code outside this file names a geometry (the guard:
// tests/mpm/grid_geometry_sites_test.py).
//
// A 2D grid lies in the x-y plane: z is one cell of 1 m, centred on z = 0, whose nodes are
// stored in the plane k = 0 only. Axisymmetric: x the axis of symmetry, y the radius (>= 0, the
// axis at y = 0), z the hoop direction; every mass, volume, force, momentum and energy is that of
// the body revolved through the full circle, 2 pi. Plane strain: z the out-of-plane direction (no
// strain along it); every extensive quantity per metre of thickness. The catalogue's current
// limit: a geometry with fewer than 2 mesh axes would need the sites that read planar() as "axis
// 2 is a single cell" made general first (docs/notes/grid_geometry_plan.md section 4).
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "mpm/geometry/geometry.hpp"
#include "mpm/scene/planar_form.hpp"

namespace impact::mpm {

/// The grid's kind (grid.geometry, docs/mpm.md#2d-grids). The values index the catalogue:
/// WithEveryGeometry lists the structs in this order (checked below).
enum class GridGeometry { three_d, axisymmetric, plane_strain };

/// What the light-node rule (kLightNodeMassFraction, mpm/step/step.hpp) takes from the seeded
/// particles: the mass it scales, and the radius that mass holds at (0: the same at every node).
struct LightNode {
  double lightest = std::numeric_limits<double>::infinity();  ///< [kg]; inf: no particle
  double radius = 0.0;                                        ///< [m]; > 0 only for rings
};

namespace detail {
// The geometries whose light node is a fixed fraction of the lightest particle.
template <class Masses, class Min>
LightNode lightest_particle(const Masses& mass, Min&& over_ranks) {
  double lightest = std::numeric_limits<double>::infinity();
  for (const double m : mass) lightest = std::min(lightest, m);
  return {over_ranks(lightest), 0.0};
}
// The memory estimate's seed count of a 2D grid: the seeded section's area, at most its bounding
// rectangle inside the grid, times ppc^2 over the cell's area.
inline double planar_seed_points(double area, const Vec3& extent, const Vec3& h,
                                 const std::array<int, 3>& ppc) {
  const double a = std::min(area, extent(0) * extent(1));
  return std::ceil(a / (h(0) * h(1)) * ppc[0] * ppc[1]);
}
}  // namespace detail

struct ThreeDGrid {
  static constexpr GridGeometry kId = GridGeometry::three_d;
  static constexpr std::string_view kName = "3d";  ///< grid.geometry; the catalogue's default
  static constexpr std::string_view kMeaning = "3D";
  static constexpr int kMeshAxes = 3;
  /// The nodes a shape of N nodes per axis visits along z.
  template <int N>
  static constexpr int kNodesAlongZ = N;
  /// The hoop terms of the step phases (shape/shape.hpp OnGrid).
  static constexpr bool kHoop = false;
  /// A particle is a ring about the x axis at radius y (contact normals, crater axis, outputs).
  static constexpr bool kRings = false;
  /// Masses, volumes, momenta and energies per metre of thickness (ledger/extensive_units.hpp).
  static constexpr bool kPerMetreOfThickness = false;
  /// The momentum components that are physical (1) or cancel by symmetry (0): the ledger's
  /// momentum and the observables' mean velocity.
  static constexpr std::array<double, 3> kMomentumComponents = {1.0, 1.0, 1.0};
  /// The faces the scene reader takes (kFaceNames order: the first kFacesRead; the rest free),
  /// and the one on the axis of symmetry (-1: none), which must be "symmetric".
  static constexpr int kFacesRead = 6;
  static constexpr int kAxisFace = -1;
  /// A seeded particle's volume at x, given its share of the cell [m^3].
  static double particle_volume(const Vec3& /*x*/, double cell_share) { return cell_share; }
  template <class Masses, class Positions, class Min>
  static LightNode light_node(const Masses& mass, const Positions& /*x*/, Min&& over_ranks) {
    return detail::lightest_particle(mass, over_ranks);
  }
  /// The volume the grid models of the body g [m^3] (summary.json's volume ratio).
  static double modelled_volume(const Geometry& g) { return volume(g); }
  /// The particles seeded of g, estimated before seeding (run/memory.cpp).
  static double estimated_seed_points(const Geometry& g, const Vec3& extent, const Vec3& h,
                                      const std::array<int, 3>& ppc) {
    const double v = std::min(volume(g), extent.prod());
    return std::ceil(v / h.prod() * ppc[0] * ppc[1] * ppc[2]);
  }
  /// Why g has no form on this grid ("" when it has one): a sentence naming the part.
  static std::string form_problem(const Geometry& /*g*/) { return ""; }
  /// Whether an object's velocity v is a motion the grid models, and what it expects otherwise.
  static bool moves_in_model(const Vec3& /*v*/) { return true; }
  static constexpr std::string_view kExpectedMotion = "";
};

struct AxisymmetricGrid {
  static constexpr GridGeometry kId = GridGeometry::axisymmetric;
  static constexpr std::string_view kName = "axisymmetric";
  static constexpr std::string_view kMeaning =
      "x the axis, y the radius >= 0; totals of the revolved body";
  static constexpr int kMeshAxes = 2;
  template <int N>
  static constexpr int kNodesAlongZ = 1;
  static constexpr bool kHoop = true;
  static constexpr bool kRings = true;
  static constexpr bool kPerMetreOfThickness = false;
  // Radial and hoop momenta cancel around each ring.
  static constexpr std::array<double, 3> kMomentumComponents = {1.0, 0.0, 0.0};
  static constexpr int kFacesRead = 4;
  static constexpr int kAxisFace = 2;  ///< y-: grid.lower[1] must be 0, the face "symmetric"
  /// The ring the sub-cell sweeps about the axis: 2 pi r times its area.
  static double particle_volume(const Vec3& x, double cell_share) {
    return 2.0 * std::numbers::pi * x(1) * cell_share;
  }
  /// A ring's mass is 2 pi r_p rho A_p: the lightest per unit radius, taken at the smallest radius
  /// seeded. Both minima are taken over the ranks, in this order.
  template <class Masses, class Positions, class Min>
  static LightNode light_node(const Masses& mass, const Positions& x, Min&& over_ranks) {
    double per_radius = std::numeric_limits<double>::infinity();
    double innermost = std::numeric_limits<double>::infinity();
    for (std::size_t p = 0; p < mass.size(); ++p) {
      per_radius = std::min(per_radius, mass[p] / x[p](1));
      innermost = std::min(innermost, x[p](1));
    }
    per_radius = over_ranks(per_radius);
    innermost = over_ranks(innermost);
    if (std::isfinite(per_radius) && std::isfinite(innermost) && innermost > 0.0)
      return {per_radius * innermost, innermost};
    return {};
  }
  /// The revolved body's.
  static double modelled_volume(const Geometry& g) { return volume(g); }
  static double estimated_seed_points(const Geometry& g, const Vec3& extent, const Vec3& h,
                                      const std::array<int, 3>& ppc) {
    return detail::planar_seed_points(meridian_area(g), extent, h, ppc);
  }
  static std::string form_problem(const Geometry& g) { return revolution_problem(g); }
  static bool moves_in_model(const Vec3& v) { return v(2) == 0.0 && v(1) == 0.0; }
  static constexpr std::string_view kExpectedMotion =
      "expected [v, 0, 0]: a body of revolution moves along its axis x";
};

struct PlaneStrainGrid {
  static constexpr GridGeometry kId = GridGeometry::plane_strain;
  static constexpr std::string_view kName = "plane_strain";
  static constexpr std::string_view kMeaning = "per metre along z";
  static constexpr int kMeshAxes = 2;
  template <int N>
  static constexpr int kNodesAlongZ = 1;
  static constexpr bool kHoop = false;
  static constexpr bool kRings = false;
  static constexpr bool kPerMetreOfThickness = true;
  static constexpr std::array<double, 3> kMomentumComponents = {1.0, 1.0, 1.0};
  static constexpr int kFacesRead = 4;
  static constexpr int kAxisFace = -1;
  /// Its cell share: the cell is 1 m along z.
  static double particle_volume(const Vec3& /*x*/, double cell_share) { return cell_share; }
  template <class Masses, class Positions, class Min>
  static LightNode light_node(const Masses& mass, const Positions& /*x*/, Min&& over_ranks) {
    return detail::lightest_particle(mass, over_ranks);
  }
  /// Per metre of thickness: the section's area times 1 m.
  static double modelled_volume(const Geometry& g) { return section_area(g) * 1.0; }
  static double estimated_seed_points(const Geometry& g, const Vec3& extent, const Vec3& h,
                                      const std::array<int, 3>& ppc) {
    return detail::planar_seed_points(section_area(g), extent, h, ppc);
  }
  static std::string form_problem(const Geometry& g) { return prism_problem(g); }
  static bool moves_in_model(const Vec3& v) { return v(2) == 0.0; }
  static constexpr std::string_view kExpectedMotion =
      "expected [vx, vy, 0]: a plane-strain body moves in the x-y plane";
};

/// The catalogue: T<every grid geometry>, in GridGeometry's order (the first is the default).
template <template <class...> class T>
using WithEveryGeometry = T<ThreeDGrid, AxisymmetricGrid, PlaneStrainGrid>;

/// A catalogued geometry: every member above, with its type (a struct missing one fails here).
template <class G>
concept CataloguedGeometry = requires(const Vec3& x, const Geometry& g,
                                      const std::array<int, 3>& ppc) {
  { G::kId } -> std::convertible_to<GridGeometry>;
  { G::kName } -> std::convertible_to<std::string_view>;
  { G::kMeaning } -> std::convertible_to<std::string_view>;
  { G::kMeshAxes } -> std::convertible_to<int>;
  { G::template kNodesAlongZ<3> } -> std::convertible_to<int>;
  { G::kHoop } -> std::convertible_to<bool>;
  { G::kRings } -> std::convertible_to<bool>;
  { G::kPerMetreOfThickness } -> std::convertible_to<bool>;
  { G::kMomentumComponents } -> std::convertible_to<std::array<double, 3>>;
  { G::kFacesRead } -> std::convertible_to<int>;
  { G::kAxisFace } -> std::convertible_to<int>;
  { G::kExpectedMotion } -> std::convertible_to<std::string_view>;
  { G::particle_volume(x, 1.0) } -> std::same_as<double>;
  {
    G::light_node(std::vector<double>{}, std::vector<Vec3>{}, [](double v) { return v; })
    } -> std::same_as<LightNode>;
  { G::modelled_volume(g) } -> std::same_as<double>;
  { G::estimated_seed_points(g, x, x, ppc) } -> std::same_as<double>;
  { G::form_problem(g) } -> std::same_as<std::string>;
  { G::moves_in_model(x) } -> std::same_as<bool>;
};

namespace detail {
// A static_assert, not a constrained pack: a constrained template passed to WithEveryGeometry's
// template template parameter is not portable (P0522 matching).
template <class... G>
struct GeometryList {
  static_assert((CataloguedGeometry<G> && ...), "a grid geometry lacks a catalogue member");
  using type = std::tuple<G...>;
};
}  // namespace detail

using GridGeometries = WithEveryGeometry<detail::GeometryList>::type;
inline constexpr std::size_t kGeometryCount = std::tuple_size_v<GridGeometries>;

/// The struct of geometry G (compile time: the shapes' OnGrid<G, N>).
template <GridGeometry G>
using GeometryOf = std::tuple_element_t<static_cast<std::size_t>(G), GridGeometries>;

/// The data members of one geometry as a run-time value.
struct GeometryFacts {
  GridGeometry id;
  std::string_view name, meaning;
  int mesh_axes;
  bool hoop, rings, per_metre_of_thickness;
  std::array<double, 3> momentum_components;
  int faces_read, axis_face;
  std::string_view expected_motion;
  /// A 2D grid: z is one cell of 1 m, not an axis of the mesh.
  constexpr bool planar() const { return mesh_axes < 3; }
  /// Face f (kFaceNames order) bounds the modelled domain: the reader takes its condition and it
  /// is not the axis (face_reach, fitted_range).
  constexpr bool is_domain_face(int f) const { return f < faces_read && f != axis_face; }
};

template <CataloguedGeometry G>
constexpr GeometryFacts facts_of() {
  return {G::kId,
          G::kName,
          G::kMeaning,
          G::kMeshAxes,
          G::kHoop,
          G::kRings,
          G::kPerMetreOfThickness,
          G::kMomentumComponents,
          G::kFacesRead,
          G::kAxisFace,
          G::kExpectedMotion};
}

namespace detail {
template <class... G>
struct FactsTable {
  static constexpr std::array<GeometryFacts, sizeof...(G)> kRows{facts_of<G>()...};
};
}  // namespace detail

/// One row per catalogue line, indexed by GridGeometry.
inline constexpr auto kGeometryFacts = WithEveryGeometry<detail::FactsTable>::kRows;

// The enum and the catalogue agree: row i is the struct whose kId is GridGeometry(i); names unique.
static_assert([] {
  for (std::size_t i = 0; i < kGeometryFacts.size(); ++i) {
    if (kGeometryFacts[i].id != static_cast<GridGeometry>(i)) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (kGeometryFacts[j].name == kGeometryFacts[i].name) return false;
  }
  return true;
}());

/// The catalogue's first line: a scene without grid.geometry, and the shapes' default argument.
inline constexpr GridGeometry kDefaultGeometry = kGeometryFacts[0].id;

/// The facts of geometry g: an array load, not a switch (cheap in contact's per-node loop).
constexpr const GeometryFacts& facts(GridGeometry g) {
  assert(static_cast<std::size_t>(g) < kGeometryFacts.size());  // the reader makes no other
  return kGeometryFacts[static_cast<std::size_t>(g)];
}

/// Every name, in catalogue order (the reader's choice; the first is the default).
inline std::vector<std::string_view> geometry_names() {
  std::vector<std::string_view> names;
  for (const GeometryFacts& f : kGeometryFacts) names.push_back(f.name);
  return names;
}

/// The geometry called `name`, or nothing.
constexpr std::optional<GridGeometry> geometry_named(std::string_view name) {
  for (const GeometryFacts& f : kGeometryFacts)
    if (f.name == name) return f.id;
  return std::nullopt;
}

/// grid.geometry's meaning for the key tables: the default, then the 2D grids with theirs.
inline std::string geometry_description() {
  std::string text(kGeometryFacts[0].name);
  text.append(", or a 2D grid in the x-y plane: ");
  bool first = true;
  for (const GeometryFacts& f : kGeometryFacts) {
    if (!f.planar()) continue;
    if (!first) text.append(" or ");
    text.append(f.name).append(" (").append(f.meaning).append(")");
    first = false;
  }
  return text;
}

namespace detail {
template <class First, class... Rest, class F>
decltype(auto) visit_in(GridGeometry g, F&& f) {
  if constexpr (sizeof...(Rest) > 0)
    if (g != First::kId) return visit_in<Rest...>(g, std::forward<F>(f));
  return std::forward<F>(f)(First{});
}
template <class... G>
struct Visit {
  template <class F>
  static decltype(auto) apply(GridGeometry g, F&& f) {
    return visit_in<G...>(g, std::forward<F>(f));
  }
};
}  // namespace detail

/// f(GeometryStruct{}) for the geometry g: the one run-time dispatch (as std::visit for a
/// variant). Every f(G{}) must return one type.
template <class F>
decltype(auto) visit_geometry(GridGeometry g, F&& f) {
  assert(static_cast<std::size_t>(g) < kGeometryCount);  // else the last line is visited
  return WithEveryGeometry<detail::Visit>::apply(g, std::forward<F>(f));
}

/// The shape templates' arguments (shape/shape.hpp, tests).
inline constexpr GridGeometry kAxisymmetric = GridGeometry::axisymmetric;
inline constexpr GridGeometry kPlaneStrain = GridGeometry::plane_strain;

}  // namespace impact::mpm
