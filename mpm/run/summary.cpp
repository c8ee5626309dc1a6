#include "mpm/run/summary.hpp"
#include "mpm/scene/grid_geometry.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "mpm/ledger/extensive_units.hpp"
#include "mpm/parallel/decomposition_plan.hpp"
#include "mpm/run/memory.hpp"
#include "mpm/run/scene_fingerprint.hpp"
#include "mpm/run/seeding_check.hpp"
#include "mpm/run/step_estimate.hpp"
#include "mpm/scene/initial_fields.hpp"
#include "mpm/scene/seed_points.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

namespace {

Json vec_json(const Vec3& v) {
  return Json::array({v(0), v(1), v(2)});
}

Json row_json(const Ledger& ledger) {
  const LedgerRow r = ledger.row();
  const auto cols = ledger.columns();
  const auto vals = ledger.values(r);
  Json j;
  for (std::size_t i = 0; i < cols.size(); ++i) j[cols[i]] = vals[i];
  return j;
}

// Element-wise sums over the ranks (comm null: one rank, the values themselves).
std::vector<double> over_ranks(const std::vector<double>& values, const Communicator& comm) {
  return comm.sum(values);
}

// Failed particles per cause (melting, tepla, drucker, becker) and the particles where a stability
// check fired without failing them (stability_check.outcome = "report").
Json failure_causes(const Particles& P, const Communicator& comm) {
  // Counts by cause (5), in tension, Drucker and Becker reported: exact as doubles.
  std::vector<double> n(8, 0.0);
  for (const PointState& s : P.state) {
    if (s.failed) n[static_cast<std::size_t>(s.failure_cause)] += 1.0;
    n[5] += s.failed && s.failed_in_tension;
    n[6] += (s.instability & kDruckerFired) != 0;
    n[7] += (s.instability & kBeckerFired) != 0;
  }
  n = over_ranks(n, comm);
  const auto count = [&](std::size_t i) { return static_cast<std::int64_t>(n[i]); };
  Json j;
  for (const FailureCause c :
       {FailureCause::melting, FailureCause::tepla, FailureCause::drucker, FailureCause::becker})
    j[std::string(to_string(c))] = count(static_cast<std::size_t>(c));
  j["in_tension"] = count(5);  // of all causes: failed with a tensile mean stress
  j["drucker_reported"] = count(6);
  j["becker_reported"] = count(7);
  return j;
}

// The grid's cells per axis and their smallest and largest edge; on a graded grid (grid.refine)
// also the base cells grid.cells gave.
Json grid_report(const GridSpec& g) {
  const auto ints = [](const std::array<int, 3>& a) { return Json::array({a[0], a[1], a[2]}); };
  const auto vec = [](const Vec3& v) { return Json::array({v(0), v(1), v(2)}); };
  Json j = {{"cells", ints(g.cells)},
            {"smallest_cell [m]", vec(g.smallest_cell())},
            {"largest_cell [m]", vec(g.largest_cell())},
            {"graded", g.graded()}};
  if (g.graded()) j["base_cells"] = ints(g.base_cells);
  return j;
}

// Per object counts, mass and volumes, and the memory estimate with the seeded count: what
// `mpm check` and summary.json share. P: the particles this rank holds.
Json particle_report(const Scene& scene, const Particles& P, int threads,
                     const Communicator& comm) {
  // Per object: count, mass, particle volume.
  std::vector<double> sums(3 * scene.objects.size(), 0.0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    double* s = &sums[3 * P.object[p]];
    s[0] += 1.0;
    s[1] += P.mass[p];
    s[2] += P.volume0[p];
  }
  sums = over_ranks(sums, comm);
  const ExtensiveUnits u = ExtensiveUnits::of(scene.grid.per_metre_of_thickness());
  const auto in = [](const char* name, const std::string& unit) {
    return std::string(name) + " [" + unit + "]";
  };
  Json objects = Json::object();
  double total_mass = 0.0;
  std::size_t total = 0;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const auto n = static_cast<std::size_t>(sums[3 * o]);
    const double mass = sums[3 * o + 1], vol = sums[3 * o + 2];
    // The revolved body's volume (axisymmetric), or per metre of thickness (plane strain).
    const double exact = visit_geometry(scene.grid.geometry, [&](auto geometry) {
      return decltype(geometry)::modelled_volume(scene.objects[o].geometry);
    });
    const double rho = scene.materials[scene.objects[o].material].material.model.params().density;
    objects[scene.objects[o].name] = {
        {"particles", n},
        {in("mass", u.mass), mass},
        {in("particle_volume", u.volume), vol},
        {in("geometric_volume", u.volume), exact},
        {in("geometric_mass", u.mass), rho * exact},
        {"volume_ratio", exact > 0 ? vol / exact : 0.0},
        {in("kinetic_energy", u.energy),
         scene.objects[o].velocity_field.has_text()  // a field: summed over its seed points
             ? initial_fields(scene, o).kinetic_energy
             : 0.5 * mass * scene.objects[o].velocity.squaredNorm()}};
    // A rigid object's motion is outside the books (docs/scenes.md#rigid-objects): its kinetic
    // energy above is not in E0.
    // Its Coulomb coefficient as the run takes it: its own mu, or physics.contact.mu.
    if (scene.objects[o].rigid) {
      objects[scene.objects[o].name]["rigid"] = true;
      objects[scene.objects[o].name]["mu"] = scene.friction_of(scene.objects[o]);
    }
    total_mass += mass;
    total += n;
  }
  const MemoryEstimate memory = estimate_memory(scene, total);
  Json report = {{"objects", objects},
                 {"grid", grid_report(scene.grid)},
                 {"particles", total},
                 {in("mass", u.mass), total_mass},
                 {"memory [MB]", memory.total() / 1e6},
                 {"memory_estimate", memory.json()},
                 {"memory_per_particle [B]", Particles::bytes_per_particle()},
                 {"velocity_fields", scene.field_count()},
                 {"threads", threads},
                 // How idle OpenMP threads wait (support/omp_wait_policy.hpp): "passive" unless
                 // the user set OMP_WAIT_POLICY.
                 {"omp_wait_policy", std::getenv("OMP_WAIT_POLICY") ? std::getenv("OMP_WAIT_POLICY")
                                                                    : "libgomp default"}};
  if (const auto available = available_memory()) report["available_memory [MB]"] = *available / 1e6;
  if (!scene.output.gauges.empty()) {
    Json gauges = Json::object();
    // Counted here, not when the scene is read: the memory estimate may refuse a huge scene.
    for (const GaugeSpec& gs : scene.output.gauges) {
      gauges[gs.name] = {
          {"particles", count_seed_points(scene, std::size_t(gs.object), gs.lower, gs.upper)}};
    }
    report["gauges"] = gauges;
  }
  return report;
}

}  // namespace

