#include "mpm/solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "mpm/parallel/decomposition_plan.hpp"
#include "mpm/parallel/migration.hpp"
#include "mpm/step/parallel.hpp"

namespace impact::mpm {

namespace {

// Attributes wall time to the phases of a step.
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

// One explicit step (USL or MUSL). Equations: Sulsky, Chen & Schreyer (1994) 20-26; MUSL:
// Sulsky, Zhou & Schreyer (1995) and Nairn (2003); contact: Bardenhagen et al. (2001); strain
// energy: report eq. 14; artificial viscosity: report eq. 12.
template <class Shape>
StepTotals advance(Particles& P, Grid& G, const Shape& shape, Stencils<Shape>& S,
                   ScatterOrder& order, const StressUpdateSettings& settings, const SolverSpec& s,
                   const ContactSpec* contact, const std::vector<HeatCapacity>& heat_capacity,
                   double dt, const HaloExchange* halo, std::optional<Failure>& failure) {
  StepTotals t;
  PhaseClock clock(t.seconds);
  const bool usl = s.scheme == Scheme::usl;
  compute_stencils<Shape>(P, shape, S, G.threads());  // S_Ip, grad S_Ip at x^n, once per step
  order_for_scatter(S, G, order);  // by slab and colour: race-free scatters, any thread count
  particles_to_grid<Shape>(P, G, S, order, dt, halo);  // m_I, p_I, f_I per field (eqs. 20-22)
  clock.lap(&PhaseTimes::particles_to_grid);
  t.grid = grid_update(G, dt, s.gravity, usl, contact);  // v*_I, contact, faces (eq. 24)
  clock.lap(&PhaseTimes::grid_update);
  // FLIP velocity, x from v*_I; USL: L from v^L_I (= v*_I but at light nodes)   (eqs. 23, 25-26)
  t.particles = grid_to_particles<Shape>(P, G, S, dt, /*usl_gradient=*/usl, heat_capacity, failure);
  clock.lap(&PhaseTimes::grid_to_particles);
  if (halo ? halo->comm().any(failure.has_value()) : failure.has_value()) return t;
  if (!usl) {
    remap_and_gradient<Shape>(P, G, S, order, contact, halo);  // MUSL: L from re-mapped v^{n+1}_I
    clock.lap(&PhaseTimes::remap);
  }
  t.stress = update_stress(P, settings, dt, failure);  // sigma, F, V, q; eq. 14
  clock.lap(&PhaseTimes::stress);
  return t;
}

AnyStencils make_stencils(const AnyShape& shape) {
  return std::visit(
      [](const auto& s) -> AnyStencils { return Stencils<std::decay_t<decltype(s)>>{}; }, shape);
}

int thread_count(int requested) {
  if (requested > 0) omp_set_num_threads(std::min(requested, kMaxThreads));
  return std::min(omp_get_max_threads(), kMaxThreads);
}

// The energy-growth check (docs/mpm.md#failure-handling). An unstable explicit step shows itself
// first as kinetic + strain energy growing far beyond what entered, many steps before a NaN or a
// particle leaving the grid. Reference: the energy that entered, E_in = E0 + external_work (at
// least E0); growth = (kinetic + strain + booked sinks + outflow - E_in) / E_ref, equal to
// energy_error whenever no work enters through gravity. Nothing is checked while no
// energy has entered (E_ref = 0: a body at rest). Names the fastest particle: where the
// instability runs away.
std::optional<Failure> energy_growth(const Ledger& ledger, const Particles& P, const TimeSpec& t) {
  const double reference = std::max(ledger.initial_energy(), ledger.energy_input());
  const double excess = ledger.energy_excess();
  if (!(reference > 0.0) || !(excess > t.max_energy_growth * reference)) return std::nullopt;
  std::size_t fastest = 0;
  double speed2 = -1.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.v[p].squaredNorm() > speed2) {
      speed2 = P.v[p].squaredNorm();
      fastest = p;
    }
  }
  const LedgerRow r = ledger.row();
  std::ostringstream m;
  m.precision(6);
  m << "kinetic + strain energy " << r.total_energy << " J (kinetic " << r.kinetic_energy
    << " J, strain " << r.strain_energy << " J) against " << ledger.energy_input()
    << " J that entered (E0 " << ledger.initial_energy() << " J, external work " << r.external_work
    << " J): growth " << std::showpos << excess / reference << std::noshowpos << " (energy_error "
    << std::showpos << r.energy_error << std::noshowpos
    << ") above time.max_energy_growth = " << t.max_energy_growth
    << "; this particle is the fastest, |v| = " << std::sqrt(speed2)
    << " m/s: the explicit step is unstable (time.multiplier " << t.multiplier << "; lower it)";
  return Failure{fastest, "energy", m.str()};
}

}  // namespace

