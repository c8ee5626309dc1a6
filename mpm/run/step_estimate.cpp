#include "mpm/run/step_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "models/core/input.hpp"
#include "mpm/run/memory.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

namespace {

// What sets the body-force step: gravity alone, or with the objects' body forces at t = 0.
std::string body_force_name(const Scene& scene) {
  return scene.has_body_force() ? "solver.gravity + the largest objects.<name>.body_force"
                                : "solver.gravity";
}

// Usual values of the factors of the count (a shipped scene: about 1e4 steps), against which the
// key that drives an absurd count is found.
constexpr double kUsualMaxTime = 1e-3;    // [s]
constexpr double kUsualMultiplier = 0.5;  // [-]
constexpr double kUsualCell = 1e-3;       // [m]
constexpr double kUsualSignal = 6000.0;   // [m/s]
constexpr double kUsualMaxDt = 1e-7;      // [s]
// One core's speed on the recommended deck (docs/performance.md: 1.9-2.4e6), for the time a
// refused particle-step count would take.
constexpr double kOneCoreParticleStepsPerSecond = 2e6;  // [1/s]

// A count for a message: "1.2e+37", or beyond the doubles.
std::string count_text(double n) {
  std::ostringstream o;
  o.precision(2);
  if (std::isinf(n)) {
    o << "more than 1.8e+308";
  } else if (n < 1e6) {  // a count a person reads whole: 512, not 5.1e+02
    o << std::llround(n);
  } else {
    o << n;
  }
  return o.str();
}

std::string driver_of(const Scene& scene, const StepEstimate& e) {
  struct Factor {
    double times_usual;
    std::string key;
  };
  const TimeSpec& t = scene.time;
  std::ostringstream text;
  text.precision(3);
  std::vector<Factor> factors;
  const auto add = [&](double times_usual, const auto&... parts) {
    text.str("");
    (text << ... << parts);
    factors.push_back({times_usual, text.str()});
  };
  add(t.max_time / kUsualMaxTime, "time.max_time (", t.max_time, " s)");
  if (e.capped) {
    add(kUsualMaxDt / t.max_dt, "time.max_dt (", t.max_dt, " s)");
  } else if (e.gravity_limited) {
    add(kUsualMultiplier * kUsualCell / kUsualSignal / e.dt, body_force_name(scene), " (",
        scene.body_force_at_start(), " m/s^2)");
  } else {
    add(kUsualMultiplier / t.multiplier, "time.multiplier (", t.multiplier, ")");
    add(kUsualCell / scene.grid.min_spacing(), "grid.cells (the smallest cell ",
        scene.grid.min_spacing(), " m)");
    const SceneObject& o = scene.objects[e.fastest];
    const double speed = o.velocity.norm();
    if (e.wave_speed >= speed) {
      // The density is named with its value: a density of 1e-30 is the usual cause, set in the
      // material file or in the scene's overrides of it.
      const SceneMaterial& m = scene.materials[o.material];
      add(e.signal_speed / kUsualSignal, "/materials/", pointer_token(m.name), " (its density ",
          m.material.model.params().density, " kg/m^3, from its file or overrides/density, and ",
          "moduli give a wave speed of ", e.wave_speed, " m/s)");
    } else {
      add(e.signal_speed / kUsualSignal, "/objects/", pointer_token(o.name), "/velocity (", speed,
          " m/s)");
    }
  }
  const Factor* largest = &factors.front();
  for (const Factor& f : factors)
    if (f.times_usual > largest->times_usual) largest = &f;
  return largest->key;
}

}  // namespace

StepEstimate estimate_steps(const Scene& scene) {
  StepEstimate e;
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const SceneObject& o = scene.objects[oi];
    const ElasticPlastic& model = scene.materials[o.material].material.model;
    // A rigid object carries no wave; what it pushes moves at up to c + |V| (Scene::rigid_speed).
    const double c = o.rigid ? 0.0 : model.wave_speed(model.initial_state(o.temperature));
    const double signal = c + o.velocity.norm() + scene.rigid_speed();
    if (signal > e.signal_speed) {  // NaN (no wave speed) is skipped
      e.signal_speed = signal;
      e.fastest = oi;
      e.wave_speed = c;
    }
  }
  const double waves =
      stable_time_step(scene.grid.min_spacing(), e.signal_speed, scene.time.multiplier);
  const double body = body_force_time_step(scene.grid.min_spacing(), scene.body_force_at_start(),
                                           scene.time.multiplier);
  e.gravity_limited = body < waves;
  const double stable = std::min(waves, body);
  e.capped = scene.time.max_dt < stable;
  e.dt = e.capped ? scene.time.max_dt : stable;
  e.steps = std::isinf(e.dt) ? 0.0 : std::ceil(scene.time.max_time / e.dt);
  if (!scene.objects.empty()) e.driver = driver_of(scene, e);
  e.particles = estimated_particle_count(scene);
  e.particle_steps = e.particles * e.steps;
  return e;
}

