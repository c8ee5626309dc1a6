// Energy and momentum ledger (history.csv). Definitions and the sign of every term
// (docs/mpm.md#ledger):
//   kinetic_energy  = sum_p 1/2 m_p |v_p|^2, end-of-step velocity            (report eq. 13)
//   strain_energy   = sum_steps sum_p 1/2 (sigma_n + sigma_{n+1}) : D V_{n+1} dt   (eq. 14)
//   total_energy    = kinetic + strain                                  (the report's quantity)
//   boundary_impulse = what the grid-face conditions exerted (grid/boundary.cpp), and the rigid
//                     objects' contact (contact/contact.hpp); stationary faces and bodies do no
//                     work, so they have no energy column; a moving face's or rigid object's work
//                     is external_work
//   sinks           = one column each, registered by the solver for the physics a scene uses, each
//                     >= 0 and non-decreasing by construction: viscous_work and friction_heat (in
//                     the balance: heat), eroded_energy (part of strain_energy: shown, not added);
//                     and one stored energy that rises and falls, contact_energy, the energy of
//                     the rigid objects' contact at the particles (contact/
//                     rigid_particle_contact.hpp: sum_p W(delta_p) >= 0, in the balance)
//   outflow_*       = (grid.outflow = remove) mass, momentum and kinetic energy of the particles
//                     that left the grid (the stress work done on them stays in strain_energy)
//   energy_error    = (kinetic + strain + sum of balance sinks + outflow_kinetic_energy - E0
//                      - external_work) / E_in: the numerical residual (time integration and
//                      transfers), the one term that is not physics
// with E0 the initial kinetic energy and E_in the largest energy that has entered so far,
// max over the run of E0 + external_work (the energy-growth check's reference), at least 1/2 M V^2
// with a rigid object moving at V or a face starting at V (start()): E0 when no body force works.
// Divided by E0 alone, a body released at rest under gravity read in J and one released at 0.01 m/s
// read -7.4e4 (issue 53). 1 J if nothing has entered (an absolute error). Column names carry their
// unit, `name [unit]` (the point driver's convention); a plane-strain run's are per metre of
// thickness (extensive_units.hpp).
#pragma once

#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "models/core/tensor.hpp"
#include "mpm/ledger/extensive_units.hpp"
#include "mpm/ledger/totals.hpp"

namespace impact::mpm {

struct LedgerRow {
  double time = 0.0;
  double kinetic_energy = 0.0;
  double strain_energy = 0.0;
  double total_energy = 0.0;
  Vec3 momentum = Vec3::Zero();
  Vec3 boundary_impulse = Vec3::Zero();
  std::vector<double> sinks;  ///< in Ledger::sink_names() order
  double outflow_mass = 0.0;
  Vec3 outflow_momentum = Vec3::Zero();
  double outflow_kinetic_energy = 0.0;
  Vec3 external_impulse = Vec3::Zero();
  double external_work = 0.0;
  double energy_error = 0.0;
};

/// The components of `v` that are the body's (`mask` 1), the others +0 (the radial and hoop
/// components of a revolved body: scene/grid_geometry.hpp kMomentumComponents). A product with 0
/// would keep the sign of a negative one, and history.csv and summary.json would print -0.
inline Vec3 body_components(const Vec3& v, const Vec3& mask) {
  return {mask(0) != 0.0 ? v(0) : 0.0, mask(1) != 0.0 ? v(1) : 0.0, mask(2) != 0.0 ? v(2) : 0.0};
}

class Ledger {
 public:
  /// `with_external`: gravity is on, so body-force impulse and work get columns too;
  /// `with_outflow`: particles that leave the grid are removed (grid.outflow = remove), so their
  /// mass, momentum and kinetic energy get columns.
  /// `momentum_components`: 1 for each component of the particles' sum m v that is the body's
  /// momentum, 0 for one that is not: on an axisymmetric grid only the axial (x) one, since the
  /// radial momenta of a ring cancel (scene/grid_geometry.hpp kMomentumComponents); the others are
  /// booked as zero. `units`: of the columns (per metre of thickness in plane strain).
  explicit Ledger(bool with_external = false, bool with_outflow = false,
                  const Vec3& momentum_components = Vec3::Ones(), ExtensiveUnits units = {})
      : with_external_(with_external),
        with_outflow_(with_outflow),
        components_(momentum_components),
        units_(std::move(units)) {}
  const ExtensiveUnits& units() const { return units_; }

  /// Registers an energy sink column (J, accumulated; `name` without unit: the header gets
  /// "name [J]"); returns its index for add_sink(). `in_balance`: a term of energy_error (false
  /// for a column that itemises part of another term, e.g. friction heat within contact
  /// dissipation). `unchecked`: energy the energy-growth check takes out of its excess
  /// (growth_excess()), whatever `in_balance` says: a wall's friction heat (wall_friction_heat,
  /// itemised within friction_heat), booked from the grid's velocities, which at a contact that
  /// does not slide can exceed what the motion lost (grid/wall.cpp).
  int add_sink_column(std::string name, bool in_balance = true, bool unchecked = false);
  const std::vector<std::string>& sink_names() const { return sink_names_; }