Simulation::SeedCensus Simulation::census(const Scene& scene, const Communicator& comm) {
  // Each rank counts an equal block of cell columns and the counts (whole numbers) are summed:
  // no rank walks every seed point of the scene.
  const long columns = scene.grid.cells[0], ranks = comm.size(), r = comm.rank();
  SeedCensus c;
  const bool least_loaded =
      scene.solver.split == SplitRule::least_loaded && scene.solver.ranks_per_axis[0] == 0;
  c.columns = seed_counts_per_column(
      scene, &c.per_axis, int(columns * r / ranks), int(columns * (r + 1) / ranks),
      least_loaded ? std::function<void(const std::array<int, 3>&)>(
                         [&](const std::array<int, 3>& cell) { count_cell(c.cells, cell); })
                   : nullptr);
  std::vector<double> table;  // each object's columns, then the cells along each axis
  for (const auto& object : c.columns)
    for (const std::size_t n : object) table.push_back(double(n));
  for (const auto& axis : c.per_axis)
    for (const std::size_t n : axis) table.push_back(double(n));
  table = comm.sum_counts(table);
  std::size_t k = 0;
  for (auto& object : c.columns)
    for (std::size_t& n : object) n = std::size_t(table[k++]);
  for (auto& axis : c.per_axis)
    for (std::size_t& n : axis) n = std::size_t(table[k++]);
  return c;
}

BoxDecomposition Simulation::split(const Scene& scene, const SeedCensus& census,
                                   const Communicator& comm) {
  // "least_loaded": the census counted this rank's block's points per cell; the tables the
  // search builds from them are summed over the ranks.
  return initial_boxes(
      scene, comm.size(), census.per_axis, [&] { return census.cells; },
      [&](const std::vector<double>& table) { return comm.sum_counts(table); });
}

