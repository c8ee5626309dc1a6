#include "mpm/simulation/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "mpm/particles/particle_order.hpp"
#include "mpm/scene/rigid_surface.hpp"
#include "mpm/scene/seed_points.hpp"
#include "mpm/simulation/advance.hpp"
#include "mpm/simulation/diagnosis.hpp"
#include "mpm/threads/threads.hpp"

namespace impact::mpm {

namespace {

AnyStencils make_stencils(const AnyShape& shape) {
  return std::visit(
      [](const auto& s) -> AnyStencils { return Stencils<std::decay_t<decltype(s)>>{}; }, shape);
}

int thread_count(int requested) {
  if (requested > 0) omp_set_num_threads(std::min(requested, kMaxThreads));
  return std::min(omp_get_max_threads(), kMaxThreads);
}

}  // namespace

Simulation::Simulation(const Scene& scene, int threads, const Communicator& comm)
    : scene_(scene),
      ranks_(comm),
      // On several ranks every rank counts the seed points per cell (census_), splits the grid
      // the same way, and seeds and stores only its box: no rank ever holds the whole scene or
      // the whole grid.
      census_(ranks_.census(scene)),
      boxes_(ranks_.split(scene, census_)),
      particles_(ranks_.seed(scene, boxes_, census_)),
      grid_(scene.grid.at_the_nodes(), grid_settings(thread_count(threads)),
            ranks_.stored_box(boxes_, scene.grid)),
      shape_(make_shape(scene)),
      stencils_(make_stencils(shape_)),
      ledger_(!scene.solver.gravity.isZero(0.0) || scene.has_body_force() ||
                  // a moving rigid object works on what it pushes
                  scene.grid.has_moving_faces() || scene.rigid_speed() > 0.0,
              scene.grid.outflow == Outflow::remove,
              Vec3(scene.grid.geometry_facts().momentum_components.data()),
              ExtensiveUnits::of(scene.grid.per_metre_of_thickness())) {
  census_ = {};  // needed for seeding only
  // Another storage order (scene.hpp SolverSpec), each particle keeping its seed index.
  if (const std::uint64_t seed = scene_.solver.shuffle_particles)
    store_in_order(particles_, shuffled_order(particles_.size(), seed));
  if (ranks_.several()) {
    grid_.set_owned(ranks_.owned_box(boxes_, scene_.grid.cells));
    halo_.emplace(ranks_.communicator(), boxes_);
  }
  const PhysicsSpec& ph = scene_.physics;
  StressUpdateSettings& st = stress_settings_;
  bool erosion = false;
  for (std::size_t m = 0; m < scene_.materials.size(); ++m) {
    const ElasticPlastic& model = scene_.materials[m].material.model;
    st.models.push_back(&model);
    heat_capacity_.push_back({model.params().heating.enabled, model.params().specific_heat});
    erosion = erosion || model.params().erosion != Erosion::none;
    if (ph.create_new_particles && scene_.companion_field(int(m)) != scene_.parent_field(int(m))) {
      st.companion_field.push_back(static_cast<std::uint16_t>(scene_.companion_field(int(m))));
    }
  }
  // Rigid objects: their fields are held at their velocities (grid/rigid_fields.cpp), their
  // particles never strain, and only their speed enters the time step.
  st.rigid_field = grid_.settings().rigid_field;
  const std::uint8_t* const rigid = st.rigid_field.empty() ? nullptr : st.rigid_field.data();
  for (std::size_t p = 0; p < particles_.size(); ++p)
    if (in_rigid_field(rigid, particles_, p)) particles_.wave_speed[p] = 0.0;
  st.f_integration = scene_.solver.f_integration;
  st.fail_particle = ph.on_numerical_fault == NumericalFaultAction::fail_particle;
  if (st.fail_particle) particles_.fault.assign(particles_.size(), 0);
  if (scene_.grid.outflow == Outflow::remove) particles_.removed.assign(particles_.size(), 0);
  if (scene_.needs_reference_positions())
    particles_.X = particles_.x;  // the reference positions: the seed points
  if (scene_.friction_at_particles())
    particles_.friction_anchor = particles_.x;  // each stick spring slack where it starts
  if (scene_.damping_at_particles())
    particles_.damper_velocity = particles_.v;  // each particle moves with its own at the start
  if (scene_.has_body_force()) body_forces_.emplace(scene_, grid_.threads());
  if (scene_.contact_at_particles()) {
    std::vector<Vec3> widths;  // uGIMP's half-widths per object [m] (a graded grid's: per particle)
    for (const Vec3& l : half_widths(scene_))
      widths.push_back(l.cwiseProduct(scene_.grid.spacing()));
    particle_contact_.emplace(scene_, grid_.settings().rigid_surface,
                              grid_.settings().rigid_velocity, std::move(widths));
  }
  if (scene_.grid.has_moving_faces()) face_motions_.emplace(scene_.grid, scene_.constants);
  st.mean_spacing = scene_.grid.mean_spacing();
  if (scene_.grid.graded()) st.graded_grid = &scene_.grid;
  if (ph.artificial_viscosity.enabled) {
    st.viscosity = &scene_.physics.artificial_viscosity;
    particles_.q.assign(particles_.size(), 0.0);
  }
  // The ledger's columns follow the physics the scene switched on.
  if (st.viscosity) sinks_.viscous = ledger_.add_sink_column("viscous_work");
  // Contact's normal reaction does no work; friction's Coulomb work is heat (contact.hpp).
  // So is the Coulomb work of a wall face (grid/wall.cpp): one column for both, and the walls'
  // part itemised, which the energy-growth check leaves out (simulation/diagnosis.cpp).
  if (scene_.contact_friction() || scene_.grid.has_wall_friction())
    sinks_.friction = ledger_.add_sink_column("friction_heat");
  if (grid_.spec().has_wall_friction())  // the walls at the nodes (at the particles: as rigid)
    sinks_.wall_friction = ledger_.add_sink_column("wall_friction_heat", /*in_balance=*/false,
                                                   /*unchecked=*/true);
  if (erosion) sinks_.eroded = ledger_.add_sink_column("eroded_energy", /*in_balance=*/false);
  // Plastic work is part of the strain energy already booked: a column, not a term of the balance.
  st.plastic_work = scene_.output.plastic_work;
  if (st.plastic_work)
    sinks_.plastic = ledger_.add_sink_column("plastic_work", /*in_balance=*/false);
  // The energy stored in the contact at the particles (rigid objects, walls): it rises and falls.
  if (particle_contact_) sinks_.contact_energy = ledger_.add_sink_column("contact_energy");
  // Its dashpots' dissipation (contact.penalty_damping, grid.wall_penalty_damping), a numerical
  // sink named as one.
  if (scene_.damping_at_particles())
    sinks_.contact_damping = ledger_.add_sink_column("contact_damping");
  restart_ledger();
}

GridSettings Simulation::grid_settings(int threads) const {
  GridSettings g;
  g.threads = threads;
  g.fields = scene_.field_count();
  g.friction_heat = scene_.contact_friction();
  if (g.fields > 1) {  // contact bodies: a material's parent and companion fields
    g.field_body.assign(std::size_t(g.fields), 0);
    g.field_density.assign(std::size_t(g.fields), 1.0);
    for (int m = 0; m < static_cast<int>(scene_.materials.size()); ++m) {
      g.field_body[std::size_t(scene_.parent_field(m))] = m;
      g.field_body[std::size_t(scene_.companion_field(m))] = m;
      const double rho = scene_.materials[std::size_t(m)].material.model.params().density;
      g.field_density[std::size_t(scene_.parent_field(m))] = rho;
      g.field_density[std::size_t(scene_.companion_field(m))] = rho;
    }
  }
  // Rigid objects' fields, whatever the field count (one material of rigid objects alone is one
  // field): the one table the grid, the stress update and the ledger read.
  for (const std::optional<Vec3>& V : scene_.rigid_field_velocities()) {
    g.rigid_field.push_back(V.has_value());
    g.rigid_velocity.push_back(V.value_or(Vec3::Zero()));
  }
  g.rigid_friction = scene_.rigid_field_friction();
  g.rigid_surface = rigid_field_surfaces(scene_);  // contact's normal against them
  // The light-node rule's mass (kLightNodeMassFraction in step/step.hpp), by the geometry's rule.
  const LightNode light = visit_geometry(scene_.grid.geometry, [&](auto geometry) {
    return decltype(geometry)::light_node(particles_.mass, particles_.x,
                                          [&](double v) { return ranks_.min(v); });
  });
  g.light_radius = light.radius;
  g.node_mean_mass = scene_.grid.graded() && scene_.solver.scheme == Scheme::usl;
  if (std::isfinite(light.lightest)) g.light_mass = kLightNodeMassFraction * light.lightest;
  // Walls hold only where a particle's domain reaches them (grid/wall.cpp); the bodies' separation
  // measures the domains too (step/contact_planes.cpp). Every rank scatters
  // the touch bits of its particles (the sums carry them to the rank holding the wall's nodes),
  // also one whose box stores no wall node.
  if ((scene_.grid.has_walls() && !scene_.grid.walls_at_particles()) ||
      (g.fields > 1 && scene_.physics.contact.detection == ContactDetection::separation))
    for (const Vec3& l : half_widths(scene_))
      g.particle_half_width.push_back(l.cwiseProduct(scene_.grid.spacing()));
  return g;
}

void Simulation::resize_particles(std::size_t n) {
  Particles& P = particles_;
  // Which optional arrays the scene uses (a rank may have held no particle when they were set).
  const bool q = stress_settings_.viscosity != nullptr;
  const bool fault = stress_settings_.fail_particle;
  const bool removed = scene_.grid.outflow == Outflow::remove;
  const bool id = ranks_.several() || scene_.solver.shuffle_particles != 0;
  const bool reference = scene_.needs_reference_positions();
  P.for_each_array([&](auto& a) { a.resize(n); });
  if (!q) P.q.clear();
  if (!fault) P.fault.clear();
  if (!removed) P.removed.clear();
  if (!id) P.id.clear();
  if (!reference) P.X.clear();
  if (!scene_.grid.graded()) P.half_width.clear();
  if (!scene_.friction_at_particles()) P.friction_anchor.clear();
  if (!scene_.damping_at_particles()) P.damper_velocity.clear();
}

void Simulation::restart_ledger() {
  double ke = 0.0;
  Vec3 p = Vec3::Zero();
  double mass = 0.0;
  const std::vector<std::uint8_t>& table = stress_settings_.rigid_field;
  const std::uint8_t* const rigid = table.empty() ? nullptr : table.data();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    if (in_rigid_field(rigid, particles_, i)) continue;  // not the system's (contact.hpp)
    ke += 0.5 * particles_.mass[i] * particles_.v[i].squaredNorm();
    p += particles_.mass[i] * particles_.v[i];
    mass += particles_.mass[i];
  }
  // Summed (and the signal speed maximised) over the ranks.
  const std::vector<double> sum = ranks_.sum({ke, p(0), p(1), p(2), mass});
  max_signal_speed_ = ranks_.max(max_signal_speed(particles_));
  // A moving rigid object's energy scale: the system moving at its speed (Ledger::start); and a
  // face that starts moving, whose first steps strain the material before its work is booked (a
  // block at rest under a face started at 1 m/s and a body force applied at once: energy_error
  // +1872 at step 1 against the body force's work alone, and the run stopped).
  double V = scene_.rigid_speed();
  if (face_motions_)
    for (const double v : face_motions_->at(0.0)) V = std::max(V, std::abs(v));
  // A body seeded overlapping a rigid object beyond its clipped reach starts with contact energy.
  const double stored = particle_contact_ ? evaluate_particle_contact()[0] : 0.0;
  ledger_.start(0.0, sum[0], Vec3(sum[1], sum[2], sum[3]), 0.5 * sum[4] * V * V, stored);
  if (sinks_.contact_energy >= 0)
    ledger_.add_sink(sinks_.contact_energy, stored - ledger_.sink(sinks_.contact_energy));
}

