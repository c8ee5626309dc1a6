#include "mpm/simulation/diagnosis.hpp"

#include <cmath>
#include <sstream>

#include "models/core/input.hpp"
#include "mpm/simulation/simulation.hpp"

namespace impact::mpm {

// The energy-growth check. An unstable explicit step shows itself
// first as kinetic + strain energy growing far beyond what entered, many steps before a NaN or a
// particle leaving the grid. Reference: the largest energy that has entered so far, E_ref =
// max over the run of E_in = E0 + external_work (at least E0): gravity's work falls back when a
// body rises again, and a block ringing on a wall under gravity came back to its start height
// (E_in 6e-12 J after 3.7e-8 J) with 1e-8 J of motion, and was stopped as unstable at 24 us
// (wall friction 0.5; resting_contact_test); growth = (kinetic + strain + booked sinks + outflow -
// E_in) / E_ref, equal to energy_error whenever no work enters through gravity and no wall friction
// heat is booked. The walls' friction heat (wall_friction_heat) is left out
// (Ledger::add_sink_column's `unchecked`): it is booked from the grid's velocities, and at a wall
// contact that does not slide the face layer's grid-scale slip books heat that the motion never
// lost (a block at rest in a three-wall corner with mu 0.25: 1.7e-8 J by 1.02 ms while kinetic +
// strain - gravity's work stayed within
// [-1e-8, 0] J; it was stopped there as "unstable";
// tests/mpm/verification/resting_contact_test.cpp). An unstable step makes motion, which the check
// still sees. Nothing is checked while no energy has entered (E_ref = 0: a body at rest). Names the
// fastest particle: where the instability runs away.
std::optional<Failure> energy_growth(const Ledger& ledger, const Particles& P, const TimeSpec& t,
                                     const std::string& energy_unit) {
  const double reference = std::max(ledger.initial_energy(), ledger.peak_energy_input());
  const double excess = ledger.growth_excess();
  if (!(reference > 0.0) || !(excess > t.max_energy_growth * reference)) return std::nullopt;
  std::size_t fastest = 0;
  double speed2 = -1.0;
  for (std::size_t p = 0; p < P.size(); ++p) {  // ties: the lowest seed index
    const double s2 = P.v[p].squaredNorm();
    if (s2 > speed2 || (s2 == speed2 && seed_index(P, p) < seed_index(P, fastest))) {
      speed2 = s2;
      fastest = p;
    }
  }
  const LedgerRow r = ledger.row();
  std::ostringstream m;
  m.precision(6);
  const std::string& J = energy_unit;  // J, or J/m per metre of thickness (plane strain)
  m << "kinetic + strain energy " << r.total_energy << " " << J << " (kinetic " << r.kinetic_energy
    << " " << J << ", strain " << r.strain_energy << " " << J << ")";
  // The sinks the excess counts: energy the motion has given up, which an unstable step cannot
  // take back (a friction heat that grows is energy made as surely as motion is).
  for (const auto& [name, value] : ledger.checked_sinks())
    if (value != 0.0) m << " + " << name << " " << value << " " << J;
  if (r.outflow_kinetic_energy != 0.0)
    m << " + outflow_kinetic_energy " << r.outflow_kinetic_energy << " " << J;
  m << " against " << ledger.energy_input() << " " << J << " that entered (E0 "
    << ledger.initial_energy() << " " << J << ", external work " << r.external_work << " " << J
    << "; the most that had entered, " << reference << " " << J << ", is the reference): growth "
    << std::showpos << excess / reference << std::noshowpos << " (energy_error " << std::showpos
    << r.energy_error << std::noshowpos
    << ") above time.max_energy_growth = " << t.max_energy_growth
    << "; this particle is the fastest, |v| = " << std::sqrt(speed2)
    << " m/s: the explicit step is unstable (time.multiplier " << t.multiplier << "; lower it)";
  return Failure{fastest, "energy", m.str()};
}

std::optional<std::string> Simulation::non_finite_body_force() const {
  if (body_forces_->finite()) return std::nullopt;
  static const Eigen::IOFormat kRow(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  const std::size_t p = body_forces_->strongest();
  const SceneObject& o = scene_.objects[particles_.object[p]];
  std::ostringstream m;
  m.precision(9);
  m << "/objects/" << pointer_token(o.name) << "/body_force = [";
  for (int d = 0; d < 3; ++d) {
    m << (d ? ", " : "");
    if (o.body_force.text[d].empty())
      m << o.body_force.value(d);
    else
      m << '"' << o.body_force.text[d] << '"';
  }
  m << "] is [" << body_forces_->values()[p].transpose().format(kRow) << "] m/s^2 at X = ["
    << particles_.X[p].transpose().format(kRow) << "] m, t = " << time_ << " s: not finite";
  return describe(Failure{p, "body force", m.str(), std::nullopt}, steps_ + 1, time_);
}

double Simulation::checked_dt() const {
  const double dt = next_dt();
  const double body = scene_.solver.gravity.stableNorm() + max_body_force_;
  if (!(dt >= scene_.time.min_dt) && std::isfinite(body) &&
      body_force_time_step(scene_.grid.min_spacing(), body, scene_.time.multiplier) <
          stable_time_step(scene_.grid.min_spacing(), max_signal_speed_, scene_.time.multiplier)) {
    // The body force sets the step: name the particle that feels the most of it.
    std::ostringstream m;
    m.precision(6);
    m << "stable time step " << dt << " s below time.min_dt = " << scene_.time.min_dt
      << " s: the body-force step sqrt(time.multiplier x the smallest cell / (|solver.gravity| + "
         "max |body_force|)), with "
      << body << " m/s^2; this particle feels the largest body force";
    const std::size_t p = body_forces_ ? body_forces_->strongest() : 0;
    stop_if(ranks_.first_failure(
        describe(Failure{p, "time step", m.str(), std::nullopt}, steps_ + 1, time_)));
  }
  if (!(dt >= scene_.time.min_dt) || !std::isfinite(dt) || !(dt > 0.0)) {
    // The step collapses when one particle's signal speed c + |v| runs away: name it.
    std::size_t fastest = 0;
    double signal = -1.0;
    // A NaN wins over any speed; ties (and NaNs) go to the lowest seed index.
    for (std::size_t p = 0; p < particles_.size(); ++p) {
      const double c = particles_.wave_speed[p] + particles_.v[p].norm();
      const bool lower = seed_index(particles_, p) < seed_index(particles_, fastest);
      const bool take = std::isnan(signal) ? std::isnan(c) && lower
                                           : std::isnan(c) || c > signal || (c == signal && lower);
      if (take) {
        signal = c;
        fastest = p;
      }
    }
    std::ostringstream m;
    m.precision(6);
    m << "stable time step " << dt << " s below time.min_dt = " << scene_.time.min_dt
      << " s; this particle has the fastest signal, c + |v| = " << signal << " m/s";
    stop_if(ranks_.first_failure(
        describe(Failure{fastest, "time step", m.str(), std::nullopt}, steps_ + 1, time_)));
  }
  return std::min(dt, scene_.time.max_time - time_);  // land on max_time
}

std::string Simulation::describe(const Failure& f, long step, double time) const {
  static const Eigen::IOFormat kRow(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  const Particles& P = particles_;
  std::ostringstream m;
  m.precision(9);
  m << "step " << step << ", time " << time << " s: ";
  if (ranks_.several()) m << "rank " << ranks_.rank() << ", ";
  m << "particle " << (f.particle < P.id.size() ? P.id[f.particle] : f.particle);
  if (f.particle < P.size()) {
    const std::size_t p = f.particle;
    const PointState& s = f.state ? *f.state : P.state[p];
    const Mat3& t = s.stress;
    m.precision(6);
    m << " (material " << scene_.materials[P.material[p]].name << ", object "
      << scene_.objects[P.object[p]].name << ", x = [" << P.x[p].transpose().format(kRow)
      << "] m, v = [" << P.v[p].transpose().format(kRow) << "] m/s, stress xx yy zz xy yz zx = ["
      << t(0, 0) << ' ' << t(1, 1) << ' ' << t(2, 2) << ' ' << t(0, 1) << ' ' << t(1, 2) << ' '
      << t(0, 2) << "] Pa, eps_p = " << s.plastic_strain << ", T = " << s.temperature
      << " K, J = " << s.F.determinant() << ", damage = " << s.damage << ")";
  }
  m << ": " << f.field << ": " << f.message;
  // Through a wall met at the particles: the penalty's pressure has a bound, the nodes' hold none.
  if (f.field == "position" && f.particle < P.size() && scene_.grid.walls_at_particles())
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2;
      const bool beyond = face % 2 == 0 ? P.x[f.particle](axis) < scene_.grid.lower(axis)
                                        : P.x[f.particle](axis) > scene_.grid.upper(axis);
      if (scene_.grid.faces[std::size_t(face)] != FaceCondition::wall || !beyond) continue;
      m << "; it went through the " << kFaceNames[std::size_t(face)]
        << " wall, met at the particles (grid.wall_contact \"particles\"), whose penalty stops a "
           "body closing at up to about its wave speed c0 and holds a contact pressure up to "
           "about rho0 (c0 + 4 V)^2 / 4 (docs/scenes.md#grid): \"nodes\" holds any";
      break;
    }
  return m.str();
}

std::optional<std::string> Simulation::particle_outside_or_not_finite() const {
  // Every particle inside the grid with a finite velocity: what the stencils and the scatter
  // need. grid_to_particles checks the same at the end of every step, so in a run this finds
  // only what came in from outside the step (an injected fault).
  const Particles& P = particles_;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  const Vec3 lower = scene_.grid.lower, upper = scene_.grid.upper;
  const auto bad = [&](std::ptrdiff_t p) {
    return !((P.x[p].array() >= lower.array()).all() && (P.x[p].array() <= upper.array()).all() &&
             P.v[p].allFinite());
  };
  bool any = false;
#pragma omp parallel for schedule(static) reduction(|| : any) num_threads(grid_.threads())
  for (std::ptrdiff_t p = 0; p < n; ++p) any = any || bad(p);
  if (!any) return std::nullopt;
  std::optional<Failure> first;  // the lowest seed index (step/step.hpp fails_first)
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    if (!bad(p) || !fails_first(P, std::size_t(p), first)) continue;
    const bool inside =
        (P.x[p].array() >= lower.array()).all() && (P.x[p].array() <= upper.array()).all();
    first = inside ? Failure{std::size_t(p), "velocity", "not finite at the start of the step",
                             std::nullopt}
                   : Failure{std::size_t(p), "position",
                             "outside the grid at the start of the step", std::nullopt};
  }
  if (!first) return std::nullopt;
  return describe(*first, steps_ + 1, time_);
}

}  // namespace impact::mpm
