// The shape functions behind one small interface, chosen once per run (no per-particle branch):
// every phase is a template on the shape and is instantiated for each shape of the catalogue.
// A shape is a struct with
//   - kName (the scene's solver.interpolation) and kMeaning (for messages),
//   - N, the nodes per axis of its stencil, and at(x, object) -> Stencil<N>,
//   - make(scene), which builds it for a scene;
// and one line in WithEveryShape below. docs/extending.md walks through adding one.
#pragma once

#include <string_view>
#include <variant>
#include <vector>

#include "mpm/scene/seed_points.hpp"
#include "mpm/shape/gimp.hpp"
#include "mpm/shape/linear.hpp"

namespace impact::mpm {

struct LinearShape {
  static constexpr std::string_view kName = "linear";
  static constexpr std::string_view kMeaning = "8-node trilinear";
  static constexpr int N = 2;  ///< nodes per axis: 8 in all
  Vec3 lower, inv_dx;
  std::array<int, 3> cells;
  Stencil<2> at(const Vec3& x, int /*object*/) const {
    return linear_stencil((x - lower).cwiseProduct(inv_dx), inv_dx, cells);
  }
  static LinearShape make(const Scene& scene) {
    return {scene.grid.lower, scene.grid.spacing().cwiseInverse(), scene.grid.cells};
  }
};

struct GimpShape {
  static constexpr std::string_view kName = "gimp";
  static constexpr std::string_view kMeaning = "27-node uGIMP";
  static constexpr int N = 3;  ///< nodes per axis: 27 in all
  Vec3 lower, inv_dx;
  std::array<int, 3> cells;
  std::vector<Vec3> half_width;  ///< per object, in cells
  Stencil<3> at(const Vec3& x, int object) const {
    return gimp_stencil((x - lower).cwiseProduct(inv_dx), inv_dx, half_width[object], cells);
  }
  static GimpShape make(const Scene& scene) {
    return {scene.grid.lower, scene.grid.spacing().cwiseInverse(), scene.grid.cells,
            half_widths(scene)};
  }
};

/// The catalogue: T<every shape>, one line per shape (the first is the default).
template <template <class...> class T>
using WithEveryShape = T<GimpShape, LinearShape>;

/// One of the shapes, as a run holds it.
using AnyShape = WithEveryShape<std::variant>;

namespace detail {
template <class... Shapes>
struct ShapeNames {
  static std::vector<std::string_view> get() { return {Shapes::kName...}; }
};
template <class... Shapes>
struct MakeShape {
  static AnyShape by_name(const Scene& scene, std::string_view name) {
    AnyShape shape;
    ((name == Shapes::kName ? void(shape = Shapes::make(scene)) : void()), ...);
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

/// Every shape's kName, catalogue order (the scene reader's choice).
inline std::vector<std::string_view> shape_names() {
  return WithEveryShape<detail::ShapeNames>::get();
}
/// The shape scene.solver.interpolation names, built for the scene.
inline AnyShape make_shape(const Scene& scene) {
  return WithEveryShape<detail::MakeShape>::by_name(scene, scene.solver.interpolation);
}
/// The bytes of one particle's stencil with the shape `name` (the memory estimate).
inline std::size_t stencil_bytes(std::string_view name) {
  return WithEveryShape<detail::StencilBytes>::of(name);
}

}  // namespace impact::mpm