Simulation::Simulation(const Scene& scene, int threads, const Communicator* comm)
    : scene_(scene),
      comm_(comm != nullptr && comm->size() > 1 ? comm : nullptr),
      census_(comm_ ? census(scene, *comm_) : SeedCensus{}),
      // On several ranks every rank counts the seed points per cell (census_), splits the grid
      // the same way, and seeds and stores only its box: no rank ever holds the whole scene or
      // the whole grid.
      boxes_(comm_ ? split(scene, census_, *comm_) : BoxDecomposition(scene.grid.cells)),
      particles_(comm_ ? seed_box(scene, boxes_.first_cell(comm_->rank()),
                                  boxes_.end_cell(comm_->rank()), census_.columns)
                       : seed_particles(scene)),
      grid_(scene.grid, thread_count(threads), scene.field_count(),
            scene.field_count() > 1 && scene.physics.contact.type == ContactType::friction &&
                scene.physics.contact.mu > 0.0,
            stored_box()),
      shape_(make_shape(scene)),
      stencils_(make_stencils(shape_)),
      ledger_(!scene.solver.gravity.isZero(0.0), scene.grid.outflow == Outflow::remove) {
  census_ = SeedCensus{};  // needed for seeding only
  if (comm_) {
    own_box();
    halo_.emplace(*comm_, boxes_);
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
  st.f_integration = scene_.solver.f_integration;
  st.fail_particle = ph.on_numerical_fault == NumericalFaultAction::fail_particle;
  if (st.fail_particle) particles_.fault.assign(particles_.size(), 0);
  if (scene_.grid.outflow == Outflow::remove) particles_.removed.assign(particles_.size(), 0);
  st.mean_spacing = scene_.grid.spacing().sum() / 3.0;
  if (ph.artificial_viscosity.enabled) {
    st.viscosity = &scene_.physics.artificial_viscosity;
    particles_.q.assign(particles_.size(), 0.0);
  }
  // The ledger's columns follow the physics the scene switched on.
  if (st.viscosity) sinks_.viscous = ledger_.add_sink_column("viscous_work");
  // Contact's normal reaction does no work; friction's Coulomb work is heat (contact.hpp).
  // So is the Coulomb work of a wall face (grid/wall.cpp): one column for both.
  if ((grid_.fields() > 1 && ph.contact.type == ContactType::friction && ph.contact.mu > 0.0) ||
      scene_.grid.has_wall_friction())
    sinks_.friction = ledger_.add_sink_column("friction_heat");
  if (erosion) sinks_.eroded = ledger_.add_sink_column("eroded_energy", /*in_balance=*/false);
  if (grid_.fields() > 1) {  // contact bodies: a material's parent and companion fields
    grid_.field_body.assign(grid_.fields(), 0);
    grid_.field_density.assign(grid_.fields(), 1.0);
    for (int m = 0; m < static_cast<int>(scene_.materials.size()); ++m) {
      grid_.field_body[scene_.parent_field(m)] = m;
      grid_.field_body[scene_.companion_field(m)] = m;
      const double rho = scene_.materials[std::size_t(m)].material.model.params().density;
      grid_.field_density[scene_.parent_field(m)] = rho;
      grid_.field_density[scene_.companion_field(m)] = rho;
    }
  }
  double lightest = std::numeric_limits<double>::infinity();
  for (const double m : particles_.mass) lightest = std::min(lightest, m);
  if (comm_) lightest = comm_->min(lightest);
  if (std::isfinite(lightest)) grid_.light_mass = kLightNodeMassFraction * lightest;
  // Walls hold only where a particle's domain reaches them (grid/wall.cpp).
  if (grid_.has_walls())
    for (const Vec3& l : half_widths(scene_))
      grid_.particle_half_width.push_back(l.cwiseProduct(scene_.grid.spacing()));
  restart_ledger();
}

void Simulation::resize_particles(std::size_t n) {
  Particles& P = particles_;
  // Which optional arrays the scene uses (a rank may have held no particle when they were set).
  const bool q = stress_settings_.viscosity != nullptr;
  const bool fault = stress_settings_.fail_particle;
  const bool removed = scene_.grid.outflow == Outflow::remove;
  const bool id = comm_ != nullptr;
  P.for_each_array([&](auto& a) { a.resize(n); });
  if (!q) P.q.clear();
  if (!fault) P.fault.clear();
  if (!removed) P.removed.clear();
  if (!id) P.id.clear();
}

void Simulation::restart_ledger() {
  double ke = 0.0;
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    ke += 0.5 * particles_.mass[i] * particles_.v[i].squaredNorm();
    p += particles_.mass[i] * particles_.v[i];
  }
  max_signal_speed_ = max_signal_speed(particles_);
  if (comm_) {
    const std::vector<double> sum = comm_->sum({ke, p(0), p(1), p(2)});
    ke = sum[0];
    p = Vec3(sum[1], sum[2], sum[3]);
    max_signal_speed_ = comm_->max(max_signal_speed_);
  }
  ledger_.start(0.0, ke, p);
}

double Simulation::next_dt() const {
  double dt = stable_time_step(grid_.spacing(), max_signal_speed_, scene_.time.multiplier);
  if (steps_ == 0) dt = std::min(dt, scene_.time.initial_dt);
  dt = std::min(dt, scene_.time.max_dt);
  // No signal at all (every particle left the grid, grid.outflow = remove): nothing limits the
  // step, and nothing is left to integrate.
  if (std::isinf(dt) && max_signal_speed_ == 0.0) dt = scene_.time.max_time - time_;
  return dt;
}

