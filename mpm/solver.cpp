#include "mpm/solver.hpp"

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "mpm/output/atomic_file.hpp"
#include "mpm/output/observables.hpp"
#include "mpm/output/output.hpp"
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
                   const StressUpdateSettings& settings, const SolverSpec& s,
                   const ContactSpec* contact, const std::vector<double>& specific_heat, double dt,
                   std::optional<Failure>& failure) {
  StepTotals t;
  PhaseClock clock(t.seconds);
  const bool usl = s.scheme == Scheme::usl;
  compute_stencils<Shape>(P, shape, S, G.threads());  // S_Ip, grad S_Ip at x^n, once per step
  particles_to_grid<Shape>(P, G, S);                  // m_I, p_I, f_I per field  (eqs. 20-22)
  clock.lap(&PhaseTimes::particles_to_grid);
  t.grid = grid_update(G, dt, s.gravity, usl, contact);  // v*_I, contact, faces (eq. 24)
  clock.lap(&PhaseTimes::grid_update);
  // FLIP velocity, x from v*_I; USL: L from v^L_I (= v*_I but at light nodes)   (eqs. 23, 25-26)
  t.particles = grid_to_particles<Shape>(P, G, S, dt, /*usl_gradient=*/usl, specific_heat, failure);
  clock.lap(&PhaseTimes::grid_to_particles);
  if (failure) return t;
  if (!usl) {
    remap_and_gradient<Shape>(P, G, S, contact);  // MUSL: L from the re-mapped v^{n+1}_I
    clock.lap(&PhaseTimes::remap);
  }
  t.stress = update_stress(P, settings, dt, failure);  // sigma, F, V, q; eq. 14
  clock.lap(&PhaseTimes::stress);
  return t;
}

std::variant<LinearShape, GimpShape> make_shape(const Scene& scene) {
  const GridSpec& g = scene.grid;
  const Vec3 inv_dx = g.spacing().cwiseInverse();
  if (scene.solver.interpolation == Interpolation::linear) {
    return LinearShape{g.lower, inv_dx, g.cells};
  }
  return GimpShape{g.lower, inv_dx, g.cells, half_widths(scene)};
}

std::variant<Stencils<LinearShape>, Stencils<GimpShape>> make_stencils(
    const std::variant<LinearShape, GimpShape>& shape) {
  if (std::holds_alternative<LinearShape>(shape)) return Stencils<LinearShape>{};
  return Stencils<GimpShape>{};
}

int thread_count(int requested) {
  if (requested > 0) omp_set_num_threads(std::min(requested, kMaxThreads));
  return std::min(omp_get_max_threads(), kMaxThreads);
}

std::string describe(const Failure& f, const Particles& P, const Scene& scene, long step,
                     double time) {
  std::ostringstream m;
  m.precision(9);
  m << "step " << step << ", time " << time << " s: particle " << f.particle;
  if (f.particle < P.size()) {
    m << " (material " << scene.materials[P.material[f.particle]].name << ", object "
      << scene.objects[P.object[f.particle]].name << ", x = [" << P.x[f.particle].transpose()
      << "] m)";
  }
  m << ": " << f.field << ": " << f.message;
  return m.str();
}

// The energy-growth check (docs/mpm.md#failure-handling). An unstable explicit step shows itself
// first as kinetic + strain energy growing far beyond what entered, many steps before a NaN or a
// particle leaving the grid. Reference: the energy that entered, E_in = E0 + boundary_work +
// external_work (at least E0); growth = (kinetic + strain + booked sinks - E_in) / E_ref, equal
// to energy_error whenever no work enters through faces or gravity. Nothing is checked while no
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
    << " J that entered (E0 " << ledger.initial_energy() << " J, boundary work " << r.boundary_work
    << " J, external work " << r.external_work << " J): growth " << std::showpos
    << excess / reference << std::noshowpos << " (energy_error " << std::showpos << r.energy_error
    << std::noshowpos << ") above time.max_energy_growth = " << t.max_energy_growth
    << "; this particle is the fastest, |v| = " << std::sqrt(speed2)
    << " m/s: the explicit step is unstable (time.multiplier " << t.multiplier << "; lower it)";
  return Failure{fastest, "energy", m.str()};
}

}  // namespace

