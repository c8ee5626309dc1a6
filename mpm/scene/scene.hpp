// What a scene is (data/scenes/*.json, every key in docs/scenes.md): grid, time, solver, physics,
// outputs, materials and objects, as validated values. mpm/input/scene_reader.hpp reads a file
// into one; nothing else touches the scene JSON.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "models/kinematics/deformation_gradient.hpp"
#include "models/material/material.hpp"
#include "mpm/geometry/geometry.hpp"
#include "mpm/scene/expression.hpp"
#include "mpm/scene/graded_axis.hpp"
#include "mpm/scene/grid_geometry.hpp"

namespace impact::mpm {

enum class Scheme { usl, musl };  ///< update stress last / modified USL
/// symmetric: mirror plane (rigid frictionless wall that also holds in tension); fixed: no-slip;
/// free: nothing; wall: rigid stationary wall that pushes and never pulls, with Coulomb friction
/// (grid/wall.cpp).
enum class FaceCondition { symmetric, fixed, free, wall };
/// How `wall` faces meet the bodies (grid.wall_contact): at the face nodes (grid/wall.cpp), or at
/// the particles, by the penalty of contact/rigid_particle_contact.hpp against the face's plane.
enum class WallContact { nodes, particles };
/// What a particle that leaves the grid does (grid.outflow): stop the run (a numerical failure), or
/// leave the simulation with its mass, momentum and kinetic energy booked as outflow.
enum class Outflow { stop, remove };

/// Faces in the order x-, x+, y-, y+, z-, z+ (index 2*axis + side).
inline constexpr std::array<const char*, 6> kFaceNames = {"x-", "x+", "y-", "y+", "z-", "z+"};

/// grid.face_velocity.<face> (docs/scenes.md#moving-faces): a `symmetric` face that moves along
/// its axis [m/s], a number or an expression of t (text, compiled by the solver).
struct FaceMotion {
  std::string text;    ///< empty: the number `value`
  double value = 0.0;  ///< [m/s], positive toward +axis
  bool set = false;    ///< the scene gave the face a velocity
};

/// grid.refine (docs/scenes.md#graded-grids; issue 56): a box of cells `factor` times finer than
/// the base, the cells outside it growing by at most `growth` per cell back to the base size
/// (NairnMPM's tartan grids). Each mesh axis is graded on its own (scene/graded_axis.hpp): a list
/// of boxes refines, along each axis, the spans of all of them.
struct GridRefinement {
  Vec3 lower, upper;    ///< [m]
  double factor = 1.0;  ///< base cell size / refined cell size [-], >= 1
  double growth = 1.2;  ///< largest ratio of neighbouring cells outside the box [-], > 1
};

struct GridSpec {
  Vec3 lower, upper;  ///< [m]
  /// Cells per axis; on a graded grid those of the graded axes (base_cells: what grid.cells gave).
  std::array<int, 3> cells{};
  /// grid.refine, one box or several; none: a uniform grid (the solver's uniform path, bit for
  /// bit).
  std::vector<GridRefinement> refine;
  std::array<int, 3> base_cells{};  ///< grid.cells (the base size); == cells when uniform
  /// Each axis's node coordinates on a graded grid (empty when uniform).
  std::array<GradedAxis, 3> axes;
  std::array<FaceCondition, 6> faces{};           ///< per face, kFaceNames order
  std::array<double, 6> wall_friction{};          ///< Coulomb coefficient of each `wall` face [-]
  WallContact wall_contact = WallContact::nodes;  ///< grid.wall_contact
  /// grid.wall_penalty_damping: the walls' penalty damping at the particles, a fraction of each
  /// particle's critical damping [-] (contact/rigid_particle_contact.hpp, "damping"); 0: none.
  double wall_penalty_damping = 0.0;
  std::array<FaceMotion, 6> face_velocity{};  ///< per face, kFaceNames order
  bool has_moving_faces() const {
    for (const FaceMotion& m : face_velocity)
      if (m.set) return true;
    return false;
  }
  /// A wall face with mu > 0: its Coulomb work is heat (grid heat array, ledger column).
  bool has_wall_friction() const {
    for (const double mu : wall_friction)
      if (mu > 0.0) return true;
    return false;
  }
  bool has_walls() const {
    for (const FaceCondition f : faces)
      if (f == FaceCondition::wall) return true;
    return false;
  }
  /// The `wall` faces act at the particles (grid.wall_contact), not at the nodes.
  bool walls_at_particles() const { return wall_contact == WallContact::particles && has_walls(); }
  /// The faces as the nodes see them: walls that act at the particles are free there (and
  /// frictionless); the Grid is built from this.
  GridSpec at_the_nodes() const {
    GridSpec g = *this;
    if (!walls_at_particles()) return g;
    for (int f = 0; f < 6; ++f)
      if (g.faces[std::size_t(f)] == FaceCondition::wall) {
        g.faces[std::size_t(f)] = FaceCondition::free;
        g.wall_friction[std::size_t(f)] = 0.0;
      }
    return g;
  }
  /// Grid work only on the 2x2x2-node blocks the particles' stencils touch (grid/grid.hpp);
  /// false: every node of the box every step (the 2004 code's dense loops).
  bool active_blocks = true;
  Outflow outflow = Outflow::stop;
  /// The grid's kind (grid.geometry; its catalogue: scene/grid_geometry.hpp).
  GridGeometry geometry = kDefaultGeometry;
  const GeometryFacts& geometry_facts() const { return facts(geometry); }
  /// A 2D grid (axisymmetric or plane strain): z is one cell of 1 m, not an axis of the mesh.
  bool planar() const { return geometry_facts().planar(); }
  /// The mesh's axes: 2 or 3.
  int dimensions() const { return geometry_facts().mesh_axes; }
  /// Masses, energies, momenta and volumes are per metre of thickness (plane strain;
  /// mpm/ledger/extensive_units.hpp).
  bool per_metre_of_thickness() const { return geometry_facts().per_metre_of_thickness; }
  /// Face f (kFaceNames order) bounds the modelled domain: read from the scene, not the axis.
  bool is_domain_face(int f) const { return geometry_facts().is_domain_face(f); }
  /// Cells of unequal size along the mesh's axes (grid.refine).
  bool graded() const { return !refine.empty(); }
  /// Grades the axes by `refine` (the reader, once cells are read): base_cells keeps grid.cells,
  /// cells becomes the graded counts. A 2D grid's z (one cell of 1 m) is not graded.
  void grade();
  /// The uniform grid of grid.cells again (refine dropped): what the reader falls back to after
  /// a problem with the refinement.
  void ungrade();
  /// What a refusal of the grid's size advises about its refinement, as a clause after "coarsen
  /// grid.cells": nothing on a uniform grid; the box's factor and extent; in a list, the box
  /// whose removal takes away the most cells, by its key path.
  std::string refinement_advice() const;
  /// The smallest cell edge of the mesh's axes [m] (the time step).
  double min_spacing() const {
    const Vec3 h = smallest_cell();
    return planar() ? std::min(h(0), h(1)) : h.minCoeff();
  }
  /// The mean cell edge of the mesh's axes [m] (artificial viscosity's length, report eq. 12; on
  /// a graded grid that of the cell the particle is in, step/stress_update.cpp).
  double mean_spacing() const {
    const Vec3 h = spacing();
    return planar() ? 0.5 * (h(0) + h(1)) : h.sum() / 3.0;
  }
  /// The cell edges [m]; on a graded grid the base cells' (grid.cells): what a site that has no
  /// graded form yet reads (the scene check refuses those with a graded grid).
  Vec3 spacing() const {
    return (upper - lower)
        .cwiseQuotient(
            Vec3(base_cells_or_cells(0), base_cells_or_cells(1), base_cells_or_cells(2)));
  }
  /// The smallest cell per axis [m].
  Vec3 smallest_cell() const {
    if (!graded()) return spacing();
    return {axes[0].smallest(), axes[1].smallest(), axes[2].smallest()};
  }
  /// The largest cell per axis [m].
  Vec3 largest_cell() const {
    if (!graded()) return spacing();
    return {axes[0].largest(), axes[1].largest(), axes[2].largest()};
  }
  /// Node i's coordinate along axis d [m] (the ghost nodes -1 and cells_d + 1 included).
  double node(int d, int i) const {
    return graded() ? axes[std::size_t(d)].node(i) : lower(d) + i * spacing()(d);
  }
  /// The edge along axis d of cell i (between nodes i and i + 1) [m].
  double cell_size(int d, int i) const {
    return graded() ? axes[std::size_t(d)].size(i) : spacing()(d);
  }
  /// The dual cell of node i along axis d, the mean of the two cells beside it [m]: what a node
  /// holds on a graded grid (the contact normals' densities, the separating plane's reach).
  double dual_size(int d, int i) const { return 0.5 * (cell_size(d, i - 1) + cell_size(d, i)); }
  /// The cell along axis d holding coordinate x, clamped into [0, cells_d - 1] (seed points,
  /// migration and the domain decomposition's counts all bin particles by it).
  int cell_along(int d, double x) const {
    if (graded()) return axes[std::size_t(d)].cell_of(x);
    const double c = std::floor((x - lower(d)) / spacing()(d));
    // NaN (a refused grid's bounds, read on to report every problem) clamps to 0 as well:
    // converted to int it is undefined (a crater's face on a grid without `lower`, fuzz_scene).
    if (!(c >= 0.0)) return 0;
    return static_cast<int>(std::min(c, static_cast<double>(cells[std::size_t(d)] - 1)));
  }
  /// The cell (i, j, k) holding position x, clamped into the grid.
  std::array<int, 3> cell_of(const Vec3& x) const {
    return {cell_along(0, x(0)), cell_along(1, x(1)), cell_along(2, x(2))};
  }