const StepTotals& Simulation::step() {
  apply_injections();
  if (comm_) {  // a failure on one rank stops all of them
    std::optional<std::string> bad;
    try {
      check_particles();
    } catch (const SolverFailure& e) {
      bad = e.what();
    }
    agree_on_failure(bad);
  } else {
    check_particles();
  }
  double dt = next_dt();
  if (!(dt >= scene_.time.min_dt) || !std::isfinite(dt) || !(dt > 0.0)) {
    // The step collapses when one particle's signal speed c + |v| runs away: name it.
    std::size_t fastest = 0;
    double signal = -1.0;
    for (std::size_t p = 0; p < particles_.size(); ++p) {
      const double c = particles_.wave_speed[p] + particles_.v[p].norm();
      if (c > signal || std::isnan(c)) {
        signal = c;
        fastest = p;
        if (std::isnan(c)) break;
      }
    }
    std::ostringstream m;
    m.precision(6);
    m << "stable time step " << dt << " s below time.min_dt = " << scene_.time.min_dt
      << " s; this particle has the fastest signal, c + |v| = " << signal << " m/s";
    agree_on_failure(
        describe(Failure{fastest, "time step", m.str(), std::nullopt}, steps_ + 1, time_));
  }
  dt = std::min(dt, scene_.time.max_time - time_);  // land on max_time
  std::optional<Failure> failure;
  last_ = std::visit(
      [&](const auto& shape) {
        using Shape = std::decay_t<decltype(shape)>;
        auto& S = std::get<Stencils<Shape>>(stencils_);
        const ContactSpec* contact = grid_.fields() > 1 ? &scene_.physics.contact : nullptr;
        return advance(particles_, grid_, shape, S, scatter_order_, stress_settings_, scene_.solver,
                       contact, heat_capacity_, dt, halo_ ? &*halo_ : nullptr, failure);
      },
      shape_);
  stress_settings_.inject_nan_stress = -1;
  phase_totals_ += last_.seconds;
  if (comm_) {
    agree_on_failure(failure ? std::optional(describe(*failure, steps_ + 1, time_ + dt))
                             : std::nullopt);
    reduce(last_);
  } else if (failure) {
    throw SolverFailure(describe(*failure, steps_ + 1, time_ + dt));
  }
  time_ += dt;
  ++steps_;
  max_signal_speed_ = last_.stress.max_signal_speed;
  ledger_.record_step(time_, last_.particles.kinetic_energy, last_.particles.momentum,
                      last_.stress.strain_energy_increment, last_.grid.boundary_impulse,
                      last_.grid.external_impulse, last_.grid.external_work);
  if (sinks_.viscous >= 0) ledger_.add_sink(sinks_.viscous, last_.stress.viscous_work);
  if (sinks_.friction >= 0) {
    ledger_.add_sink(sinks_.friction,
                     last_.grid.contact.friction_heat + last_.grid.wall_friction_heat);
  }
  if (sinks_.eroded >= 0) ledger_.add_sink(sinks_.eroded, last_.stress.eroded_energy);
  if (last_.particles.removed > 0) {
    ledger_.add_outflow(last_.particles.outflow_mass, last_.particles.outflow_momentum,
                        last_.particles.outflow_kinetic_energy);
    removed_ += last_.particles.removed;
  }
  failed_ += last_.stress.failed;
  converted_ += last_.stress.converted;
  const auto faulted = static_cast<std::int64_t>(last_.stress.faulted.size());
  faulted_ += static_cast<long>(comm_ ? comm_->sum(faulted) : faulted);
  // The step is complete (time, ledger and particles at t^{n+1}): the failure names this step.
  const std::optional<Failure> grown = energy_growth(ledger_, particles_, scene_.time);
  if (comm_) {
    agree_on_failure(grown ? std::optional(describe(*grown, steps_, time_)) : std::nullopt);
    // Particles that left this rank's box go to their new owner.
    migrated_ = migrate(particles_, boxes_, scene_.grid, *comm_).sent;
    rebalance_if_needed();
  } else if (grown) {
    throw SolverFailure(describe(*grown, steps_, time_));
  }
  return last_;
}