Simulation::Simulation(const Scene& scene, int threads)
    : scene_(scene),
      particles_(seed_particles(scene)),
      grid_(scene.grid, thread_count(threads), scene.field_count(),
            scene.field_count() > 1 && scene.physics.contact.type == ContactType::friction),
      shape_(make_shape(scene)),
      stencils_(make_stencils(shape_)),
      ledger_(!scene.solver.gravity.isZero(0.0)) {
  const PhysicsSpec& ph = scene_.physics;
  StressUpdateSettings& st = stress_settings_;
  bool erosion = false;
  for (std::size_t m = 0; m < scene_.materials.size(); ++m) {
    const ElasticPlastic& model = scene_.materials[m].material.model;
    st.models.push_back(&model);
    specific_heat_.push_back(model.params().specific_heat);
    erosion = erosion || model.params().erosion != Erosion::none;
    if (ph.create_new_particles && scene_.companion_field(int(m)) != scene_.parent_field(int(m))) {
      st.companion_field.push_back(static_cast<std::uint16_t>(scene_.companion_field(int(m))));
    }
  }
  st.f_integration = scene_.solver.f_integration;
  st.mean_spacing = scene_.grid.spacing().sum() / 3.0;
  if (ph.artificial_viscosity.enabled) {
    st.viscosity = &scene_.physics.artificial_viscosity;
    particles_.q.assign(particles_.size(), 0.0);
  }
  // The ledger's columns follow the physics the scene switched on.
  if (st.viscosity) sinks_.viscous = ledger_.add_sink_column("viscous_work");
  if (grid_.fields() > 1) {
    sinks_.contact = ledger_.add_sink_column("contact_dissipation");
    if (ph.contact.type == ContactType::friction)
      sinks_.friction = ledger_.add_sink_column("friction_heat", /*in_balance=*/false);
  }
  if (erosion) sinks_.eroded = ledger_.add_sink_column("eroded_energy", /*in_balance=*/false);
  if (!particles_.mass.empty()) {
    grid_.light_mass =
        kLightNodeMassFraction * *std::min_element(particles_.mass.begin(), particles_.mass.end());
  }
  restart_ledger();
}

void Simulation::restart_ledger() {
  double ke = 0.0;
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    ke += 0.5 * particles_.mass[i] * particles_.v[i].squaredNorm();
    p += particles_.mass[i] * particles_.v[i];
  }
  ledger_.start(0.0, ke, p);
  max_signal_speed_ = max_signal_speed(particles_);
}

double Simulation::next_dt() const {
  double dt = stable_time_step(grid_.spacing(), max_signal_speed_, scene_.time.multiplier);
  if (steps_ == 0) dt = std::min(dt, scene_.time.initial_dt);
  return std::min(dt, scene_.time.max_dt);
}

const StepTotals& Simulation::step() {
  double dt = next_dt();
  if (!(dt >= scene_.time.min_dt) || !std::isfinite(dt) || !(dt > 0.0)) {
    std::ostringstream m;
    m << "step " << steps_ << ", time " << time_ << " s: time step " << dt
      << " s below min_dt = " << scene_.time.min_dt << " s (fastest signal " << max_signal_speed_
      << " m/s)";
    throw SolverFailure(m.str());
  }
  dt = std::min(dt, scene_.time.max_time - time_);  // land on max_time
  std::optional<Failure> failure;
  last_ = std::visit(
      [&](const auto& shape) {
        using Shape = std::decay_t<decltype(shape)>;
        auto& S = std::get<Stencils<Shape>>(stencils_);
        const ContactSpec* contact = grid_.fields() > 1 ? &scene_.physics.contact : nullptr;
        return advance(particles_, grid_, shape, S, stress_settings_, scene_.solver, contact,
                       specific_heat_, dt, failure);
      },
      shape_);
  if (failure) throw SolverFailure(describe(*failure, particles_, scene_, steps_ + 1, time_ + dt));
  time_ += dt;
  ++steps_;
  max_signal_speed_ = last_.stress.max_signal_speed;
  ledger_.record_step(time_, last_.particles.kinetic_energy, last_.particles.momentum,
                      last_.stress.strain_energy_increment, last_.grid.boundary.impulse,
                      last_.grid.boundary.work, last_.grid.boundary.dissipation,
                      last_.grid.external_impulse, last_.grid.external_work);
  if (sinks_.viscous >= 0) ledger_.add_sink(sinks_.viscous, last_.stress.viscous_work);
  if (sinks_.contact >= 0) ledger_.add_sink(sinks_.contact, last_.grid.contact.dissipation);
  if (sinks_.friction >= 0) ledger_.add_sink(sinks_.friction, last_.grid.contact.friction_heat);
  if (sinks_.eroded >= 0) ledger_.add_sink(sinks_.eroded, last_.stress.eroded_energy);
  failed_ += last_.stress.failed;
  converted_ += last_.stress.converted;
  // The step is complete (time, ledger and particles at t^{n+1}): the failure names this step.
  if (auto grown = energy_growth(ledger_, particles_, scene_.time))
    throw SolverFailure(describe(*grown, particles_, scene_, steps_, time_));
  return last_;
}

