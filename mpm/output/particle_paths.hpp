// Particle paths (output.particle_paths, docs/scenes.md): the strain and temperature history of
// chosen particles, written at the end of the run as a point-driver path file, so that a material
// law can be unit-tested along the path it really followed inside an impact (`pointdriver run
// DIR/paths/<name>.json` replays it with the same law, models/).
//
// Per step the particle's velocity gradient L (the one its stress update used), the step length
// and its start-of-step temperature (which includes the heat the solver adds: artificial
// viscosity, friction) become one leg: {"duration": dt, "steps": 1, "velocity_gradient": L,
// "thermal": "isothermal", "start_temperature": T_n}. The driver then calls the same
// ElasticPlastic::update with the same L, dt and T_n; F is advanced by exp(L dt) in the driver,
// which is the MPM's own update with solver.deformation_gradient = exponential (forward Euler
// differs by O((L dt)^2) per step). Beside the path: <name>.material.json (the resolved material,
// scene overrides and physics flags applied) and <name>.csv (the particle's MPM state after every
// step, SI units) to compare the replay with.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "mpm/particles/particles.hpp"

namespace impact::mpm {

class ParticlePaths {
 public:
  /// Picks, for every output.particle_paths entry, the particle of its object whose initial
  /// position is nearest to the entry's position.
  ParticlePaths(const Scene& scene, const Particles& initial);

  bool empty() const { return tracks_.empty(); }
  /// The particle index of path i (scene order).
  std::size_t particle(std::size_t i) const { return tracks_[i].particle; }
  /// Call before Simulation::step(): remembers the start-of-step temperatures.
  void before_step(const Particles& P);
  /// Call after it, with the new time and the step length [s].
  void after_step(const Particles& P, double time, double dt);
  /// Writes DIR/paths/<name>.json, <name>.material.json and <name>.csv for every path.
  void write(const std::filesystem::path& dir, const Scene& scene, const std::string& scene_file,
             double start_time) const;

 private:
  struct Step {
    double time, dt, start_temperature;
    Mat3 L;
    PointState end;
  };
  struct Track {
    std::string name;
    std::size_t particle = 0;
    PointState start;  ///< state when recording began (t = 0, or the restart)
    double pending_temperature = 0.0;
    std::vector<Step> steps;
  };
  std::vector<Track> tracks_;
};

}  // namespace impact::mpm
