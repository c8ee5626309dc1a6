// The solver: a Simulation owns particles, grid and ledger and advances them one explicit step at
// a time (advance() in solver.cpp is the whole step on one screen); mpm/run/run.hpp drives it to
// the end time with outputs, checkpoints and failure handling. No global state: everything hangs
// off the Scene.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "mpm/grid/grid.hpp"
#include "mpm/ledger/ledger.hpp"
#include "mpm/parallel/box_decomposition.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/parallel/split_search.hpp"
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

class CheckpointWriter;
class CheckpointReader;

/// A fault planted on purpose (mpm run --inject-fault KIND:STEP[:PARTICLE], a developer option;
/// docs/mpm.md#fault-injection): shows that the detection and the clean stop work.
struct FaultInjection {
  enum class Kind {
    nan,           ///< the stress PARTICLE's update returns in step STEP is replaced by NaN
    nan_velocity,  ///< PARTICLE's velocity is set to NaN at the start of step STEP
    outside,       ///< PARTICLE is moved one cell beyond the grid's x+ face at the start of STEP
    jacobian,      ///< PARTICLE's F gets det F < 0 (first column negated) at the start of STEP
    sigterm,       ///< SIGTERM is raised after step STEP (mpm run's handler: checkpoint, stop)
    sigint,        ///< SIGINT likewise
  };
  Kind kind = Kind::nan;
  long step = 1;
  std::size_t particle = 0;
};
/// Parses "nan:STEP:PARTICLE", "nan_velocity:..", "outside:..", "jacobian:..", "sigterm:STEP",
/// "sigint:STEP" (STEP >= 1); nullopt when malformed.
std::optional<FaultInjection> parse_fault_injection(const std::string& text);

/// Wall time of each phase of the last step [s] (omp_get_wtime; for the benchmark's profile).
struct PhaseTimes {
  double particles_to_grid = 0, grid_update = 0, grid_to_particles = 0, remap = 0, stress = 0;

  /// Each phase with its name, in step order (for summaries).
  static constexpr std::pair<const char*, double PhaseTimes::*> kPhases[] = {
      {"particles_to_grid", &PhaseTimes::particles_to_grid},
      {"grid_update", &PhaseTimes::grid_update},
      {"grid_to_particles", &PhaseTimes::grid_to_particles},
      {"remap", &PhaseTimes::remap},
      {"stress", &PhaseTimes::stress}};
  PhaseTimes& operator+=(const PhaseTimes& o) {
    for (const auto& [name, phase] : kPhases) this->*phase += o.*phase;
    return *this;
  }
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
  /// Seeds the particles and builds the grid; `threads` <= 0 keeps OpenMP's default. With `comm`
  /// of several ranks (docs/mpi.md) the grid is split into boxes balanced by particle count
  /// (solver.ranks_per_axis per axis): this rank keeps its box's particles, sums the node layers
  /// it shares with its neighbours, and every total (ledger, time step, failures) is reduced over
  /// the ranks, so the ledger and the time step are the same on every rank.
  explicit Simulation(const Scene& scene, int threads = 0, const Communicator* comm = nullptr);
  Simulation(const Simulation&) = delete;  // stress_settings_.models points into scene_
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
  /// This process's rank and the boxes (one rank: rank 0 and one box).
  int rank() const { return comm_ ? comm_->rank() : 0; }
  int ranks() const { return comm_ ? comm_->size() : 1; }
  /// The ranks this run is on: null on one rank.
  const Communicator* communicator() const { return comm_ && comm_->size() > 1 ? comm_ : nullptr; }
  const BoxDecomposition& boxes() const { return boxes_; }
  /// Particles that moved to another rank in the last step.
  std::size_t migrated() const { return migrated_; }
  /// Times the boxes were re-balanced (solver.rebalance_above).
  long rebalances() const { return rebalances_; }
  /// Each phase's wall time summed over the steps this Simulation ran (on this rank) [s]: where a
  /// rank's time goes, and with several ranks which phase is out of balance (docs/mpi.md).
  const PhaseTimes& phase_totals() const { return phase_totals_; }
  long failed_particles() const { return failed_; }        ///< failures so far
  long converted_particles() const { return converted_; }  ///< moved to a companion field
  /// Particles flagged by physics.on_numerical_fault = fail_particle so far.
  long faulted_particles() const { return faulted_; }
  /// Particles that left the grid and were removed so far (grid.outflow = remove).
  long removed_particles() const { return removed_; }
  /// The particles flagged in the last step, and why (ascending index; fail_particle only).
  const std::vector<Failure>& last_faults() const { return last_.stress.faulted; }
  /// "step N, time T s: particle P (material, object, position, velocity, stress, eps_p, T, J,
  /// damage): field: message" for a failure in step N ending at time T.
  std::string describe(const Failure& f, long step, double time) const;

