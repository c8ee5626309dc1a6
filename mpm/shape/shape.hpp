// The shape functions behind one small interface, chosen once per run (no per-particle branch):
// every phase is a template on the shape and is instantiated for each shape of the catalogue.
// A shape is a struct with
//   - kName (the scene's solver.interpolation) and kMeaning (for messages),
//   - N, the nodes per axis of its stencil, and at(x, object, half_width) -> Stencil<N>
//     (half_width: the particle's own [m] on a graded grid, Particles::half_width, else null),
//   - OnGrid<G, N> as a base: the grid geometry it serves (NZ nodes along z, hoop terms),
//   - make(scene), which builds it for a scene;
// and its line in WithEveryShape below, which puts it on every grid geometry of the catalogue
// (scene/grid_geometry.hpp). docs/extending.md walks through adding one.
#pragma once

#include <algorithm>
#include <memory>
#include <string_view>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "mpm/scene/seed_points.hpp"
#include "mpm/shape/gimp.hpp"
#include "mpm/shape/linear.hpp"
#include "mpm/shape/tartan.hpp"

namespace impact::mpm {

/// A graded grid's node coordinates, shared by the copies of a shape (null: a uniform grid, and
/// the shape's own uniform arithmetic, bit for bit).
using GradedAxes = std::shared_ptr<const std::array<GradedAxis, 3>>;
inline GradedAxes graded_axes(const Scene& scene) {
  if (!scene.grid.graded()) return nullptr;
  return std::make_shared<const std::array<GradedAxis, 3>>(scene.grid.axes);
}

/// The stencil's reach along z on a grid of geometry G: 3D, or the single node plane k = 0 of a
/// 2D grid (weight 1, no gradient along z: no strain out of the plane but the hoop term).
template <int N>
inline void flatten_z(Stencil<N>& s) {
  s.base[2] = 0;
  for (int a = 0; a < N; ++a) s.w[2][a] = s.dw[2][a] = 0.0;
  s.w[2][0] = 1.0;
}

/// What every shape takes from its grid's geometry: NZ, the nodes along z its loops visit, and
/// kHoop, whether the axisymmetric hoop terms (Sulsky & Schreyer 1996 eqs. 14 and 20) apply:
///   f_I,r -= V_p sigma_tt,p S_Ip / r_p,   L_tt,p = sum_I S_Ip v_I,r / r_p.
template <GridGeometry G, int N>
struct OnGrid {
  using GridKind = GeometryOf<G>;  // not Geometry: that names the solid bodies
  static constexpr GridGeometry kGeometry = G;
  static constexpr int NZ = GridKind::template kNodesAlongZ<N>;
  static constexpr bool kHoop = GridKind::kHoop;
  /// Whether a node of zero weight always has a zero gradient too (then a gather may take a
  /// massless node's zero velocity without testing its mass: it adds exact zeros). Not for the
  /// linear hat, whose slope is -1/h at the node it has just left.
  static constexpr bool kSlopeVanishesWithWeight = false;
};

template <GridGeometry G = kDefaultGeometry>
struct LinearShape : OnGrid<G, 2> {
  static constexpr std::string_view kName = "linear";
  static constexpr std::string_view kMeaning =
      GeometryOf<G>::kMeshAxes == 3 ? "8-node trilinear" : "4-node bilinear";
  static constexpr int N = 2;  ///< nodes per axis: 8 in all (4 on a 2D grid)
  Vec3 lower, inv_dx;
  std::array<int, 3> cells;
  GradedAxes graded;  ///< a graded grid's axes (tartan.hpp), null when uniform
  Stencil<2> at(const Vec3& x, int /*object*/, const Vec3* /*half_width*/ = nullptr,
                bool* /*narrowed: no box, never*/ = nullptr) const {
    Stencil<2> s = graded ? tartan_linear_stencil(*graded, x)
                          : linear_stencil((x - lower).cwiseProduct(inv_dx), inv_dx, cells);
    if constexpr (GeometryOf<G>::kMeshAxes < 3) flatten_z(s);
    return s;
  }
  static LinearShape make(const Scene& scene) {
    return {{},
            scene.grid.lower,
            scene.grid.spacing().cwiseInverse(),
            scene.grid.cells,
            graded_axes(scene)};
  }
};

template <GridGeometry G = kDefaultGeometry>
struct GimpShape : OnGrid<G, 3> {
  static constexpr std::string_view kName = "gimp";
  static constexpr std::string_view kMeaning =
      GeometryOf<G>::kMeshAxes == 3 ? "27-node uGIMP" : "9-node uGIMP";
  static constexpr int N = 3;  ///< nodes per axis: 27 in all (9 on a 2D grid)
  static constexpr bool kSlopeVanishesWithWeight = true;  ///< S and dS/dr vanish at |r| = 1 + l
  Vec3 lower, inv_dx;
  std::array<int, 3> cells;
  std::vector<Vec3> half_width;  ///< per object, in cells (a uniform grid)
  GradedAxes graded;             ///< a graded grid's axes (tartan.hpp), null when uniform
  /// On a graded grid the particle's own half-width [m] (`own`, Particles::half_width, fixed at
  /// seeding); without it, the object's in cells of the cell x lies in. `narrowed` is set when
  /// the box had to be narrowed to its cells (tartan.hpp).
  Stencil<3> at(const Vec3& x, int object, const Vec3* own = nullptr,
                bool* narrowed = nullptr) const {
    Stencil<3> s = graded ? tartan_gimp_stencil(*graded, x, own ? *own : cell_half_width(x, object),
                                                narrowed, GeometryOf<G>::kMeshAxes)
                          : gimp_stencil((x - lower).cwiseProduct(inv_dx), inv_dx,
                                         half_width[object], cells, GeometryOf<G>::kMeshAxes);
    if constexpr (GeometryOf<G>::kMeshAxes < 3) flatten_z(s);
    return s;
  }
  static GimpShape make(const Scene& scene) {
    return {{},
            scene.grid.lower,
            scene.grid.spacing().cwiseInverse(),
            scene.grid.cells,
            half_widths(scene),
            graded_axes(scene)};
  }

