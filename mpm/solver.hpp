// The solver loop: a Simulation owns particles, grid and ledger and advances them one explicit
// step at a time (advance() in solver.cpp is the whole step on one screen); run() wraps it with
// output, progress and failure handling. No global state: everything hangs off the Scene.
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "mpm/grid/grid.hpp"
#include "mpm/ledger/ledger.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/shape/shape.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

/// A run that cannot go on: the message names step, time, particle, material and field.
class SolverFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Wall time of each phase of the last step [s] (omp_get_wtime; for the benchmark's profile).
struct PhaseTimes {
  double particles_to_grid = 0, grid_update = 0, grid_to_particles = 0, remap = 0, stress = 0;
};

/// One step's totals, for the ledger and for tests.
struct StepTotals {
  GridUpdate grid;
  ParticleTotals particles;
  StressTotals stress;
  PhaseTimes seconds;
};

class Simulation {
 public:
  /// Seeds the particles and builds the grid; `threads` <= 0 keeps OpenMP's default.
  explicit Simulation(const Scene& scene, int threads = 0);
  Simulation(const Simulation&) = delete;  // models_ points into scene_
  Simulation& operator=(const Simulation&) = delete;

  /// Re-reads E0, p0 and the signal speed after a caller changed particle fields at t = 0 (tests
  /// that prescribe a velocity field, e.g. a vibration mode).
  void restart_ledger();

  /// Advances one step with the stable dt (bounded by the scene's time block); throws
  /// SolverFailure on NaN/Inf, a particle leaving the grid, a failed update, dt < min_dt, or
  /// energy growth beyond time.max_energy_growth (thrown after the step is booked: time(),
  /// steps() and the ledger then show the step that grew).
  const StepTotals& step();
  /// The dt the next step() will use.
  double next_dt() const;

  const Scene& scene() const { return scene_; }
  Particles& particles() { return particles_; }
  const Particles& particles() const { return particles_; }
  const Grid& grid() const { return grid_; }
  const Ledger& ledger() const { return ledger_; }
  double time() const { return time_; }
  long steps() const { return steps_; }
  bool finished() const { return time_ >= scene_.time.max_time * (1.0 - 1e-12); }
  int threads() const { return grid_.threads(); }
  long failed_particles() const { return failed_; }        ///< failures so far
  long converted_particles() const { return converted_; }  ///< moved to a companion field

 private:
  Scene scene_;
  Particles particles_;
  Grid grid_;
  std::variant<LinearShape, GimpShape> shape_;
  std::variant<Stencils<LinearShape>, Stencils<GimpShape>> stencils_;  ///< reused every step
  StressUpdateSettings stress_settings_;
  std::vector<double> specific_heat_;  ///< per material, for friction heating
  Ledger ledger_;
  /// Ledger sink columns registered for this scene's physics (-1: not registered).
  struct SinkColumns {
    int viscous = -1, contact = -1, friction = -1, eroded = -1;
  } sinks_;
  long failed_ = 0, converted_ = 0;
  StepTotals last_;
  double time_ = 0.0;
  long steps_ = 0;
  double max_signal_speed_ = 0.0;
};

struct RunOptions {
  std::string out_dir;    ///< empty: the scene's output.directory
  int threads = 0;        ///< <= 0: OpenMP default
  bool progress = false;  ///< a progress line on stderr
};

/// Runs a scene to its end time writing history.csv, snapshots, summary.json and the resolved
/// scene. Returns 0, or 3 after a SolverFailure (reported on stderr, final snapshot written).
int run(const Scene& scene, const RunOptions& options);

/// What `mpm check` prints after the resolved scene: per-object counts, mass, particle volume
/// against the exact geometric volume, estimated steps and memory.
Json check_report(const Scene& scene, int threads);

}  // namespace impact::mpm
