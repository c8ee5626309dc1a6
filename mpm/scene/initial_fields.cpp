#include "mpm/scene/initial_fields.hpp"

#include <cmath>

#include "mpm/scene/seed_points.hpp"

namespace impact::mpm {

InitialVelocity::InitialVelocity(const Scene& scene, std::size_t object)
    : constant_(scene.objects[object].velocity) {
  const SceneObject& o = scene.objects[object];
  if (o.velocity_field.has_text()) field_.emplace(o.velocity_field, scene.constants);
}

InitialFields initial_fields(const Scene& scene, std::size_t object) {
  const SceneObject& o = scene.objects[object];
  const double rho = scene.materials[std::size_t(o.material)].material.model.params().density;
  const auto particle_volume = visit_geometry(
      scene.grid.geometry, [](auto geometry) { return &decltype(geometry)::particle_volume; });
  InitialVelocity v0(scene, object);
  std::optional<VectorField> b;
  if (o.has_body_force()) b.emplace(o.body_force, scene.constants);
  InitialFields s;
  const auto [lo, hi] = bounds(o.geometry);
  for_each_seed_point(scene, object, lo, hi, [&](const Vec3& x, int) {
    const Vec3 v = v0.at(x);
    if (!v.allFinite() && !s.non_finite_velocity) s.non_finite_velocity = x;
    for (int d = 0; d < 3; ++d)
      if (std::abs(v(d)) > std::abs(s.velocity_peak(d))) s.velocity_peak(d) = v(d);
    s.kinetic_energy +=
        0.5 * rho * particle_volume(x, seeded_cell_share(scene, object, x)) * v.squaredNorm();
    if (b) {
      const Vec3 f = (*b)(x, 0.0);
      if (!f.allFinite() && !s.non_finite_body_force) s.non_finite_body_force = x;
      const double norm = f.norm();  // inf beyond sqrt(max double): then the scaled norm
      s.body_force_peak =
          std::max(s.body_force_peak, std::isinf(norm) && f.allFinite() ? f.stableNorm() : norm);
    }
  });
  return s;
}

}  // namespace impact::mpm