  /// The state at t = 0 (E0 and p0). `drive` [J]: the energy scale of a rigid object moving at
  /// V, or of a face that starts at V, 1/2 M V^2 of the system's mass M
  /// (Simulation::restart_ledger; 0 without either): E_in is at least that from the start
  /// (docs/mpm.md#ledger). A face strains its material before its work is booked likewise. A rigid
  /// body set moving against a body at rest strains it from the first step, while contact books its
  /// work from the second (the start pass corrects velocities the particles do not carry); against
  /// an E_in of round-off the first step read energy_error 1e16 and the growth check stopped valid
  /// runs. `stored` [J]: energy held at t = 0 in a column other than kinetic and strain (the rigid
  /// contact's contact_energy, where a body is seeded overlapping a rigid object): part of E0.
  void start(double time, double kinetic_energy, const Vec3& momentum, double drive = 0.0,
             double stored = 0.0);
  /// One step's increments and end-of-step particle totals.
  void record_step(double time, double kinetic_energy, const Vec3& momentum,
                   double strain_energy_increment, const Vec3& boundary_impulse,
                   const Vec3& external_impulse, double external_work);
  void add_sink(int index, double energy) { s_.sinks[std::size_t(index)] += energy; }
  /// A sink column's value [J].
  double sink(int index) const { return s_.sinks[std::size_t(index)]; }
  /// Particles removed at the grid's edge this step (grid.outflow = remove).
  void add_outflow(double mass, const Vec3& momentum, double kinetic_energy) {
    s_.outflow_mass += mass;
    s_.outflow_momentum += booked(momentum);
    s_.outflow_kinetic += kinetic_energy;
  }

  LedgerRow row() const;
  /// The energy that entered so far: E0 + external_work [J].
  double energy_input() const { return s_.initial_energy + s_.external_work; }
  /// The largest energy_input() so far [J]: gravity's work falls back when a body rises again.
  double peak_energy_input() const { return s_.peak_input; }
  /// kinetic + strain + balance sinks + outflow - energy_input() [J]: the numerator
  /// of energy_error (no allocation: the solver's energy-growth check calls it every step).
  double energy_excess() const;
  /// energy_excess() without the unchecked sinks: the energy-growth check's excess [J].
  double growth_excess() const;
  /// The sinks growth_excess() counts (in the balance and checked), by name, with their values
  /// [J]: what the energy-growth check's message adds to kinetic + strain.
  std::vector<std::pair<std::string, double>> checked_sinks() const;
  double initial_energy() const { return s_.initial_energy; }
  const Vec3& initial_momentum() const { return s_.p0; }

  /// CSV header: "time [s]", "kinetic_energy [J]", ..., "energy_error [-]" (the solver's original
  /// names with their units).
  std::vector<std::string> columns() const;
  std::vector<double> values(const LedgerRow& r) const;
  bool with_external() const { return with_external_; }
  bool with_outflow() const { return with_outflow_; }

  /// Every accumulator: what a checkpoint saves (mpm/simulation/simulation_checkpoint.cpp walks
  /// kFields, then the sinks); restore() on a ledger with the same columns continues bit for bit.
  struct State {
    double time = 0.0, kinetic = 0.0, strain = 0.0, external_work = 0.0, initial_energy = 0.0;
    double outflow_mass = 0.0, outflow_kinetic = 0.0;
    double peak_input = 0.0;  ///< the largest E0 + external_work so far [J]
    Vec3 momentum = Vec3::Zero(), p0 = Vec3::Zero(), boundary_impulse = Vec3::Zero();
    Vec3 external_impulse = Vec3::Zero(), outflow_momentum = Vec3::Zero();
    std::vector<double> sinks;  ///< one per sink column, sized by add_sink_column()
    /// The checkpoint record, in file order (mpm/ledger/totals.hpp).
    static constexpr auto kFields = std::tuple{saved(&State::time),
                                               saved(&State::kinetic),
                                               saved(&State::strain),
                                               saved(&State::external_work),
                                               saved(&State::initial_energy),
                                               saved(&State::outflow_mass),
                                               saved(&State::outflow_kinetic),
                                               saved(&State::peak_input),
                                               saved(&State::momentum),
                                               saved(&State::p0),
                                               saved(&State::boundary_impulse),
                                               saved(&State::external_impulse),
                                               saved(&State::outflow_momentum)};
  };
  const State& state() const { return s_; }
  /// Throws std::invalid_argument when the number of sink columns differs.
  void restore(const State& s);

 private:
  bool with_external_, with_outflow_;
  Vec3 components_;
  ExtensiveUnits units_;
  Vec3 booked(const Vec3& v) const { return body_components(v, components_); }
  State s_;
  std::vector<std::string> sink_names_;
  std::vector<bool> in_balance_;
  std::vector<bool> unchecked_;
};

}  // namespace impact::mpm