Json StepEstimate::json(const Scene& scene) const {
  Json j = {{"estimated_steps", steps},
            {"stable_dt [s]", dt},
            {"fastest_signal [m/s]", signal_speed},
            {"max_estimated_steps", scene.time.max_estimated_steps},
            {"estimated_particle_steps", particle_steps},
            {"max_estimated_particle_steps", scene.time.max_estimated_particle_steps}};
  if (!scene.objects.empty()) j["fastest_object"] = scene.objects[fastest].name;
  return j;
}

namespace {

// The particle-steps bound: the particles the geometry seeds times the steps.
std::string particle_step_refusal(const Scene& scene, const StepEstimate& e) {
  const TimeSpec& t = scene.time;
  if (!(e.particle_steps > t.max_estimated_particle_steps)) return {};
  const GridSpec& g = scene.grid;
  std::ostringstream m;
  m.precision(3);
  m << "refusing to start: an estimated " << count_text(e.particle_steps) << " particle-steps ("
    << count_text(e.particles) << " particles estimated from the geometry on " << g.cells[0]
    << " x " << g.cells[1] << " x " << g.cells[2] << " cells (grid.cells, the objects' "
    << "particles_per_cell) x " << count_text(e.steps) << " steps; at "
    << kOneCoreParticleStepsPerSecond << " particle-steps/s, one core's speed "
    << "(docs/performance.md), about " << e.particle_steps / kOneCoreParticleStepsPerSecond
    << " s) exceed time.max_estimated_particle_steps = " << t.max_estimated_particle_steps
    << "; coarsen grid.cells" << g.refinement_advice()
    << " or lower particles_per_cell, or raise time.max_estimated_particle_steps to run the "
       "scene anyway";
  return m.str();
}

// "sqrt(time.multiplier 0.5 x the smallest cell 0.005 m / solver.gravity 1e+12 m/s^2)": how the
// body-force step comes about, for the refusals.
std::string body_force_step_text(const Scene& scene) {
  std::ostringstream m;
  m.precision(3);
  m << "sqrt(time.multiplier " << scene.time.multiplier << " x the smallest cell "
    << scene.grid.min_spacing() << " m / " << body_force_name(scene) << " "
    << scene.body_force_at_start() << " m/s^2)";
  return m.str();
}

// "time.multiplier 0.5 x the smallest cell 0.0005 m / the fastest signal 6123 m/s, the wave
// speed ... of object block": how the wave step comes about, for the refusals.
std::string wave_step_text(const Scene& scene, const StepEstimate& e) {
  const SceneObject& o = scene.objects[e.fastest];
  std::ostringstream m;
  m.precision(3);
  m << "time.multiplier " << scene.time.multiplier << " x the smallest cell "
    << scene.grid.min_spacing() << " m / the fastest signal " << e.signal_speed
    << " m/s, the wave speed " << e.wave_speed << " m/s of material "
    << scene.materials[o.material].name << " plus the speed " << o.velocity.norm()
    << " m/s of object " << o.name;
  return m.str();
}

}  // namespace

std::string step_refusal(const Scene& scene) {
  const StepEstimate e = estimate_steps(scene);
  const TimeSpec& t = scene.time;
  // Gravity is constant: a body-force step below time.min_dt would stop the run at its first
  // step, blaming the fastest particle's signal. Say so before anything is seeded.
  if (e.gravity_limited && !e.capped && e.dt < t.min_dt) {
    std::ostringstream m;
    m.precision(3);
    m << "refusing to start: the body-force step " << body_force_step_text(scene) << " = " << e.dt
      << " s is below time.min_dt = " << t.min_dt
      << " s, so the run would stop at its first step; lower " << body_force_name(scene)
      << " or time.min_dt";
    return m.str();
  }
  // Likewise a wave step below it: `mpm check` passed time.min_dt 1 s, and the run stopped at
  // step 1.
  if (!e.gravity_limited && !e.capped && e.dt < t.min_dt && !scene.objects.empty()) {
    std::ostringstream m;
    m.precision(3);
    m << "refusing to start: the stable time step (" << wave_step_text(scene, e) << ") = " << e.dt
      << " s is below time.min_dt = " << t.min_dt
      << " s, so the run would stop at its first step; lower time.min_dt";
    return m.str();
  }
  if (!(e.steps > t.max_estimated_steps)) return particle_step_refusal(scene, e);
  std::ostringstream m;
  m.precision(3);
  m << "refusing to start: an estimated " << count_text(e.steps) << " steps (time.max_time "
    << t.max_time << " s over a first step of " << e.dt << " s: ";
  if (e.capped) {
    m << "time.max_dt, below the stable step";
  } else if (e.gravity_limited) {
    m << body_force_step_text(scene)
      << ", the step in which the body force alone carries a particle that far";
  } else {
    m << wave_step_text(scene, e);
  }
  m << ") exceed time.max_estimated_steps = " << t.max_estimated_steps
    << "; the key that drives the count: " << e.driver
    << "; correct it, or raise time.max_estimated_steps to run the scene anyway";
  return m.str();
}

std::string start_refusal(const Scene& scene) {
  std::string refusal = memory_refusal(scene);
  return refusal.empty() ? step_refusal(scene) : refusal;
}

}  // namespace impact::mpm
