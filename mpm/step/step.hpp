// The phases of one explicit MPM step, each a free function templated on the shape (a shape of
// the catalogue, mpm/shape/shape.hpp); advance() in mpm/simulation/advance.hpp strings them
// together on one screen. Notation: p particles, I nodes, S_Ip weights, grad S_Ip gradients (at the
// start-of-step x_p).
#pragma once

#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "mpm/contact/contact.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/ledger/totals.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/shape.hpp"
#include "mpm/step/scatter_order.hpp"

namespace impact::mpm {

class HaloExchange;  // mpm/parallel/halo_exchange.hpp: the node sums shared with other ranks

/// The first particle (lowest seed index) whose update failed, and why.
struct Failure {
  Failure() = default;
  Failure(std::size_t particle_, std::string field_, std::string message_,
          std::optional<PointState> state_ = std::nullopt)
      : particle(particle_),
        field(std::move(field_)),
        message(std::move(message_)),
        state(std::move(state_)) {}

  std::size_t particle = 0;
  std::string field;  ///< e.g. "position", "velocity", "stress"
  std::string message;
  /// The particle's state when the fault was found, if the particle's stored state no longer
  /// shows it (fail_particle zeroes the stress).
  std::optional<PointState> state;
};

/// Whether particle p's failure comes before `kept` (none kept, or p's seed index is the lower):
/// the particle a failure names is then the same whatever the storage order
/// (solver.shuffle_particles) and whichever thread saw it.
inline bool fails_first(const Particles& P, std::size_t p, const std::optional<Failure>& kept) {
  return !kept || seed_index(P, p) < seed_index(P, kept->particle);
}
inline bool fails_first(const Particles& P, const Failure& a, const Failure& b) {
  return seed_index(P, a.particle) < seed_index(P, b.particle);
}

/// The stencils (1-D weights and derivatives, base node) of every particle at its start-of-step
/// position: computed once per step and reused by P2G, G2P and the MUSL re-map.
template <class Shape>
using Stencils = std::vector<Stencil<Shape::N>>;
namespace detail {
// std::variant of the distinct types among Ts (shapes on several grid geometries share their
// stencil type).
template <class Variant, class... Ts>
struct DistinctVariant {
  using type = Variant;
};
template <class... Vs, class T, class... Ts>
struct DistinctVariant<std::tuple<Vs...>, T, Ts...> {
  using type = typename DistinctVariant<
      std::conditional_t<(std::is_same_v<T, Vs> || ...), std::tuple<Vs...>, std::tuple<Vs..., T>>,
      Ts...>::type;
};
template <class... Vs>
struct DistinctVariant<std::tuple<Vs...>> {
  using type = std::variant<Vs...>;
};
}  // namespace detail
template <class... Shapes>
using StencilsOf = typename detail::DistinctVariant<std::tuple<>, Stencils<Shapes>...>::type;
/// The stencils of the run's shape.
using AnyStencils = WithEveryShape<StencilsOf>;
/// Returns the particles whose box was narrowed to fit (a graded grid; 0 on a uniform one).
template <class Shape>
long compute_stencils(const Particles& P, const Shape& shape, Stencils<Shape>& S, int threads);

/// Particles to grid (Sulsky et al. 1994 eqs. 20-22):
///   m_I = sum_p S_Ip m_p,  p_I = sum_p S_Ip m_p v_p,
///   f_I = -sum_p V_p sigma_p . grad S_Ip   (gravity is added as m_I g in grid_update),
/// scattered in `order` (order_for_scatter on S); with wall faces, also the walls each particle
/// reaches within the step `dt` (Grid::wall_touch); `halo` (several ranks) completes the sums at
/// the node planes shared with the neighbouring ranks before the step's nodes are activated.
/// With `body_force` (b_p per particle [m/s^2], step/body_force.hpp) f_I += sum_p S_Ip m_p b_p.
/// With `rigid_force` (f_p per particle [N], contact/rigid_particle_contact.hpp) f_I += sum_p
/// S_Ip f_p, and the rigid objects' particles put nothing on the grid: the bodies meet them at
/// the particles alone.
template <class Shape>
void particles_to_grid(const Particles& P, Grid& G, const Stencils<Shape>& S,
                       const ScatterOrder& order, double dt, const HaloExchange* halo = nullptr,
                       const Vec3* body_force = nullptr, const Vec3* rigid_force = nullptr);

/// USL's velocity gradient limits the acceleration part of v*_I at nodes lighter than this
/// fraction of the lightest particle mass: v^L_I = v_I + min(1, m_I/m_light) (v*_I - v_I). Why:
/// with trilinear weights a particle that has just entered a cell gives the node ahead a mass
/// S m_p -> 0 but a gradient ~ 1/dx, so dt f_I/m_I fed back through L multiplies that particle's
/// stress by about (c dt/dx)^2 / S per step (> 8 for S < 0.03 at CFL 0.5): any round-off grows
/// without bound. The limiter bounds the factor by (c dt/dx)^2 / 0.5 < 2. FLIP velocity and
/// position use the true v*_I (S_Ip dt f_I/m_I stays bounded), so momentum is untouched.
/// Axisymmetric: a ring's mass grows with its radius (2 pi r A rho), so the lightest mass is that
/// per unit radius times the node's radius (at least the innermost particle's;
/// GridSettings::light_radius): one threshold for the whole grid let an outer node far lighter than
/// its particles through, and a linear/USL rigid translation grew unstable within 150 steps
/// (planar_verification_test.cpp).
inline constexpr double kLightNodeMassFraction = 0.5;

/// With `contact.normal = "logistic_regression"`: the plane separating the two bodies' particles
/// at each node of two bodies, fitted by logistic regression (Nairn, Hammerquist & Smith 2020;
/// contact/separating_plane.hpp), into Grid::contact_plane for the step's contact passes; with
/// `gaps` (`contact.detection = "separation"`) also the bodies' gap along it, Grid::contact_gap.
/// With `halo` (several ranks) the other ranks' particles near the box join the clouds.
template <class Shape>
void fit_contact_planes(const Particles& P, Grid& G, const Shape& shape, const Stencils<Shape>& S,
                        const HaloExchange* halo, bool gaps);

/// Grid update (eq. 24), per velocity field: v_I = p_I/m_I, v*_I = v_I + dt (f_I/m_I + g); with
/// `contact` and more than one field the contact model corrects v_I (the impact) and v*_I (the
/// step) (contact/contact.hpp); the face conditions as a mirror (grid/boundary.cpp) on v_I and
/// v*_I; the FLIP increment from the uncorrected p_I/m_I to the corrected v*_I; for USL the
/// gradient velocity v^L_I (kLightNodeMassFraction). Books, exactly at the nodes, the faces'
/// impulse, what the contact corrections removed, and the external (gravity) impulse and work
/// (grid_update.cpp).
struct GridUpdate {
  /// sum over constrained nodes of m_I (dv_I - dv_I^free): what the faces exerted, and the
  /// rigid objects' contact reaction (ContactTotals::rigid_impulse) [N s]. A stationary face or
  /// body does no work (docs/mpm.md#ledger).
  Vec3 boundary_impulse = Vec3::Zero();
  ContactTotals contact;
  double wall_friction_heat = 0.0;  ///< Coulomb heat of the wall faces (grid/wall.cpp) [J]
  Vec3 external_impulse = Vec3::Zero();
  double external_work = 0.0;
  /// How each total combines over ranks (mpm/ledger/totals.hpp).
  static constexpr auto kFields =
      std::tuple{summed(&GridUpdate::boundary_impulse), summed(&GridUpdate::contact),
                 summed(&GridUpdate::wall_friction_heat), summed(&GridUpdate::external_impulse),
                 summed(&GridUpdate::external_work)};
};
GridUpdate grid_update(Grid& G, double dt, const Vec3& gravity, bool usl_gradient,
                       const ContactSpec* contact);

/// What grid-to-particles measured on the end-of-step particle velocities (report eq. 13).
struct ParticleTotals {
  double kinetic_energy = 0.0;
  Vec3 momentum = Vec3::Zero();
  double max_speed = 0.0;      ///< max_p |v_p| [m/s]
  double friction_heat = 0.0;  ///< friction heat delivered to the particles [J]
  /// Particles that left the grid this step and were removed (grid.outflow = remove): their mass,
  /// momentum and kinetic energy as they left [kg, kg m/s, J].
  double outflow_mass = 0.0;
  Vec3 outflow_momentum = Vec3::Zero();
  double outflow_kinetic_energy = 0.0;
  long removed = 0;
  /// The body forces' impulse sum_p dt m_p b_p and work sum_p dt m_p b_p . sum_I S_Ip (v_I +
  /// v*_I)/2 [N s, J]: by linearity, exactly the nodal sum_I dt f^b_I . (v_I + v*_I)/2 at the
  /// velocities the nodes keep, as gravity's in grid_update.
  Vec3 external_impulse = Vec3::Zero();
  double external_work = 0.0;
  /// How each total combines over threads and ranks (mpm/ledger/totals.hpp).
  static constexpr auto kFields = std::tuple{summed(&ParticleTotals::kinetic_energy),
                                             summed(&ParticleTotals::momentum),
                                             largest(&ParticleTotals::max_speed),
                                             summed(&ParticleTotals::friction_heat),
                                             summed(&ParticleTotals::outflow_mass),
                                             summed(&ParticleTotals::outflow_momentum),
                                             summed(&ParticleTotals::outflow_kinetic_energy),
                                             summed(&ParticleTotals::removed),
                                             summed(&ParticleTotals::external_impulse),
                                             summed(&ParticleTotals::external_work)};
};

/// Per material: whether a particle retains heat (adiabatic heating on) and its c_p [J/(kg K)].
struct HeatCapacity {
  bool retained = false;
  double specific_heat = 0.0;
};

/// Grid to particles: FLIP velocity v_p += sum_I S_Ip (v*_I - v_I) (eq. 23), position
/// x_p += dt sum_I S_Ip v*_I (eq. 25), and with `usl_gradient` L_p = sum_I v^L_I (x) grad S_Ip
/// (eq. 26, evaluated as sum_I (v^L_I - v_p) (x) grad S_Ip over nodes with mass: equal, as
/// sum_I grad S_Ip = 0, and a massless node no longer fakes a velocity jump).
/// With friction heat on the grid (G.heat), each particle receives sum_I S_Ip h_I / m_I per unit
/// mass (the heat of a node shared among its particles in proportion to S_Ip m_p, so the total is
/// delivered exactly), retained by the rule of models/thermal/adiabatic_heating.hpp
/// (`heat_capacity` per material). A particle that leaves the grid stops the step (a Failure), or
/// with grid.outflow = remove (Particles::removed allocated) leaves the simulation.
/// With `body_force` (the b_p particles-to-grid added), its impulse and work (ParticleTotals).
/// With `rigid_force` (contact/rigid_particle_contact.hpp) a particle the rigid contact pushed
/// this step moves with the velocity its strain sees, for USL x_p += dt sum_I S_Ip v^L_I; for
/// MUSL remap_and_gradient moves it. Why: its contact energy is a function of x_p, its
/// neighbours' strain energy of the displacement L integrates; driven by two velocities the
/// spring and the body trade work that is not a gradient, O(dt^2) per step and one-signed: a
/// column resting on a rigid floor gained energy until the check stopped it (docs/verification.md).
template <class Shape>
ParticleTotals grid_to_particles(Particles& P, const Grid& G, const Stencils<Shape>& S, double dt,
                                 bool usl_gradient, const std::vector<HeatCapacity>& heat_capacity,
                                 std::optional<Failure>& failure, const Vec3* body_force = nullptr,
                                 const Vec3* rigid_force = nullptr);

/// MUSL (Sulsky et al. 1995; Nairn 2003): re-map the updated particle momentum with the same
/// weights, v^{n+1}_I = sum_p S_Ip m_p v_p^{n+1} / m_I, correct it by the contact model (if any)
/// and mirror it at the faces (projections: the particles do not see them), and
/// L_p = sum_I v^{n+1}_I (x) grad S_Ip. The momentum is scattered in `order`, as in P2G.
/// With `rigid_force`, a particle the rigid contact pushed this step moves with the velocity L
/// integrates, x_p = x_p^n + dt sum_I S_Ip v^{n+1}_I (grid_to_particles says why).
template <class Shape>
void remap_and_gradient(Particles& P, Grid& G, const Stencils<Shape>& S, const ScatterOrder& order,
                        const ContactSpec* contact, const HaloExchange* halo = nullptr,
                        double dt = 0.0, const Vec3* rigid_force = nullptr);

/// What the stress update needs besides the particles: the models per material and the
/// optional physics of the scene.
/// Whether particle p belongs to a rigid object, by the per-field table of GridSettings::
/// rigid_field (`rigid` its data, null without rigid objects).
inline bool in_rigid_field(const std::uint8_t* rigid, const Particles& P, std::size_t p) {
  return rigid != nullptr && rigid[P.field[p]] != 0;
}

struct StressUpdateSettings {
  std::vector<const ElasticPlastic*> models;  ///< per material
  FIntegration f_integration = FIntegration::forward_euler;
  const ArtificialViscositySpec* viscosity = nullptr;  ///< null: off
  double mean_spacing = 0.0;  ///< l = (dx + dy + dz)/3, (dx + dy)/2 in 2D [m] (eq. 12)
  /// A graded grid (null: uniform): l is then the mean edge of the cell the particle is in.
  const GridSpec* graded_grid = nullptr;
  /// Per material: the field a failed particle moves to (create_new_particles); empty: off.
  std::vector<std::uint16_t> companion_field;
  /// Per velocity field, 1 where it carries a rigid object: the grid's table
  /// (GridSettings::rigid_field, the one source). Its particles keep their state (no stress, no
  /// strain) and only their speed enters the time step; empty: no rigid object.
  std::vector<std::uint8_t> rigid_field;
  /// physics.on_numerical_fault = fail_particle: a particle whose update fails (non-finite F or
  /// stress, negative Jacobian, radial return not converged, EOS out of range) is flagged in
  /// Particles::fault, its stress (and q) zeroed, its other state kept from the start of the
  /// step, and it is not updated again; the step goes on. Otherwise the first such particle is
  /// the step's Failure.
  bool fail_particle = false;
  /// output.plastic_work: sum the step's plastic work (StressTotals::plastic_work).
  bool plastic_work = false;
  /// Fault injection (mpm run --inject-fault nan:STEP:PARTICLE): this particle's updated stress
  /// is replaced by NaN in this step, as if its model had returned NaN; -1: none.
  std::ptrdiff_t inject_nan_stress = -1;
};

/// Constitutive update by the library for every particle: F_{n+1} from L (models/kinematics),
/// sigma_{n+1} by ElasticPlastic::update (objective, with the library's rotation), V = V0 det F.
/// Returns the strain-energy increment of report eq. 14, sum_p 1/2 (sigma_n + sigma_{n+1}) : D
/// V_{n+1} dt, and the largest signal speed for the next time step. With artificial viscosity:
/// q_{n+1} (eq. 12) for the next internal force, its dissipation q_{n+1} (-tr D) V_{n+1} dt >= 0,
/// and the signal speed Q + sqrt(Q^2 + c^2), Q = C_L a + C_0 l |tr D| (Wilkins 1980). A particle
/// that fails moves to its companion field (create_new_particles) in the same step. With
/// output.plastic_work: the step's plastic work sum_p sigma_eq,n+1 (ep_n+1 - ep_n) V_{n+1}, the
/// backward-Euler value of the radial return's sigma : d eps^p (J2, associated flow: sigma_eq =
/// sigma_y after the return), with the stress the point carries at the end of the step: a point
/// whose stress erosion zeroes (ZeroStress) does no plastic work from its failure on, though its
/// model may go on reporting flow. A part of the strain-energy increment.
struct StressTotals {
  double strain_energy_increment = 0.0;
  double viscous_work = 0.0;      ///< [J]
  double eroded_energy = 0.0;     ///< elastic energy removed by erosion this step [J]
  double plastic_work = 0.0;      ///< [J], output.plastic_work only
  double max_signal_speed = 0.0;  ///< max_p (c_p + |v_p|) [m/s]
  long failed = 0;                ///< particles that failed this step
  long converted = 0;             ///< particles moved to a companion field this step
  /// fail_particle: the particles flagged this step and why (ascending index).
  std::vector<Failure> faulted;
  /// How each total combines over threads and ranks (mpm/ledger/totals.hpp); `faulted` is a
  /// list, joined in thread order by update_stress.
  static constexpr auto kFields = std::tuple{summed(&StressTotals::strain_energy_increment),
                                             summed(&StressTotals::viscous_work),
                                             summed(&StressTotals::eroded_energy),
                                             summed(&StressTotals::plastic_work),
                                             largest(&StressTotals::max_signal_speed),
                                             summed(&StressTotals::failed),
                                             summed(&StressTotals::converted)};
};
StressTotals update_stress(Particles& P, const StressUpdateSettings& settings, double dt,
                           std::optional<Failure>& failure);

/// Stable step: multiplier * min_d dx_d / max_p (c_p + |v_p|) (docs/report_code.md sec. 16,
/// with the speed magnitude instead of per-axis components: slightly more conservative);
/// `min_spacing` = GridSpec::min_spacing(), the mesh's axes only.
double stable_time_step(double min_spacing, double max_signal_speed, double multiplier);
/// Body-force step: sqrt(multiplier * min_d dx_d / abs(g)), the step in which the velocity a
/// body force adds, abs(g) dt, carries a particle multiplier cells on its own
/// (abs(g) dt * dt = multiplier dx); infinite for g = 0. Binds only where gravity outruns the
/// wave speed's step (1e12 m/s^2 on a 1 mm cell at multiplier 0.5: 2.2e-8 s against 1e-7 s).
double body_force_time_step(double min_spacing, double gravity, double multiplier);
/// max_p (c_p + |v_p|) from the stored wave speeds (first step).
double max_signal_speed(const Particles& P);

}  // namespace impact::mpm
