#include "mpm/scene/rigid_surface.hpp"

#include <cmath>
#include <type_traits>

#include "mpm/scene/object_overlap.hpp"

namespace impact::mpm {

namespace {

// The faces of the grid a body continues through as its image: `symmetric` and `wall` faces
// that do not move, along an axis the body does not move along.
struct MirrorFaces {
  bool lower[3] = {}, upper[3] = {};
  double plane_lower[3] = {}, plane_upper[3] = {};
  double tolerance[3] = {};  ///< [m] 1e-9 of the cell
};

MirrorFaces mirror_faces(const GridSpec& s, const Vec3& V) {
  MirrorFaces m;
  const Vec3 h = s.smallest_cell();
  for (int d = 0; d < s.dimensions(); ++d) {
    const auto mirrors = [&](int f) {
      const FaceCondition c = s.faces[std::size_t(f)];
      return (c == FaceCondition::symmetric || c == FaceCondition::wall) &&
             !s.face_velocity[std::size_t(f)].set && V(d) == 0.0;
    };
    m.lower[d] = mirrors(2 * d);
    m.upper[d] = mirrors(2 * d + 1);
    m.plane_lower[d] = s.lower(d);
    m.plane_upper[d] = s.upper(d);
    m.tolerance[d] = 1e-9 * h(d);
  }
  return m;
}

// A segment [a, b] along axis d continued by its image through the mirror faces it reaches.
void continue_segment(const MirrorFaces& m, int d, double& a, double& b) {
  const bool a_low = a <= b;
  double& lo = a_low ? a : b;
  double& hi = a_low ? b : a;
  const double lo0 = lo, hi0 = hi;
  if (m.lower[d] && lo0 <= m.plane_lower[d] + m.tolerance[d]) lo = 2.0 * m.plane_lower[d] - hi0;
  if (m.upper[d] && hi0 >= m.plane_upper[d] - m.tolerance[d]) hi = 2.0 * m.plane_upper[d] - lo0;
}

Geometry continued(const Geometry& g, const MirrorFaces& m) {
  return std::visit(
      [&](const auto& s) -> Geometry {
        using T = std::decay_t<decltype(s)>;
        T c = s;
        if constexpr (std::is_same_v<T, Box>) {
          for (int d = 0; d < 3; ++d) continue_segment(m, d, c.lower(d), c.upper(d));
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          // Its ends are faces only where its axis runs along a grid axis.
          const Vec3 e = (s.top - s.bottom).normalized();
          for (int d = 0; d < 3; ++d)
            if (std::abs(std::abs(e(d)) - 1.0) < 1e-12)
              continue_segment(m, d, c.bottom(d), c.top(d));
        } else if constexpr (std::is_same_v<T, HollowCylinder>) {
          // Its open end, and its bottom too where it has no cap; its cap is a body's end.
          const Vec3 e = (s.top - s.bottom).normalized();
          for (int d = 0; d < 3; ++d) {
            if (!(std::abs(std::abs(e(d)) - 1.0) < 1e-12)) continue;
            continue_segment(m, d, c.bottom(d), c.top(d));
            if (s.cap_thickness > 0.0) c.bottom(d) = s.bottom(d);
          }
        } else if constexpr (std::is_same_v<T, Union>) {
          for (Geometry& part : c.parts) part = continued(part, m);
        }
        // A sphere has no plane face.
        return Geometry{c};
      },
      g.shape);
}

}  // namespace

std::vector<std::optional<Geometry>> rigid_field_surfaces(const Scene& scene) {
  if (!scene.has_rigid_objects()) return {};
  std::vector<std::optional<Geometry>> surface(static_cast<std::size_t>(scene.field_count()));
  std::vector<bool> cut(surface.size(), false);
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const SceneObject& o = scene.objects[oi];
    if (!o.rigid) continue;
    const std::size_t f = std::size_t(scene.parent_field(o.material));
    // Cut by an object of another field (one of its own field's parts is its body too: several
    // rigid boxes of one material make one bowl, and their union is what is seeded).
    const ObjectOverlap overlap = object_overlap(scene, oi);
    for (const std::size_t a : overlap.by)
      if (std::size_t(scene.parent_field(scene.objects[a].material)) != f) cut[f] = true;
    const Geometry part = continued(o.geometry, mirror_faces(scene.grid, o.velocity));
    surface[f] = surface[f] ? Geometry{Union{{*surface[f], part}}} : part;
  }
  for (std::size_t f = 0; f < surface.size(); ++f)
    if (cut[f]) surface[f].reset();
  return surface;
}

}  // namespace impact::mpm
