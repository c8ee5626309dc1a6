// The step count of a run, estimated from the scene alone before anything is seeded (mpm check
// prints it; mpm run refuses to start when it exceeds time.max_estimated_steps, exit 4;
// docs/mpm.md#memory-and-step-estimates): time.max_time over the first stable step, which is
// stable_time_step (mpm/step/time_step.cpp) of the smallest cell and the fastest signal
// max_objects (c0 + |v0|), c0 the longitudinal wave speed of the object's material in its initial
// state, or the body-force step sqrt(multiplier dx / abs(g)) where it is smaller, capped at
// time.max_dt. Every particle of an object starts with the same c0 and v0, so
// this is the first step the run takes. A density of 1e-30 kg/m^3, a multiplier of 1e-300 or a
// max_time of 1e30 s give 1e20 to 1e300 steps: a run that never finishes, refused at once. So is
// one whose particle-steps (particles estimated from the geometry x steps) exceed
// time.max_estimated_particle_steps: 100000 x 3 x 3 cells of a small block passed the step bound
// and showed an ETA of 8 days.
#pragma once

#include <cstddef>
#include <string>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

struct StepEstimate {
  double steps = 0.0;            ///< ceil(max_time / dt); 0 when no signal limits the step
  double dt = 0.0;               ///< the first stable step, capped at time.max_dt [s]
  double signal_speed = 0.0;     ///< the fastest signal c0 + |v0| [m/s]
  std::size_t fastest = 0;       ///< the object that carries it
  double wave_speed = 0.0;       ///< its material's initial longitudinal wave speed c0 [m/s]
  bool capped = false;           ///< time.max_dt is below the stable step
  bool gravity_limited = false;  ///< the body-force step (solver.gravity) is below the waves'
  double particles = 0.0;        ///< estimated from the geometry (estimated_particle_count)
  double particle_steps = 0.0;   ///< particles x steps: what the run's wall time scales with
  /// The key that drives the count: of max_time, multiplier, max_dt (when it caps), the smallest
  /// cell, the fastest material's wave speed and object's speed, the one furthest (as a factor)
  /// from its usual value (1e-3 s, 0.5, the stable step, 1e-3 m, 6000 m/s, 1000 m/s), with its
  /// value: "time.max_time (1e+30 s)".
  std::string driver;
  /// {"estimated_steps", "stable_dt [s]", "fastest_signal [m/s]", "fastest_object",
  ///  "max_estimated_steps", "estimated_particle_steps", "max_estimated_particle_steps"}: mpm
  ///  check's report.
  Json json(const Scene& scene) const;
};

StepEstimate estimate_steps(const Scene& scene);

/// Why `mpm run` must not start this scene (the estimate exceeds time.max_estimated_steps: the
/// count, how it comes about and the key that drives it; or the particle-steps exceed
/// time.max_estimated_particle_steps: a few steps of very many particles take as long as very
/// many steps), or empty. Seeds nothing.
std::string step_refusal(const Scene& scene);

/// What mpm run, mpm check and Python's check_scene test before seeding: memory_refusal
/// (mpm/run/memory.hpp), else step_refusal; empty when the scene may start.
std::string start_refusal(const Scene& scene);

}  // namespace impact::mpm