  /// Plants a fault (nan, nan_velocity, outside, jacobian) for a later step, on the particle of
  /// that seed index (whichever rank holds it then; collective on several ranks); throws
  /// std::out_of_range for an index out of range, std::invalid_argument for a signal kind.
  void inject(const FaultInjection& fault);

  /// Everything the next steps depend on (mpm/run/checkpoint.cpp): load() on a Simulation built
  /// from the same scene with the same thread count continues bit for bit.
  void save(CheckpointWriter& out) const;
  void load(CheckpointReader& in);
  /// Makes room for n particles (a checkpoint's count on this rank; every array the scene uses).
  void resize_particles(std::size_t n);

 private:
  /// The seed points per cell column of each object (ids) and per cell along each axis
  /// (balance): what several ranks seed their boxes from.
  struct SeedCensus {
    SeedCounts columns;
    SeedAxisCounts per_axis;
    /// This rank's block's points per cell, for the "least_loaded" search (else empty).
    std::vector<CellCount> cells;
  };
  static SeedCensus census(const Scene& scene, const Communicator& comm);
  /// The boxes of the ranks (solver.ranks_per_axis), balanced by the census.
  static BoxDecomposition split(const Scene& scene, const SeedCensus& census,
                                const Communicator& comm);

  Scene scene_;
  const Communicator* comm_ = nullptr;  ///< null on one rank
  SeedCensus census_;                   ///< while seeding (several ranks), then emptied
  BoxDecomposition boxes_;              ///< before the particles and the grid: both follow it
  Particles particles_;
  Grid grid_;
  AnyShape shape_;
  AnyStencils stencils_;        ///< reused every step
  ScatterOrder scatter_order_;  ///< rebuilt every step from the stencils
  StressUpdateSettings stress_settings_;
  std::vector<HeatCapacity> heat_capacity_;  ///< per material, for friction heating
  Ledger ledger_;
  /// Ledger sink columns registered for this scene's physics (-1: not registered).
  struct SinkColumns {
    int viscous = -1, friction = -1, eroded = -1;
  } sinks_;
  long failed_ = 0, converted_ = 0, faulted_ = 0, removed_ = 0;
  std::vector<FaultInjection> injections_;
  /// The particle loops' start-of-step check (positions inside the grid, velocities finite).
  void check_particles() const;
  /// Throws SolverFailure on every rank when any rank has a failure message: the lowest such
  /// rank's, which names the rank (one rank: throws `message` if any).
  void agree_on_failure(const std::optional<std::string>& message) const;
  /// Sums (and maxima) of a step's totals over the ranks.
  void reduce(StepTotals& t) const;
  std::optional<HaloExchange> halo_;
  std::size_t migrated_ = 0;
  long rebalances_ = 0;
  /// The nodes this rank's grid stores: its box's cells [c0, c1) per axis and the halo its
  /// particles' stencils, the shared-layer sums and the contact gradients reach,
  /// [c0 - kHaloPlanes, c1 + kHaloPlanes] (the whole grid on one rank).
  std::optional<NodeBox> stored_box() const;
  /// Builds this rank's grid for the current boxes (after a re-balance or a restart), keeping
  /// the settings the constructor gave it; sets the owned nodes (own_box).
  void rebuild_grid();
  /// This rank's nodes for the ledger (Grid::set_owned) from boxes_.
  void own_box();
  /// New boxes balanced by the current particle counts when the largest rank holds more than
  /// solver.rebalance_above times the mean, and the particles moved to them.
  void rebalance_if_needed();
  /// Applies the injections of the coming step.
  void apply_injections();
  StepTotals last_;
  PhaseTimes phase_totals_;
  double time_ = 0.0;
  long steps_ = 0;
  double max_signal_speed_ = 0.0;
};

}  // namespace impact::mpm
