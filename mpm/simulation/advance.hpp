// One explicit MPM step on one screen: the phases of mpm/step/ in order (USL or MUSL), each timed.
// Equations: Sulsky, Chen & Schreyer (1994) 20-26; MUSL: Sulsky, Zhou & Schreyer (1995) and Nairn
// (2003); contact: Bardenhagen et al. (2001); strain energy: report eq. 14; artificial viscosity:
// report eq. 12.
#pragma once

#include <omp.h>

#include <optional>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/parallel/halo_exchange.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/simulation/step_totals.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

/// What a step reads besides the particles, the grid and the shape: fixed for a run.
struct StepSetup {
  const StressUpdateSettings& stress;
  const SolverSpec& solver;
  const ContactSpec* contact;                      ///< null with one velocity field
  const std::vector<HeatCapacity>& heat_capacity;  ///< per material, for friction heating
  const HaloExchange* halo;                        ///< null on one rank
  /// b_p per particle of this step [m/s^2] (step/body_force.hpp); null: no body force.
  const std::vector<Vec3>* body_force;
  /// The rigid objects' contact force per particle [N] (contact/rigid_particle_contact.hpp); null
  /// where bodies meet them at the nodes.
  const std::vector<Vec3>* rigid_force = nullptr;
};

/// Attributes wall time to the phases of a step.
class PhaseClock {
 public:
  explicit PhaseClock(PhaseTimes& times) : times_(times), last_(omp_get_wtime()) {}
  void lap(double PhaseTimes::*phase) {
    const double now = omp_get_wtime();
    times_.*phase += now - last_;
    last_ = now;
  }

 private:
  PhaseTimes& times_;
  double last_;
};

/// Advances P by dt on G; `failure` is set (and the stress update skipped) when a
/// particle fails in the grid-to-particle phase on any rank.
template <class Shape>
StepTotals advance(Particles& P, Grid& G, const Shape& shape, Stencils<Shape>& S,
                   ScatterOrder& order, const StepSetup& run, double dt,
                   std::optional<Failure>& failure) {
  StepTotals t;
  PhaseClock clock(t.seconds);
  const bool usl = run.solver.scheme == Scheme::usl;
  t.narrowed = compute_stencils<Shape>(P, shape, S, G.threads());  // S_Ip, grad S_Ip at x^n
  order_for_scatter(S, G, order);  // by band and colour: race-free scatters, any thread count
  const Vec3* body = run.body_force ? run.body_force->data() : nullptr;  // b(X_p, t^n)
  const Vec3* rigid = run.rigid_force ? run.rigid_force->data() : nullptr;
  particles_to_grid<Shape>(P, G, S, order, dt, run.halo, body, rigid);  // m_I, p_I, f_I (20-22)
  if (run.contact && run.contact->normal == ContactNormal::logistic_regression && G.fields() > 1)
    fit_contact_planes<Shape>(P, G, shape, S, run.halo,  // the planes between bodies (Nairn 2020)
                              run.contact->detection == ContactDetection::separation);
  clock.lap(&PhaseTimes::particles_to_grid);
  t.grid = grid_update(G, dt, run.solver.gravity, usl, run.contact);  // v*_I, contact, faces (24)
  clock.lap(&PhaseTimes::grid_update);
  // FLIP velocity, x from v*_I; USL: L from v^L_I (= v*_I but at light nodes)   (eqs. 23, 25-26)
  // (x of a particle the rigid contact pushed: from the velocity its L takes, step.hpp)
  t.particles = grid_to_particles<Shape>(P, G, S, dt, /*usl_gradient=*/usl, run.heat_capacity,
                                         failure, body, rigid);
  clock.lap(&PhaseTimes::grid_to_particles);
  if (run.halo ? run.halo->comm().any(failure.has_value()) : failure.has_value()) return t;
  if (!usl) {
    // MUSL: L from v^{n+1}_I, and the particles the rigid contact pushed moved with it
    remap_and_gradient<Shape>(P, G, S, order, run.contact, run.halo, dt, rigid);
    clock.lap(&PhaseTimes::remap);
  }
  t.stress = update_stress(P, run.stress, dt, failure);  // sigma, F, V, q; eq. 14
  clock.lap(&PhaseTimes::stress);
  return t;
}

}  // namespace impact::mpm
