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
//
// On several ranks the particle moves between ranks: each step the rank holding it before the
// step contributes the start temperature, the rank holding it after the step the rest, and every
// rank keeps the whole path (one small all-gather per step, only when paths are asked for).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"

namespace impact::mpm {

class ParticlePaths {
 public:
  /// Picks, for every output.particle_paths entry, the particle of its object whose position in
  /// `initial` (the particles as seeded, those this rank holds: also for a restarted run, which
  /// must follow the particle the first run followed) is nearest to the entry's position; of
  /// equally near ones the lowest seed index. Collective on several ranks (`comm`).
  ParticlePaths(const Scene& scene, const Particles& initial, const Communicator& comm);

  /// A restarted run: the paths begin at the restored particles `P` (each track's start state
  /// becomes its particle's there; the particles were chosen by their seeded positions, as the
  /// first run chose them). Collective on several ranks.
  void begin_at(const Particles& P);

  bool empty() const { return tracks_.empty(); }
  /// The seed index of path i's particle (scene order).
  std::size_t particle(std::size_t i) const { return tracks_[i].id; }
  /// Call before Simulation::step(): remembers the start-of-step temperatures.
  void before_step(const Particles& P);
  /// Call after it, with the new time and the step length [s] (collective on several ranks).
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
    std::uint64_t id = 0;  ///< the particle's seed index
    std::size_t held = 0;  ///< its index here when this rank held it last (a hint)
    PointState start;      ///< state when recording began (t = 0, or the restart)
    bool pending = false;  ///< this rank held it before the step
    double pending_temperature = 0.0;
    std::vector<Step> steps;
  };
  /// Where track t's particle is in P, or P.size() when this rank does not hold it.
  std::size_t find(Track& t, const Particles& P) const;

  std::vector<Track> tracks_;
  const Communicator& comm_;
};

}  // namespace impact::mpm