namespace {

Json vec_json(const Vec3& v) {
  return Json::array({v(0), v(1), v(2)});
}

Json row_json(const Ledger& ledger) {
  const LedgerRow r = ledger.row();
  const auto cols = ledger.columns();
  const auto vals = Ledger::values(r, ledger.with_external());
  Json j;
  for (std::size_t i = 0; i < cols.size(); ++i) j[cols[i]] = vals[i];
  return j;
}

}  // namespace

Json check_report(const Scene& scene, int threads) {
  const Particles P = seed_particles(scene);
  Json objects = Json::object();
  double total_mass = 0.0;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    std::size_t n = 0;
    double mass = 0.0, vol = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      if (P.object[p] != o) continue;
      ++n;
      mass += P.mass[p];
      vol += P.volume0[p];
    }
    const double exact = volume(scene.objects[o].geometry);
    const double rho = scene.materials[scene.objects[o].material].material.model.params().density;
    objects[scene.objects[o].name] = {
        {"particles", n},
        {"mass [kg]", mass},
        {"particle_volume [m^3]", vol},
        {"geometric_volume [m^3]", exact},
        {"geometric_mass [kg]", rho * exact},
        {"volume_ratio", exact > 0 ? vol / exact : 0.0},
        {"kinetic_energy [J]", 0.5 * mass * scene.objects[o].velocity.squaredNorm()}};
    total_mass += mass;
  }
  const double dt =
      std::min(stable_time_step(scene.grid.spacing(), max_signal_speed(P), scene.time.multiplier),
               scene.time.max_dt);
  const Grid g(scene.grid, std::max(threads, 1), scene.field_count(),
               scene.field_count() > 1 && scene.physics.contact.type == ContactType::friction);
  const double particle_bytes = double(P.size()) * Particles::bytes_per_particle();
  Json report = {{"objects", objects},
                 {"particles", P.size()},
                 {"mass [kg]", total_mass},
                 {"stable_dt [s]", dt},
                 {"estimated_steps", std::ceil(scene.time.max_time / dt)},
                 {"memory [MB]", (particle_bytes + double(g.bytes())) / 1e6},
                 {"memory_per_particle [B]", Particles::bytes_per_particle()},
                 {"velocity_fields", g.fields()},
                 {"threads", threads}};
  if (!scene.output.gauges.empty()) {
    Json gauges = Json::object();
    for (const GaugeSpec& gs : scene.output.gauges) gauges[gs.name] = {{"particles", gs.particles}};
    report["gauges"] = gauges;
  }
  return report;
}