std::optional<NodeBox> Simulation::stored_box() const {
  if (!comm_) return std::nullopt;
  return stored_nodes(boxes_, scene_.grid.cells, comm_->rank());
}

void Simulation::rebuild_grid() {
  Grid next(scene_.grid, grid_.threads(), grid_.fields(), !grid_.heat.empty(), stored_box());
  next.field_body = grid_.field_body;
  next.field_density = grid_.field_density;
  next.light_mass = grid_.light_mass;
  next.particle_half_width = grid_.particle_half_width;
  grid_ = std::move(next);
  own_box();
}

void Simulation::own_box() {
  const int r = comm_ ? comm_->rank() : 0;
  const std::array<int, 3> coordinates = boxes_.coordinates(r);
  NodeBox owned;
  for (std::size_t d = 0; d < 3; ++d) {
    const SlabDecomposition& axis = boxes_.axis(int(d));
    const int c = coordinates[d];
    // The end boxes also own the ghost layer and the last node layer outside their cells.
    owned.first[d] = c == 0 ? -1 : axis.first_cell(c);
    owned.last[d] = c + 1 == axis.ranks() ? scene_.grid.cells[d] + 1 : axis.first_cell(c + 1) - 1;
  }
  grid_.set_owned(owned);
}

void Simulation::rebalance_if_needed() {
  // Decided from particle counts only, the same on every rank and in every run.
  const std::vector<double> held = comm_->gather_all(double(particles_.size()));
  double total = 0.0, largest = 0.0;
  for (const double n : held) {
    total += n;
    largest = std::max(largest, n);
  }
  if (!(largest > scene_.solver.rebalance_above * total / comm_->size())) return;
  BoxDecomposition next = BoxDecomposition::balanced(axis_counts(particles_, scene_.grid, comm_),
                                                     boxes_.ranks_per_axis());
  if (scene_.solver.split == SplitRule::least_loaded && scene_.solver.ranks_per_axis[0] == 0) {
    std::vector<CellCount> counted;  // this rank's particles, summed over the ranks per table
    for (const Vec3& x : particles_.x) count_cell(counted, scene_.grid.cell_of(x));
    next = refine_boundaries(
        next, counted, [&](const std::vector<double>& t) { return comm_->sum_counts(t); }, nullptr);
  }
  if (next == boxes_) return;  // already as balanced as boxes can be
  boxes_ = std::move(next);
  rebuild_grid();
  migrated_ += migrate(particles_, boxes_, scene_.grid, *comm_).sent;
  ++rebalances_;
}

void Simulation::agree_on_failure(const std::optional<std::string>& message) const {
  if (!comm_) {
    if (message) throw SolverFailure(*message);
    return;
  }
  const std::vector<double> failed = comm_->gather_all(message ? 1.0 : 0.0);
  for (int r = 0; r < comm_->size(); ++r) {
    if (failed[std::size_t(r)] == 0.0) continue;
    throw SolverFailure(comm_->broadcast(message.value_or(""), r));
  }
}

void Simulation::reduce(StepTotals& t) const {
  // One reduction of every summed total and one of every largest, in table order
  // (mpm/ledger/totals.hpp).
  for (const Merge merge : {Merge::sum, Merge::max}) {
    std::vector<double> v;
    append_fields(t.particles, merge, v);
    append_fields(t.stress, merge, v);
    append_fields(t.grid, merge, v);
    v = merge == Merge::sum ? comm_->sum(v) : comm_->max(v);
    std::size_t k = 0;
    extract_fields(t.particles, merge, v, k);
    extract_fields(t.stress, merge, v, k);
    extract_fields(t.grid, merge, v, k);
  }
}