 private:
  double base_cells_or_cells(int d) const {
    return graded() ? base_cells[std::size_t(d)] : cells[std::size_t(d)];
  }
};

struct TimeSpec {
  double max_time = 0.0;    ///< end time [s]
  double initial_dt = 0.0;  ///< first step is min(initial_dt, stable dt) [s]
  double min_dt = 0.0;      ///< the run stops if the stable dt falls below this [s]
  double max_dt = 0.0;      ///< cap on dt [s]
  double multiplier = 0.5;  ///< CFL factor on the stable dt [-], up to 1.5 (> 1: warned)
  /// The run stops when kinetic + strain energy (+ booked sinks) exceeds the energy that entered
  /// by this fraction of it: energy_error > max_energy_growth (docs/mpm.md#failure-handling) [-]
  double max_energy_growth = 1.0;
  /// mpm run refuses (exit 4) a scene whose step count, estimated before seeding, exceeds this
  /// (mpm/run/step_estimate.hpp; docs/mpm.md#memory-and-step-estimates) [-]
  double max_estimated_steps = 1e7;
  /// ... and whose particle-steps (the particles estimated from the geometry times the steps)
  /// exceed this: about 42 h on one core at 2e6 particle-steps/s (docs/performance.md) [-]
  double max_estimated_particle_steps = 3e11;
};

/// How a run on several ranks chooses its ranks per axis (solver.ranks_per_axis, docs/mpi.md).
enum class SplitRule { fewest_cut_faces, least_loaded };

struct SolverSpec {
  /// The shape functions' kName (mpm/shape/shape.hpp): gimp (27-node uGIMP) or linear (8-node
  /// trilinear).
  std::string interpolation = "gimp";
  Scheme scheme = Scheme::musl;
  FIntegration f_integration = FIntegration::forward_euler;
  Vec3 gravity = Vec3::Zero();  ///< body force per unit mass [m/s^2]
  /// On several ranks (docs/mpi.md): the boxes are re-balanced by particle count when the largest
  /// rank's count exceeds this multiple of the mean [-].
  double rebalance_above = 1.2;
  /// On several ranks: boxes per axis (product = the rank count); {0, 0, 0}: chosen by `split`.
  std::array<int, 3> ranks_per_axis{0, 0, 0};
  /// How {0, 0, 0} chooses: the split cutting the fewest node faces
  /// (BoxDecomposition::ranks_per_axis), or the least loaded boxes (least_loaded_split, JSON
  /// "least_loaded": refined boundaries, also when re-balancing).
  SplitRule split = SplitRule::fewest_cut_faces;
  /// 0: the particles are stored in seed order (a cell sort: the fastest transfers); k in [1,
  /// 1e15]: in the permutation shuffled_order draws with seed k (mpm/particles/particle_order.hpp),
  /// each rank's own particles on several ranks. The physics is the same; the sums over particles
  /// run in another order, so an ensemble of seeds measures how far round-off moves a scene's
  /// results (campaigns/benchmark/result_bounds.py --ensemble).
  std::uint64_t shuffle_particles = 0;
};

/// How the velocity fields of different materials interact at shared nodes (Bardenhagen et al.
/// 2001; docs/report_code.md sec. 14). `single_velocity` is ordinary single-field MPM; `friction`
/// (the scene's "friction" or "approach": one model, contact/contact.hpp) gives each material its
/// own field, corrected where they approach, with Coulomb friction mu.
enum class ContactType { single_velocity, friction };

/// The contact normal at a node of two bodies (contact/contact.hpp): `mass_gradients` unit(grad
/// m_other - grad m_self) (Bardenhagen et al. 2001); `larger_volume` the surface of the body with
/// more volume at the node (Nairn's "maximum volume"; for a small body on a large flat one);
/// `logistic_regression` the plane separating the two bodies' particles at the node (Nairn,
/// Hammerquist & Smith 2020; contact/separating_plane.hpp).
enum class ContactNormal { mass_gradients, larger_volume, logistic_regression };

/// When two bodies at a node are in contact (contact/contact.hpp): `approach` wherever their
/// fields approach (Bardenhagen et al. 2001); `separation` where they approach and their particles'
/// deformed domains meet along the fitted plane's normal (Nairn, Hammerquist & Smith 2020: the
/// bodies' separation from the logistic regression's cloud; step/contact_planes.cpp).
enum class ContactDetection { approach, separation };

/// The most velocity fields multi-field contact handles at a node (its per-node arrays in
/// contact.cpp are this long); the scene check refuses a scene with more (Scene::field_count).
constexpr int kMaxContactFields = 64;

/// Where bodies meet rigid objects: at the shared nodes (contact/contact.hpp, as between any two
/// bodies), or at the particles, by a penalty against the rigid surface
/// (contact/rigid_particle_contact.hpp).
enum class RigidContact { nodes, particles };

struct ContactSpec {
  ContactType type = ContactType::single_velocity;
  double mu = 0.0;  ///< Coulomb friction coefficient [-]
  ContactNormal normal = ContactNormal::mass_gradients;
  ContactDetection detection = ContactDetection::approach;
  RigidContact rigid = RigidContact::nodes;
  /// The penalty's damping at the particles, a fraction of each particle's critical damping
  /// 2 sqrt(k_p m_p) [-] (contact/rigid_particle_contact.hpp, "damping"); 0: none.
  double penalty_damping = 0.0;
};

/// Artificial bulk viscosity, report eq. 12 (von Neumann & Richtmyer 1950, Wilkins 1980):
/// q = rho (C_L a |tr D| l + C_0 (tr D l)^2) when tr D < 0, else 0.
struct ArtificialViscositySpec {
  bool enabled = false;
  double linear = 0.2;     ///< C_L (the report's coeff1; its Case 1 used 0.07) [-]
  double quadratic = 2.0;  ///< C_0 (coeff2; Case 1: 1.6) [-]
};

/// physics.on_numerical_fault.
enum class NumericalFaultAction { stop, fail_particle };

/// The report's <MPM> flags: optional physics, each off (or the material file's choice) unless a
/// scene asks for it.
struct PhysicsSpec {
  ContactSpec contact;
  ArtificialViscositySpec artificial_viscosity;
  bool create_new_particles = false;  ///< failed particles move to a companion velocity field
  /// What a numerical fault of one particle's update (NaN stress or F, negative Jacobian, radial
  /// return not converged, EOS out of range) does: stop the run (default), or flag the particle
  /// failed (stress zeroed, no further update) and go on (docs/mpm.md#failure-handling).
  NumericalFaultAction on_numerical_fault = NumericalFaultAction::stop;
  // Overrides of every material's own setting (absent: the material file decides).
  std::optional<Erosion> erosion;
  std::optional<bool> do_melting;
  std::optional<bool> adiabatic_heating;  ///< the report's turn_on_adiabatic_heating
};

/// A history gauge (output.gauges.<name>, docs/scenes.md): the mass-weighted mean over the
/// particles of one object whose initial position lies in a box (closed), sampled at every
/// history row into the column `gauge_<name> [unit]` (mpm/output/observables.hpp).
enum class GaugeType { velocity, strain, pressure };

struct GaugeSpec {
  std::string name;
  GaugeType type = GaugeType::velocity;
  int object = 0;             ///< index into Scene::objects
  Vec3 lower = Vec3::Zero();  ///< region of initial positions [m]
  Vec3 upper = Vec3::Zero();  ///< [m]
  int component = 0;          ///< 0, 1, 2 = x, y, z (velocity and strain)
};

/// output.crater: the crater an impact along +x leaves in the face x = `face` of an object.
struct CraterSpec {
  int object = 0;     ///< index into Scene::objects
  double face = 0.0;  ///< x of the impacted face [m]
  /// The crater axis (y, z) [m] when given (a quarter model's symmetry corner); otherwise the
  /// mean position of the displaced particles.
  std::optional<std::array<double, 2>> axis;
};

/// output.particle_paths.<name>: record the path of the particle of `object` whose initial
/// position is nearest to `position` (mpm/output/particle_paths.hpp).
struct ParticlePathSpec {
  std::string name;
  int object = 0;                ///< index into Scene::objects
  Vec3 position = Vec3::Zero();  ///< [m]
};

struct OutputSpec {
  std::string directory;                         ///< where history.csv etc. go
  double interval = 0.0;                         ///< history row and snapshot interval [s]
  bool snapshots = true;                         ///< write particles/step_NNNNNN.vtu
  std::vector<std::string> fields;               ///< VTU point-data fields
  std::vector<GaugeSpec> gauges;                 ///< history gauges (none: no columns, no work)
  std::optional<CraterSpec> crater;              ///< crater observables in summary.json
  std::vector<ParticlePathSpec> particle_paths;  ///< point-driver paths (none: no work)
  /// Write DIR/checkpoint.bin every this many steps (0: off; mpm/run/checkpoint.hpp).
  long checkpoint_interval_steps = 0;
  /// A history column plastic_work [J] (mpm/step/step.hpp StressTotals::plastic_work).
  bool plastic_work = false;
  /// An exact displacement u(X, t) [m] to measure the particles against: history columns
  /// displacement_error_rms and _max (mpm/output/displacement_error.hpp); none: no columns.
  std::optional<VectorExpression> exact_displacement;
};

struct SceneMaterial {
  std::string name;
  Material material;
};

struct SceneObject {
  std::string name;
  Geometry geometry;
  int material = 0;  ///< index into Scene::materials
  /// Initial velocity [m/s]: the numbers of velocity_field; where it has expressions, their
  /// value of largest magnitude over the seed points (mpm/scene/initial_fields.hpp), what the
  /// estimates of one velocity per object read.
  Vec3 velocity = Vec3::Zero();
  /// The initial velocity as written: numbers, or expressions over X, Y, Z at t = 0.
  VectorExpression velocity_field;
  double temperature = 294.0;                      ///< initial temperature [K]
  std::array<int, 3> particles_per_cell{2, 2, 2};  ///< the report's `res`
  /// Body force per unit mass b(X, t) [m/s^2] on this object's particles, beside solver.gravity
  /// (numbers or expressions; zero: none).
  VectorExpression body_force;
  /// max |b(X_p, 0)| over the seed points [m/s^2] (the reader's, mpm/scene/initial_fields.hpp):
  /// what the step estimate takes of the body force.
  double initial_body_force_peak = 0.0;
  /// A rigid body (objects.<name>.rigid): its particles move at `velocity` for ever, carry no
  /// stress and take no body force; the other bodies meet it through multi-field contact as a
  /// partner of infinite mass (Nairn's rigid material; contact/contact.hpp). Its material gives
  /// its density (the nodal masses the contact normals read) and its own velocity field.
  bool rigid = false;
  /// A rigid object's Coulomb coefficient against the bodies it meets [-] (objects.<name>.mu);
  /// unset: physics.contact.mu, which also acts between the deformable bodies.
  std::optional<double> mu;