std::vector<double> Simulation::evaluate_particle_contact() {
  particle_contact_->evaluate(particles_, time_, grid_.threads());
  const Vec3& F = particle_contact_->total_force();
  particle_contact_sums_ =
      ranks_.sum({particle_contact_->energy(), F(0), F(1), F(2), particle_contact_->power(),
                  particle_contact_->friction_heat()});
  particle_contact_current_ = true;
  return particle_contact_sums_;
}

double Simulation::next_dt() const {
  // A moving face drives its material at |V| before the particles' velocities show it (they take
  // the face's jumps through the stress): the signal runs at up to c + |v| + |V|.
  // A rigid object drives what it pushes at its speed likewise (Scene::rigid_speed).
  // Contact at the particles: its penalty's frequency (RigidParticleContact::signal_speed).
  const double contact = particle_contact_ ? particle_contact_->signal_speed() : 0.0;
  const double waves =
      stable_time_step(scene_.grid.min_spacing(),
                       std::max(max_signal_speed_ + face_speed_ + scene_.rigid_speed(), contact),
                       scene_.time.multiplier);
  // No signal at all (every particle left the grid, grid.outflow = remove): nothing is left to
  // integrate, and gravity, which limits the step of a body, has none to move.
  if (max_signal_speed_ == 0.0 && std::isinf(std::min(waves, scene_.time.max_dt)))
    return scene_.time.max_time - time_;
  // Gravity and the objects' body forces at the start of this step, at most their sum.
  const double body = scene_.solver.gravity.stableNorm() + max_body_force_;
  double dt = std::min(
      waves, body_force_time_step(scene_.grid.min_spacing(), body, scene_.time.multiplier));
  if (steps_ == 0) dt = std::min(dt, scene_.time.initial_dt);
  return std::min(dt, scene_.time.max_dt);
}