 private:
  Vec3 cell_half_width(const Vec3& x, int object) const {
    Vec3 l;
    for (int d = 0; d < 3; ++d) {
      const GradedAxis& axis = (*graded)[std::size_t(d)];
      l(d) = half_width[object](d) * axis.size(axis.cell_of(x(d)));
    }
    return l;
  }
};

namespace detail {
// Shape S on every grid geometry, as a tuple of types.
template <template <GridGeometry> class S>
struct OnEveryGeometry {
  template <class... G>
  using type = std::tuple<S<G::kId>...>;
};
template <template <class...> class T, class Tuple>
struct Rebind;
template <template <class...> class T, class... X>
struct Rebind<T, std::tuple<X...>> {
  using type = T<X...>;
};
}  // namespace detail

/// T<every shape in Shapes on every grid geometry>, shape by shape.
template <template <class...> class T, template <GridGeometry> class... Shapes>
using ShapesOnEveryGeometry = typename detail::Rebind<
    T, decltype(std::tuple_cat(
           std::declval<WithEveryGeometry<detail::OnEveryGeometry<Shapes>::template type>>()...))>::
    type;

/// The catalogue: one name per shape (the first is the default), each on every grid geometry.
template <template <class...> class T>
using WithEveryShape = ShapesOnEveryGeometry<T, GimpShape, LinearShape>;

/// One of the shapes, as a run holds it.
using AnyShape = WithEveryShape<std::variant>;

namespace detail {
template <class... Shapes>
struct ShapeNames {
  static std::vector<std::string_view> get() {
    std::vector<std::string_view> names;
    ((std::find(names.begin(), names.end(), Shapes::kName) == names.end()
          ? void(names.push_back(Shapes::kName))
          : void()),
     ...);
    return names;
  }
};
template <class... Shapes>
struct MakeShape {
  static AnyShape by_name(const Scene& scene, std::string_view name) {
    AnyShape shape;
    ((name == Shapes::kName && scene.grid.geometry == Shapes::kGeometry
          ? void(shape = Shapes::make(scene))
          : void()),
     ...);
    return shape;
  }
};
template <class... Shapes>
struct StencilBytes {
  static std::size_t of(std::string_view name) {
    std::size_t bytes = 0;
    ((name == Shapes::kName ? void(bytes = sizeof(Stencil<Shapes::N>)) : void()), ...);
    return bytes;
  }
};
}  // namespace detail

/// Every shape's kName once, catalogue order (the scene reader's choice).
inline std::vector<std::string_view> shape_names() {
  return WithEveryShape<detail::ShapeNames>::get();
}
/// The shape scene.solver.interpolation names on the scene's grid geometry, built for the scene.
inline AnyShape make_shape(const Scene& scene) {
  return WithEveryShape<detail::MakeShape>::by_name(scene, scene.solver.interpolation);
}
/// The bytes of one particle's stencil with the shape `name` (the memory estimate).
inline std::size_t stencil_bytes(std::string_view name) {
  return WithEveryShape<detail::StencilBytes>::of(name);
}

}  // namespace impact::mpm