  bool has_body_force() const { return body_force.has_text() || !body_force.value.isZero(0.0); }
};

struct Scene {
  std::string file;
  Json resolved;  ///< the merged document (after extends), as run
  GridSpec grid;
  TimeSpec time;
  SolverSpec solver;
  PhysicsSpec physics;
  OutputSpec output;
  std::vector<SceneMaterial> materials;
  std::vector<SceneObject> objects;
  /// Named numbers the expressions may use (top-level "constants") [SI].
  NamedConstants constants;
  /// Admissible but suspicious settings (e.g. a multiplier above 1), "file: /key/path: why";
  /// the command line prints them on stderr.
  std::vector<std::string> warnings;

  /// Velocity fields: one per material when contact is not single_velocity (and a companion per
  /// material with create_new_particles), else one shared field (ordinary MPM).
  int field_count() const;
  /// Whether the particles keep their reference positions (Particles::X): a body force or an
  /// exact displacement reads them.
  bool needs_reference_positions() const {
    return has_body_force() || output.exact_displacement.has_value() || contact_at_particles();
  }
  /// Whether bodies meet the rigid objects at the particles (ContactSpec::rigid), which reads the
  /// seed points (contact/rigid_particle_contact.hpp).
  bool rigid_contact_at_particles() const {
    return physics.contact.rigid == RigidContact::particles && has_rigid_objects();
  }
  /// Whether anything meets the bodies at the particles: rigid objects, or `wall` faces
  /// (grid.wall_contact).
  bool contact_at_particles() const {
    return rigid_contact_at_particles() || grid.walls_at_particles();
  }
  /// Whether that contact has Coulomb friction (contact.mu > 0 with rigid objects, a wall face's
  /// wall_friction > 0), which keeps a stick spring's anchor per particle
  /// (Particles::friction_anchor).
  bool friction_at_particles() const {
    return (rigid_contact_at_particles() && rigid_friction() > 0.0) ||
           (grid.walls_at_particles() && grid.has_wall_friction());
  }
  /// Whether multi-field contact has Coulomb friction somewhere (physics.contact.mu > 0, or a
  /// rigid object's own mu > 0): its work is the ledger's friction_heat, kept per node.
  bool contact_friction() const {
    return field_count() > 1 && physics.contact.type == ContactType::friction &&
           (physics.contact.mu > 0.0 || rigid_friction() > 0.0);
  }
  /// Rigid object o's Coulomb coefficient against the bodies it meets, as the run takes it [-]:
  /// its own mu, else physics.contact.mu.
  double friction_of(const SceneObject& o) const { return o.mu.value_or(physics.contact.mu); }
  /// The largest Coulomb coefficient between a rigid object and the bodies [-] (0: none rigid).
  double rigid_friction() const {
    double mu = 0.0;
    for (const SceneObject& o : objects)
      if (o.rigid) mu = std::max(mu, friction_of(o));
    return mu;
  }
  /// Whether that contact's penalty is damped (contact.penalty_damping with rigid objects,
  /// grid.wall_penalty_damping with walls).
  bool damping_at_particles() const {
    return (rigid_contact_at_particles() && physics.contact.penalty_damping > 0.0) ||
           (grid.walls_at_particles() && grid.wall_penalty_damping > 0.0);
  }
  /// |solver.gravity| + the largest initial body force of an object [m/s^2]: the body-force step's
  /// at the start.
  double body_force_at_start() const {
    double b = 0.0;
    for (const SceneObject& o : objects) b = std::max(b, o.initial_body_force_peak);
    return solver.gravity.stableNorm() + b;
  }
  /// Whether an object has a body force (SceneObject::body_force).
  bool has_body_force() const {
    return std::any_of(objects.begin(), objects.end(),
                       [](const SceneObject& o) { return o.has_body_force(); });
  }
  /// Whether an object is rigid (SceneObject::rigid).
  bool has_rigid_objects() const {
    return std::any_of(objects.begin(), objects.end(),
                       [](const SceneObject& o) { return o.rigid; });
  }
  /// The largest speed of a rigid object [m/s] (0: none moves): the material it pushes is driven
  /// at it before its particles show it, as a moving face's.
  double rigid_speed() const {
    double v = 0.0;
    for (const SceneObject& o : objects)
      if (o.rigid) v = std::max(v, o.velocity.norm());
    return v;
  }
  /// Per velocity field, the velocity of the rigid object it carries [m/s] (its material's parent
  /// field), empty for a field of deformable bodies; an empty vector when no object is rigid.
  std::vector<std::optional<Vec3>> rigid_field_velocities() const;
  /// Per velocity field, the Coulomb coefficient between its rigid object and the bodies it
  /// meets [-] (SceneObject::mu, else physics.contact.mu); physics.contact.mu for a field of
  /// deformable bodies; an empty vector when no object is rigid.
  std::vector<double> rigid_field_friction() const;
  /// The field a particle of material m starts in, and the companion it moves to on failure.
  int parent_field(int material) const;
  int companion_field(int material) const;
};

}  // namespace impact::mpm
