// An object's fields at t = 0 over its seed points (docs/scenes.md#expressions): the initial
// velocity (objects.<name>.velocity: three numbers, or expressions over the seed point X, Y, Z,
// the start of a manufactured solution, Wallstedt & Guilkey 2008) and the body force. Seeding reads
// the velocity point by point; the reader checks both fields where they are evaluated first (a
// NaN or an infinity is refused there, naming the point), and the estimates that take one value
// per object (time step, fitted strain rate, units check, the report's kinetic energy) read their
// summary.
#pragma once

#include <cstddef>
#include <optional>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// The initial velocity of one object at its seed points.
class InitialVelocity {
 public:
  InitialVelocity(const Scene& scene, std::size_t object);
  /// At seed point x [m/s].
  Vec3 at(const Vec3& x) { return field_ ? (*field_)(x, 0.0) : constant_; }

 private:
  Vec3 constant_;
  std::optional<VectorField> field_;
};

/// Over an object's seed points at t = 0.
struct InitialFields {
  /// Per component the velocity of largest magnitude, its sign kept [m/s].
  Vec3 velocity_peak = Vec3::Zero();
  /// 1/2 sum_p m_p |v_p|^2 [J; per metre or per radian on 2D grids, as the particle masses are].
  double kinetic_energy = 0.0;
  /// max_p |b(X_p, 0)| [m/s^2] (0 without a body force).
  double body_force_peak = 0.0;
  /// The first seed point whose velocity, or body force, is not finite.
  std::optional<Vec3> non_finite_velocity, non_finite_body_force;
};
InitialFields initial_fields(const Scene& scene, std::size_t object);

}  // namespace impact::mpm