int run(const Scene& scene, const RunOptions& options) {
  namespace fs = std::filesystem;
  const std::string dir = options.out_dir.empty() ? scene.output.directory : options.out_dir;
  fs::create_directories(dir);
  write_file_atomically(fs::path(dir) / "scene.json",
                        [&](std::ostream& o) { o << scene.resolved.dump(2) << '\n'; });
  // Wall time from the start of the step loop (as summary.json; restarted after the first outputs).
  auto t0 = std::chrono::steady_clock::now();
  const auto wall_time = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  Simulation sim(scene, options.threads);
  // status.json: where the run is (rewritten at every history row) and how it ended.
  const auto write_status = [&](const std::string& status, const std::string& message) {
    Json j = {{"status", status},
              {"step", sim.steps()},
              {"time [s]", sim.time()},
              {"energy_error [-]", sim.ledger().row().energy_error},
              {"wall_time [s]", wall_time()}};
    if (status != "running") j["message"] = message;
    write_file_atomically(fs::path(dir) / "status.json",
                          [&](std::ostream& o) { o << j.dump(2) << '\n'; });
  };
  // Gauge and crater particle sets from the particles as seeded (nothing when the scene has none).
  const Gauges gauges(scene, sim.particles());
  Observables observables(scene, sim.particles());
  HistoryCsv history((fs::path(dir) / "history.csv").string(), sim.ledger(), gauges.columns());
  const auto write_history = [&] {
    observables.sample(sim.particles(), sim.time());  // max pressure: sampled at history rows
    history.write(sim.ledger().row(), gauges.read(sim.particles()));
    write_status("running", "");
  };
  std::optional<SnapshotWriter> snapshots;
  if (scene.output.snapshots) snapshots.emplace(dir, scene.output.fields);
  const auto write_outputs = [&] {
    write_history();
    if (snapshots) snapshots->write(sim.particles(), sim.steps(), sim.time());
  };
  write_outputs();
  t0 = std::chrono::steady_clock::now();
  auto last_progress = t0;
  double next_output = scene.output.interval;
  std::string status = "completed", message;
  int code = 0;
  try {
    while (!sim.finished()) {
      sim.step();
      if (sim.time() >= next_output * (1.0 - 1e-12) || sim.finished()) {
        write_outputs();
        while (next_output <= sim.time() * (1.0 + 1e-12)) next_output += scene.output.interval;
      }
      const auto now = std::chrono::steady_clock::now();
      if (options.progress && now - last_progress > std::chrono::milliseconds(500)) {
        last_progress = now;
        const double wall = std::chrono::duration<double>(now - t0).count();
        const double eta = wall * (scene.time.max_time - sim.time()) / sim.time();
        std::fprintf(stderr, "\rstep %ld  t %.4e s  dt %.3e s  energy_error %+.3e  ETA %.0f s   ",
                     sim.steps(), sim.time(), sim.next_dt(), sim.ledger().row().energy_error, eta);
      }
    }
  } catch (const SolverFailure& e) {
    status = "failed";
    message = e.what();
    code = 3;
    std::cerr << (options.progress ? "\n" : "") << "mpm: run failed: " << message << '\n';
    if (snapshots) snapshots->write(sim.particles(), sim.steps() + 1, sim.time());
    write_history();
  } catch (const std::exception& e) {  // e.g. an output that cannot be written: say so, re-throw
    try {
      write_status("failed", e.what());
    } catch (const std::exception&) {  // keep the original error
    }
    throw;
  }
  if (options.progress) std::fprintf(stderr, "\n");
  const double wall = wall_time();
  Json summary = check_report(scene, sim.threads());
  summary.erase("estimated_steps");
  summary.erase("stable_dt [s]");
  summary["status"] = status;
  if (!message.empty()) summary["message"] = message;
  summary["steps"] = sim.steps();
  summary["time [s]"] = sim.time();
  summary["wall_time [s]"] = wall;
  summary["particle_steps_per_second"] =
      wall > 0 ? double(sim.particles().size()) * double(sim.steps()) / wall : 0.0;
  summary["initial_energy [J]"] = sim.ledger().initial_energy();
  summary["velocity_fields"] = sim.grid().fields();
  summary["failed_particles"] = sim.failed_particles();
  summary["converted_particles"] = sim.converted_particles();
  summary["initial_momentum [kg m/s]"] = vec_json(sim.ledger().initial_momentum());
  summary["final"] = row_json(sim.ledger());
  summary["observables"] = observables.summary(sim.particles());
  summary["units"] = {{"time", "s"},
                      {"energy", "J"},
                      {"momentum", "kg m/s"},
                      {"boundary_impulse", "N s"},
                      {"energy_error", "-"}};
  write_file_atomically(fs::path(dir) / "summary.json",
                        [&](std::ostream& o) { o << summary.dump(2) << '\n'; });
  write_status(status, message);  // last: a completed status.json means every file is in place
  return code;
}

}  // namespace impact::mpm