Json check_report(const Scene& scene, int threads, int ranks, std::vector<std::string>* seeding) {
  const Particles P = seed_particles(scene);
  if (seeding) *seeding = seeding_warnings(scene, P, Communicator());
  Json report = particle_report(scene, P, threads, Communicator());  // every particle seeded here
  report.update(estimate_steps(scene).json(scene));
  report["scene_fingerprint"] = scene_fingerprint(scene.resolved);
  // The keys without a unit in their name: counts and ratios.
  report["units"] = {{"particles", "-"},
                     {"cells", "-"},
                     {"base_cells", "-"},
                     {"volume_ratio", "-"},
                     {"mu", "-"},
                     {"estimated_steps", "-"},
                     {"max_estimated_steps", "-"},
                     {"estimated_particle_steps", "-"},
                     {"max_estimated_particle_steps", "-"},
                     {"velocity_fields", "-"},
                     {"threads", "-"}};
  if (ranks > 1) report["decomposition"] = plan_decomposition(scene, P, ranks);
  return report;
}

Json run_summary(const Simulation& sim, const Particles& P, const std::string& status,
                 const std::string& message, double wall, const Observables& observables,
                 const GaugeExtrema& gauges, const ParticlePaths* paths) {
  const Scene& scene = sim.scene();
  const Communicator& comm = sim.communicator();
  Json summary = particle_report(scene, P, sim.threads(), comm);
  const auto particles = summary["particles"].get<std::size_t>();
  summary["ranks"] = sim.ranks();
  summary["status"] = status;
  if (!message.empty()) summary["message"] = message;
  summary["steps"] = sim.steps();
  summary["time [s]"] = sim.time();
  summary["wall_time [s]"] = wall;
  summary["particle_steps_per_second"] =
      wall > 0 ? double(particles) * double(sim.steps()) / wall : 0.0;
  if (const auto peak = peak_resident_memory()) summary["peak_resident_memory [MB]"] = *peak / 1e6;
  const ExtensiveUnits& u = sim.ledger().units();
  summary["initial_energy [" + u.energy + "]"] = sim.ledger().initial_energy();
  summary["velocity_fields"] = sim.grid().fields();
  summary["failed_particles"] = sim.failed_particles();
  summary["failed_by_cause"] = failure_causes(P, comm);
  for (std::size_t i = 0; paths && i < scene.output.particle_paths.size(); ++i)
    summary["particle_paths"][scene.output.particle_paths[i].name] = paths->particle(i);
  summary["converted_particles"] = sim.converted_particles();
  if (scene.grid.graded()) summary["narrowed_particle_steps"] = sim.narrowed_particle_steps();
  summary["faulted_particles"] = sim.faulted_particles();
  summary["initial_momentum [" + u.momentum + "]"] = vec_json(sim.ledger().initial_momentum());
  summary["final"] = row_json(sim.ledger());
  summary["observables"] = observables.summary(P);
  for (std::size_t g = 0; g < scene.output.gauges.size() && g < gauges.size(); ++g)
    summary["gauges"][scene.output.gauges[g].name].update(gauges.json(g));
  summary["units"] = {{"time", "s"},
                      {"energy", u.energy},
                      {"momentum", u.momentum},
                      {"boundary_impulse", u.impulse},
                      {"mass", u.mass},
                      {"volume", u.volume},
                      {"energy_error", "-"},
                      // counts and ratios, and the one rate without a unit in its name
                      {"particles", "-"},
                      {"cells", "-"},
                      {"base_cells", "-"},
                      {"steps", "-"},
                      {"volume_ratio", "-"},
                      {"mu", "-"},
                      {"failed_particles", "-"},
                      {"failed_by_cause", "-"},
                      {"converted_particles", "-"},
                      {"narrowed_particle_steps", "-"},
                      {"faulted_particles", "-"},
                      {"velocity_fields", "-"},
                      {"threads", "-"},
                      {"ranks", "-"},
                      {"particle_steps_per_second", "1/s"}};
  return summary;
}

}  // namespace impact::mpm