std::string Simulation::describe(const Failure& f, long step, double time) const {
  static const Eigen::IOFormat kRow(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  const Particles& P = particles_;
  std::ostringstream m;
  m.precision(9);
  m << "step " << step << ", time " << time << " s: ";
  if (comm_) m << "rank " << comm_->rank() << ", ";
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
  return m.str();
}

void Simulation::inject(const FaultInjection& fault) {
  if (fault.kind == FaultInjection::Kind::sigterm || fault.kind == FaultInjection::Kind::sigint)
    throw std::invalid_argument("a signal is raised by run(), not the Simulation");
  // The particle is its seed index, on any number of ranks (collective on several).
  const auto total = static_cast<std::size_t>(comm_ ? comm_->sum(std::int64_t(particles_.size()))
                                                    : std::int64_t(particles_.size()));
  if (fault.particle >= total) {
    throw std::out_of_range("particle " + std::to_string(fault.particle) + " out of range (" +
                            std::to_string(total) + " particles)");
  }
  injections_.push_back(fault);
}

void Simulation::apply_injections() {
  for (const FaultInjection& f : injections_) {
    if (f.step != steps_ + 1) continue;
    // Its index here: the seed index itself on one rank; on several, the rank holding it.
    std::size_t p = f.particle;
    if (!particles_.id.empty()) {
      const auto it = std::find(particles_.id.begin(), particles_.id.end(), f.particle);
      if (it == particles_.id.end()) continue;
      p = static_cast<std::size_t>(it - particles_.id.begin());
    }
    switch (f.kind) {
      case FaultInjection::Kind::nan:
        stress_settings_.inject_nan_stress = static_cast<std::ptrdiff_t>(p);
        break;
      case FaultInjection::Kind::nan_velocity:
        particles_.v[p].setConstant(std::numeric_limits<double>::quiet_NaN());
        break;
      case FaultInjection::Kind::outside:
        particles_.x[p](0) = scene_.grid.upper(0) + grid_.spacing()(0);
        break;
      case FaultInjection::Kind::jacobian:
        particles_.state[p].F.col(0) *= -1.0;
        break;
      case FaultInjection::Kind::sigterm:
      case FaultInjection::Kind::sigint:
        break;
    }
  }
}

void Simulation::check_particles() const {
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
  if (!any) return;
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    if (!bad(p)) continue;
    const bool inside =
        (P.x[p].array() >= lower.array()).all() && (P.x[p].array() <= upper.array()).all();
    const Failure f = inside ? Failure{std::size_t(p), "velocity",
                                       "not finite at the start of the step", std::nullopt}
                             : Failure{std::size_t(p), "position",
                                       "outside the grid at the start of the step", std::nullopt};
    throw SolverFailure(describe(f, steps_ + 1, time_));
  }
}

std::optional<FaultInjection> parse_fault_injection(const std::string& text) {
  using Kind = FaultInjection::Kind;
  static const std::pair<const char*, Kind> kinds[] = {
      {"nan", Kind::nan},         {"nan_velocity", Kind::nan_velocity},
      {"outside", Kind::outside}, {"jacobian", Kind::jacobian},
      {"sigterm", Kind::sigterm}, {"sigint", Kind::sigint}};
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t colon = text.find(':', start);
    parts.push_back(text.substr(start, colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  FaultInjection f;
  bool known = false;
  for (const auto& [name, kind] : kinds) {
    if (parts[0] == name) {
      f.kind = kind;
      known = true;
    }
  }
  const bool signal = f.kind == Kind::sigterm || f.kind == Kind::sigint;
  if (!known || parts.size() != (signal ? 2u : 3u)) return std::nullopt;
  const auto whole = [](const std::string& s, long long& v) {
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 15)
      return false;
    v = std::stoll(s);
    return true;
  };
  long long step = 0, particle = 0;
  if (!whole(parts[1], step) || step < 1) return std::nullopt;
  if (!signal && !whole(parts[2], particle)) return std::nullopt;
  f.step = static_cast<long>(step);
  f.particle = static_cast<std::size_t>(particle);
  return f;
}

}  // namespace impact::mpm
