// The scene's body forces (SceneObject::body_force, docs/scenes.md#expressions): b_p = b(X_p, t)
// per unit mass at each particle's reference position X_p, evaluated once a step before
// particles-to-grid, which adds m_p b_p S_Ip to the nodal force; grid-to-particles books its work
// at the velocity the nodes keep, as grid_update books gravity's (step.hpp).
#pragma once

#include <optional>
#include <vector>

#include "mpm/particles/particles.hpp"
#include "mpm/scene/expression.hpp"

namespace impact::mpm {

class BodyForces {
 public:
  /// One compiled copy of each object's field per thread (muParser evaluates in its parser).
  BodyForces(const Scene& scene, int threads);

  /// b_p = b(X_p, t) for every particle (Particles::X) into values(), and its largest norm.
  void evaluate(const Particles& P, double t);
  /// Per particle [m/s^2], in particle order.
  const std::vector<Vec3>& values() const { return b_; }
  /// max_p |b_p| of the last evaluate() [m/s^2] (the body-force time step's; a removed particle
  /// counts as 0).
  double peak() const { return peak_; }
  /// The particle with the largest |b_p| of the last evaluate() (a non-finite b_p counts as the
  /// largest), and whether its b_p is finite.
  std::size_t strongest() const { return strongest_; }
  bool finite() const { return finite_; }

 private:
  std::vector<std::vector<std::optional<VectorField>>> fields_;  // [thread][object]
  std::vector<Vec3> b_;
  double peak_ = 0.0;
  std::size_t strongest_ = 0;
  bool finite_ = true;
};

}  // namespace impact::mpm