const StepTotals& Simulation::step() {
  apply_injections();
  stop_if(ranks_.first_failure(particle_outside_or_not_finite()));  // a failure stops every rank
  if (body_forces_) {  // b(X_p, t^n), before the step it limits
    body_forces_->evaluate(particles_, time_);
    stop_if(ranks_.first_failure(non_finite_body_force()));
    max_body_force_ = ranks_.max(body_forces_->peak());
  }
  if (particle_contact_ && !particle_contact_current_) evaluate_particle_contact();  // at x^n, t^n
  if (face_motions_) {
    face_speed_ = 0.0;
    for (const double v : face_motions_->at(time_))
      face_speed_ = std::max(face_speed_, std::abs(v));
  }
  const double dt = checked_dt();
  if (face_motions_)
    grid_.set_face_velocities(face_motions_->at(time_), face_motions_->at(time_ + dt));
  grid_.set_time(time_);  // where the rigid objects' surfaces are
  std::optional<Failure> failure;
  last_ = advance_step(dt, failure);
  phase_totals_ += last_.seconds;
  stop_if(ranks_.first_failure(failure ? std::optional(describe(*failure, steps_ + 1, time_ + dt))
                                       : std::nullopt));
  ranks_.reduce(last_.particles, last_.stress, last_.grid);
  book(dt);
  // The step is complete (time, ledger and particles at t^{n+1}): the failure names this step.
  const std::optional<Failure> grown =
      energy_growth(ledger_, particles_, scene_.time,
                    ExtensiveUnits::of(scene_.grid.per_metre_of_thickness()).energy);
  stop_if(
      ranks_.first_failure(grown ? std::optional(describe(*grown, steps_, time_)) : std::nullopt));
  migrated_ = ranks_.migrate(particles_, boxes_, scene_.grid);  // those that left this box
  rebalance_if_needed();
  // The rigid contact's forces are per particle: on several ranks the particles have moved.
  if (ranks_.several()) particle_contact_current_ = false;
  return last_;
}

