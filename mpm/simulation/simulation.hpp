// The solver: a Simulation owns particles, grid and ledger and advances them one explicit step at
// a time (advance() in mpm/simulation/advance.hpp is the whole step on one screen; step() books it
// and asks the ranks, mpm/parallel/ranks.hpp, for what several ranks must agree on);
// mpm/run/run.hpp drives it to the end time with outputs, checkpoints and failure handling. No
// global state: everything hangs off the Scene.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "mpm/contact/rigid_particle_contact.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/ledger/ledger.hpp"
#include "mpm/parallel/box_decomposition.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/parallel/ranks.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/face_motion.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/shape/shape.hpp"
#include "mpm/simulation/fault_injection.hpp"
#include "mpm/simulation/step_totals.hpp"
#include "mpm/step/body_force.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

/// A run that cannot go on: the message names step, time, particle, material and field.
class SolverFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CheckpointWriter;
class CheckpointReader;

class Simulation {
 public:
  /// Seeds the particles and builds the grid; `threads` <= 0 keeps OpenMP's default. With `comm`
  /// of several ranks (docs/mpi.md) the grid is split into boxes balanced by particle count
  /// (solver.ranks_per_axis per axis): this rank keeps its box's particles, sums the node layers
  /// it shares with its neighbours, and every total (ledger, time step, failures) is reduced over
  /// the ranks, so the ledger and the time step are the same on every rank.
  Simulation(const Scene& scene, int threads, const Communicator& comm);
  /// This process alone (one rank).
  explicit Simulation(const Scene& scene, int threads = 0)
      : Simulation(scene, threads, Communicator::one_rank()) {}
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
  int rank() const { return ranks_.rank(); }
  int ranks() const { return ranks_.size(); }
  /// The ranks this run is on: null on one rank.
  const Communicator& communicator() const { return ranks_.communicator(); }
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
  /// Particle-steps whose uGIMP box was narrowed to its cells (a graded grid; shape/tartan.hpp).
  long narrowed_particle_steps() const { return narrowed_; }
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
  Scene scene_;
  Ranks ranks_;               ///< what several ranks agree on; the identity on one rank
  Ranks::SeedCensus census_;  ///< while seeding (several ranks), then emptied
  BoxDecomposition boxes_;    ///< before the particles and the grid: both follow it
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
    int viscous = -1, friction = -1, wall_friction = -1, eroded = -1, plastic = -1;
    int contact_energy = -1;   ///< stored, not a sink: the particles' contact with rigid objects
    int contact_damping = -1;  ///< its dashpots' dissipation (contact.penalty_damping)
  } sinks_;
  long failed_ = 0, converted_ = 0, faulted_ = 0, removed_ = 0, narrowed_ = 0;
  std::vector<FaultInjection> injections_;
  std::optional<HaloExchange> halo_;
  std::size_t migrated_ = 0;
  long rebalances_ = 0;

  /// The particle loops' start-of-step check: the first particle outside the grid or with a
  /// velocity that is not finite, described (nullopt: none).
  std::optional<std::string> particle_outside_or_not_finite() const;
  /// The particle whose body force (of this step) is not finite, described with its object's
  /// expressions, reference position and time (nullopt: none).
  std::optional<std::string> non_finite_body_force() const;
  /// The stable dt of the coming step, landing on max_time; a diagnosis naming the particle with
  /// the fastest signal when it falls below time.min_dt (every rank gets the same dt).
  double checked_dt() const;
  /// The step itself (advance() with this Simulation's shape); `failure` set when a particle
  /// failed.
  StepTotals advance_step(double dt, std::optional<Failure>& failure);
  /// Books the step's totals: time, ledger row and sinks, outflow, failure counters.
  void book(double dt);
  /// Throws SolverFailure with the message every rank agreed on, if any.
  void stop_if(const std::optional<std::string>& message) const;
  /// Builds this rank's grid for the current boxes (after a re-balance or a restart), keeping
  /// the settings the constructor gave it; sets the owned nodes.
  void rebuild_grid();
  /// What the grid is given (at construction; the same to a rebuilt grid): threads, fields and
  /// their contact bodies, the light-node masses (collective: minima over the ranks), the
  /// particles' half-widths for the wall faces. Reads scene_, ranks_ and particles_.
  GridSettings grid_settings(int threads) const;
  /// New boxes when the ranks' particle counts drifted (solver.rebalance_above), and the
  /// particles moved to them.
  void rebalance_if_needed();
  /// Applies the injections of the coming step.
  void apply_injections();
  StepTotals last_;
  PhaseTimes phase_totals_;
  double time_ = 0.0;
  long steps_ = 0;
  double max_signal_speed_ = 0.0;
  /// The objects' body forces (SceneObject::body_force), evaluated at the start of each step.
  std::optional<BodyForces> body_forces_;
  /// grid.face_velocity: the moving faces' V(t), given to the grid at each step's start and end.
  std::optional<FaceMotions> face_motions_;
  double face_speed_ = 0.0;      ///< max_f |V_f(t^n)| [m/s]: the material a face drives moves at it
  double max_body_force_ = 0.0;  ///< max_p |b_p| of this step, over the ranks [m/s^2]
  /// Bodies meet the rigid objects (ContactSpec::rigid) or the `wall` faces
  /// (GridSpec::wall_contact) at the particles: its forces are those of the current particle
  /// positions and time while `particle_contact_current_`.
  std::optional<RigidParticleContact> particle_contact_;
  bool particle_contact_current_ = false;
  /// Evaluates the contact at the particles' positions and time_; returns its energy, its
  /// force and its power on the system, each summed over the ranks: {U [J], F_x, F_y, F_z [N],
  /// P [W]}.
  std::vector<double> evaluate_particle_contact();
  /// The last evaluate_particle_contact(), summed over the ranks: energy [J], force [N], power [W],
  /// slip heat [J].
  std::vector<double> particle_contact_sums_;
};

}  // namespace impact::mpm