StepTotals Simulation::advance_step(double dt, std::optional<Failure>& failure) {
  const ContactSpec* contact = grid_.fields() > 1 ? &scene_.physics.contact : nullptr;
  const StepSetup setup{stress_settings_,
                        scene_.solver,
                        contact,
                        heat_capacity_,
                        halo_ ? &*halo_ : nullptr,
                        body_forces_ ? &body_forces_->values() : nullptr,
                        particle_contact_ ? &particle_contact_->forces() : nullptr};
  StepTotals t = std::visit(
      [&](const auto& shape) {
        using Shape = std::decay_t<decltype(shape)>;
        return advance(particles_, grid_, shape, std::get<Stencils<Shape>>(stencils_),
                       scatter_order_, setup, dt, failure);
      },
      shape_);
  stress_settings_.inject_nan_stress = -1;
  return t;
}

void Simulation::book(double dt) {
  time_ += dt;
  ++steps_;
  max_signal_speed_ = last_.stress.max_signal_speed;
  Vec3 boundary_impulse = last_.grid.boundary_impulse;
  double external_work = last_.grid.external_work + last_.particles.external_work;
  if (particle_contact_) {  // the step's rigid contact forces, at t^n: their impulse, and their
                            // work
    const std::vector<double>& c = particle_contact_sums_;  // at the rigid objects' velocities
    boundary_impulse += dt * Vec3(c[1], c[2], c[3]);
    external_work += dt * c[4];
  }
  ledger_.record_step(time_, last_.particles.kinetic_energy, last_.particles.momentum,
                      last_.stress.strain_energy_increment, boundary_impulse,
                      last_.grid.external_impulse + last_.particles.external_impulse,
                      external_work);
  double rigid_friction_heat = 0.0;
  if (sinks_.contact_damping >= 0)  // the step's dashpots, on the motion they acted on
    ledger_.add_sink(sinks_.contact_damping,
                     ranks_.sum(std::vector<double>{
                         particle_contact_->damper_work(particles_, dt, grid_.threads())})[0]);
  if (particle_contact_) {  // the contact's energy at t^{n+1}, its forces for the next step, and
                            // the
    // heat of the slip since t^n
    const std::vector<double> sums = evaluate_particle_contact();
    ledger_.add_sink(sinks_.contact_energy, sums[0] - ledger_.sink(sinks_.contact_energy));
    rigid_friction_heat = sums[5];
  }
  if (sinks_.viscous >= 0) ledger_.add_sink(sinks_.viscous, last_.stress.viscous_work);
  if (sinks_.friction >= 0) {
    ledger_.add_sink(sinks_.friction, last_.grid.contact.friction_heat +
                                          last_.grid.wall_friction_heat + rigid_friction_heat);
  }
  if (sinks_.wall_friction >= 0)
    ledger_.add_sink(sinks_.wall_friction, last_.grid.wall_friction_heat);
  if (sinks_.eroded >= 0) ledger_.add_sink(sinks_.eroded, last_.stress.eroded_energy);
  if (sinks_.plastic >= 0) ledger_.add_sink(sinks_.plastic, last_.stress.plastic_work);
  if (last_.particles.removed > 0) {
    ledger_.add_outflow(last_.particles.outflow_mass, last_.particles.outflow_momentum,
                        last_.particles.outflow_kinetic_energy);
    removed_ += last_.particles.removed;
  }
  failed_ += last_.stress.failed;
  converted_ += last_.stress.converted;
  faulted_ += ranks_.sum(static_cast<long>(last_.stress.faulted.size()));
  if (scene_.grid.graded()) narrowed_ += ranks_.sum(last_.narrowed);
}

void Simulation::stop_if(const std::optional<std::string>& message) const {
  if (message) throw SolverFailure(*message);
}

void Simulation::rebuild_grid() {
  grid_ =
      Grid(scene_.grid.at_the_nodes(), grid_.settings(), ranks_.stored_box(boxes_, scene_.grid));
  grid_.set_owned(ranks_.owned_box(boxes_, scene_.grid.cells));
}

void Simulation::rebalance_if_needed() {
  std::optional<BoxDecomposition> next = ranks_.rebalanced(particles_, boxes_, scene_);
  if (!next) return;
  boxes_ = std::move(*next);
  rebuild_grid();
  migrated_ += ranks_.migrate(particles_, boxes_, scene_.grid);
  ++rebalances_;
}

void Simulation::inject(const FaultInjection& fault) {
  if (fault.is_signal())
    throw std::invalid_argument("a signal is raised by run(), not the Simulation");
  // The particle is its seed index, on any number of ranks (collective on several).
  const auto total = static_cast<std::size_t>(ranks_.sum(long(particles_.size())));
  if (fault.particle >= total) {
    throw std::out_of_range("particle " + std::to_string(fault.particle) + " out of range (" +
                            std::to_string(total) + " particles)");
  }
  injections_.push_back(fault);
}

void Simulation::apply_injections() {
  if (injections_.empty()) return;
  stress_settings_.inject_nan_stress =
      apply_faults(injections_, steps_ + 1, particles_, scene_.grid);
}

}  // namespace impact::mpm
