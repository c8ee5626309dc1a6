// Checkpoint and restart (docs/mpm.md#checkpoint-and-restart) on
// tests/data/mpm_runs/contact_friction_av.json: two blocks in oblique contact with friction
// (two velocity fields, nodal stress, friction heat into the temperatures), artificial viscosity
// (q per particle) and physics.on_numerical_fault = fail_particle (one particle's stress is made
// NaN at step 5, so the fault flags are part of the state), 2 threads.
// (a) Simulation level: K = 40 steps uninterrupted against 20 steps, a checkpoint (in memory),
//     a new Simulation loaded from it and 20 more steps: every particle array and every member of
//     every PointState equal (==), the ledger row equal after every one of the 20 steps, and the
//     counters equal.
// (b) run() level: an uninterrupted run against one stopped by SIGTERM (injected after step 30:
//     the real handler) and restarted with restart(): exit 143 then 0, status.json "interrupted"
//     then "completed", and history.csv, particles.pvd and every particles/step_NNNNNN.vtu
//     (every field, raw Float64) byte-identical, summary.json equal but for the wall-clock
//     fields. And a run that wrote a checkpoint every 7 steps and then ran on to the end (as a
//     run killed after its last checkpoint): restarting it drops the history rows after the
//     checkpoint and ends byte-identical again.
// (a') The same with both blocks on the Mechanical Threshold Stress law, whose internal variable
//      (PointState::flow_internal) must come back from the checkpoint.
// (c) A restart is refused (InputError) for a checkpoint of another format version, a corrupt
//     one (a flipped byte: checksum or length field), a truncated one (named so, with both
//     lengths), a scene.json edited since, and a missing checkpoint.
// (e) A run stopped and restarted three times, from the repository root with relative material
//     paths and once from another directory, ends as the uninterrupted run.
// (d) (a) and (b) on axisymmetric grids (axisymmetric_scenes below).
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "../verification_helpers.hpp"
#include "helpers/mts_illustrative.hpp"
#include "mpm/input/scene_reader.hpp"
#include "mpm/run/checkpoint.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;

namespace {

const std::string kScene =
    std::string(IMPACT_SOURCE_DIR) + "/tests/data/mpm_runs/contact_friction_av.json";

Scene scene() {
  return load_scene(kScene);
}

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("mpm_restart_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  BOOST_REQUIRE_MESSAGE(in, "cannot open " << file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Json read_json(const fs::path& file) {
  return Json::parse(read_bytes(file));
}

bool same_state(const PointState& a, const PointState& b) {
  return a.stress == b.stress && a.F == b.F && a.R == b.R && a.plastic_strain == b.plastic_strain &&
         a.plastic_strain_rate == b.plastic_strain_rate && a.temperature == b.temperature &&
         a.internal_energy == b.internal_energy && a.damage == b.damage &&
         a.porosity == b.porosity && a.flow_internal == b.flow_internal && a.melted == b.melted &&
         a.failed == b.failed && a.failure_cause == b.failure_cause &&
         a.instability == b.instability && a.failed_in_tension == b.failed_in_tension;
}

// Particles that differ in any array.
std::size_t differing(const Particles& a, const Particles& b) {
  BOOST_REQUIRE(a.size() == b.size());
  BOOST_REQUIRE(a.q.size() == b.q.size());
  BOOST_REQUIRE(a.fault.size() == b.fault.size());
  BOOST_REQUIRE(a.X.size() == b.X.size());
  BOOST_REQUIRE(a.half_width.size() == b.half_width.size());
  BOOST_REQUIRE(a.friction_anchor.size() == b.friction_anchor.size());
  std::size_t n = 0;
  for (std::size_t p = 0; p < a.size(); ++p) {
    const bool same =
        a.x[p] == b.x[p] && a.v[p] == b.v[p] && a.mass[p] == b.mass[p] &&
        a.volume0[p] == b.volume0[p] && a.volume[p] == b.volume[p] && a.L[p] == b.L[p] &&
        same_state(a.state[p], b.state[p]) && a.wave_speed[p] == b.wave_speed[p] &&
        a.material[p] == b.material[p] && a.object[p] == b.object[p] && a.field[p] == b.field[p] &&
        (a.q.empty() || a.q[p] == b.q[p]) && (a.fault.empty() || a.fault[p] == b.fault[p]) &&
        (a.X.empty() || a.X[p] == b.X[p]) &&
        (a.half_width.empty() || a.half_width[p] == b.half_width[p]) &&
        (a.friction_anchor.empty() || a.friction_anchor[p] == b.friction_anchor[p]);
    n += same ? 0 : 1;
  }
  return n;
}

// Steps a new Simulation of `s` `half` times (`setup` first, e.g. a fault injection), saves a
// checkpoint in memory and loads it into `c`.
void load_after(Simulation& c, const Scene& s, int half,
                const std::function<void(Simulation&)>& setup = {}) {
  std::stringstream checkpoint;
  {
    Simulation b(s, 2);
    if (setup) setup(b);
    for (int i = 0; i < half; ++i) b.step();
    CheckpointWriter w(checkpoint);
    b.save(w);
    w.finish();
  }
  CheckpointReader r(checkpoint, "checkpoint in memory");
  c.load(r);
  r.finish();
}

std::vector<double> ledger_row(const Simulation& sim) {
  return sim.ledger().values(sim.ledger().row());
}

// `steps` steps of `s` uninterrupted against `half` steps, a checkpoint in memory and the rest:
// both runs' particles at the end, how many of the continued run's ledger rows differ, and its
// last row.
struct Continuation {
  Particles uninterrupted, continued;
  std::size_t rows_differ = 0;
  LedgerRow last;
};
Continuation continue_from_checkpoint(const Scene& s, int steps, int half) {
  Continuation out;
  std::vector<std::vector<double>> rows_a;
  {
    Simulation a(s, 2);
    for (int i = 0; i < steps; ++i) {
      a.step();
      rows_a.push_back(ledger_row(a));
    }
    out.uninterrupted = a.particles();
  }
  Simulation c(s, 2);
  load_after(c, s, half);
  for (int i = half; i < steps; ++i) {
    c.step();
    out.rows_differ += ledger_row(c) == rows_a[i] ? 0 : 1;
  }
  out.continued = c.particles();
  out.last = c.ledger().row();
  return out;
}

// Every file of the run directory that must be identical, relative names.
std::vector<std::string> output_files(const fs::path& dir) {
  std::vector<std::string> files = {"history.csv", "particles.pvd", "scene.json"};
  for (const auto& e : fs::directory_iterator(dir / "particles"))
    files.push_back("particles/" + e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

// `skip`: a file whose text may differ (the scene.json of a run started with relative material
// paths).
void require_same_outputs(const fs::path& a, const fs::path& b, const std::string& skip = "") {
  const auto files = output_files(a);
  BOOST_TEST(files == output_files(b));
  std::size_t same = 0;
  for (const std::string& f : files) {
    if (f == skip) continue;
    const bool equal = read_bytes(a / f) == read_bytes(b / f);
    BOOST_TEST(equal, f << " differs");
    same += equal;
  }
  BOOST_TEST_MESSAGE(same << " of " << files.size() << " output files byte-identical");
  Json sa = read_json(a / "summary.json"), sb = read_json(b / "summary.json");
  for (Json* s : {&sa, &sb}) {
    for (const char* k : {"wall_time [s]", "particle_steps_per_second", "peak_resident_memory [MB]",
                          "available_memory [MB]", "phase_seconds [s]"})
      s->erase(k);
  }
  BOOST_TEST(sa == sb);
}

// The uninterrupted run (2 threads), once for the test cases that compare with it; removed at
// exit.
const fs::path& uninterrupted() {
  struct Run {
    fs::path dir = scratch("uninterrupted");
    Run() {
      RunOptions options;
      options.threads = 2;
      options.out_dir = dir.string();
      BOOST_REQUIRE(run(scene(), options) == 0);
    }
    ~Run() { fs::remove_all(dir); }
  };
  static const Run once;
  return once.dir;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_restart)

BOOST_AUTO_TEST_CASE(simulation_continues_bit_for_bit_from_a_checkpoint) {
  constexpr int kSteps = 40, kHalf = 20;
  const Scene s = scene();
  const FaultInjection nan{FaultInjection::Kind::nan, 5, 100};
  std::vector<std::vector<double>> rows_a;
  Particles end_a;
  long faulted_a = 0;
  {
    Simulation a(s, 2);
    a.inject(nan);
    for (int i = 0; i < kSteps; ++i) {
      a.step();
      rows_a.push_back(ledger_row(a));
    }
    end_a = a.particles();
    faulted_a = a.faulted_particles();
  }
  Simulation c(s, 2);
  load_after(c, s, kHalf, [&](Simulation& b) { b.inject(nan); });
  BOOST_TEST(c.steps() == kHalf);
  std::size_t rows_differ = 0;
  for (int i = kHalf; i < kSteps; ++i) {
    c.step();
    rows_differ += ledger_row(c) == rows_a[i] ? 0 : 1;
  }
  const std::size_t particles_differ = differing(end_a, c.particles());
  BOOST_TEST_MESSAGE(
      end_a.size() << " particles, " << kSteps << " steps against " << kHalf << " + checkpoint + "
                   << kSteps - kHalf << ": " << particles_differ << " particles and " << rows_differ
                   << " ledger rows differ; " << c.faulted_particles() << " faulted particle");
  BOOST_TEST(particles_differ == 0u);
  BOOST_TEST(rows_differ == 0u);
  BOOST_TEST(faulted_a == 1);
  BOOST_TEST(c.faulted_particles() == faulted_a);
}

BOOST_AUTO_TEST_CASE(a_flow_stress_internal_variable_continues_from_a_checkpoint) {
  // Both blocks on MTS (an illustrative set: sigma_e grows from 0 where they flow).
  Json doc = load_scene_document(kScene);
  // The illustrative set with a lower athermal and intrinsic stress, so that the blocks flow.
  Json mts = testing::mts_illustrative_law();
  mts["sigma_a"] = 20e6;
  mts["sigma_i"] = 30e6;
  Json law = mts;  // the overrides are a merge patch: null takes Johnson-Cook's keys out
  for (const char* key : {"A", "B", "n", "C", "m", "reference_strain_rate", "rate_form"})
    law[key] = nullptr;
  for (auto& [name, material] : doc["materials"].items())
    material["overrides"]["constitutive_model"]["flow_stress"] = law;
  const Scene s = read_scene(doc, kScene);
  constexpr int kSteps = 40, kHalf = 20;
  Particles end_a;
  {
    Simulation a(s, 2);
    for (int i = 0; i < kSteps; ++i) a.step();
    end_a = a.particles();
  }
  Simulation c(s, 2);
  load_after(c, s, kHalf);
  for (int i = kHalf; i < kSteps; ++i) c.step();
  std::size_t hardened = 0;
  for (const PointState& p : end_a.state) hardened += p.flow_internal > 0.0 ? 1 : 0;
  const std::size_t particles_differ = differing(end_a, c.particles());
  BOOST_TEST_MESSAGE("MTS blocks: " << hardened << " of " << end_a.size()
                                    << " particles with sigma_e > 0; " << particles_differ
                                    << " differ after the restart");
  BOOST_TEST(hardened > 0u);
  BOOST_TEST(particles_differ == 0u);
}

// (a'') A body force of X and t (objects.<name>.body_force): the reference positions come back
// from the checkpoint and the ledger's external work continues bit for bit.
BOOST_AUTO_TEST_CASE(a_body_force_run_continues_bit_for_bit_from_a_checkpoint) {
  Json doc = load_scene_document(kScene);
  doc["constants"] = {{"K", 3e8}, {"w", 4e4}};
  for (auto& [name, object] : doc["objects"].items())
    object["body_force"] = {"K*(X - 0.03)*cos(w*t)", "-K*Y*0.1", 0};
  const Continuation r = continue_from_checkpoint(read_scene(doc, kScene), 40, 20);
  BOOST_TEST_REQUIRE(r.uninterrupted.X.size() == r.uninterrupted.size());
  BOOST_TEST(differing(r.uninterrupted, r.continued) == 0u);
  BOOST_TEST(r.rows_differ == 0u);
  BOOST_TEST(r.last.external_work != 0.0);
}

// (a'''') Rigid objects met at the particles (contact.rigid_contact = "particles"): the forces are
// evaluated afresh from the restored positions, seed points and time, and the contact energy
// column comes back with the ledger, so the disk in the trough continues bit for bit.
BOOST_AUTO_TEST_CASE(a_rigid_contact_at_the_particles_continues_bit_for_bit_from_a_checkpoint) {
  const Scene s = test::verification_scene(
      "rigid_trough.json", {{"physics", {{"contact", {{"rigid_contact", "particles"}}}}},
                            {"grid", {{"cells", {22, 22}}}}});
  // The disk meets the trough at step 84: the checkpoint falls in the contact, at step 100.
  const Continuation r = continue_from_checkpoint(s, 160, 100);
  BOOST_TEST(differing(r.uninterrupted, r.continued) == 0u);
  BOOST_TEST(r.rows_differ == 0u);
  const std::vector<std::string> names = Simulation(s, 1).ledger().sink_names();
  const auto column = std::find(names.begin(), names.end(), "contact_energy");
  BOOST_TEST_REQUIRE((column != names.end()));
  BOOST_TEST(r.last.sinks[std::size_t(column - names.begin())] > 0.0);  // the disk is pressed
}

namespace {
// The stick springs with their anchor off the particle (Particles::friction_anchor).
std::size_t stretched_springs(const Particles& P) {
  std::size_t n = 0;
  for (std::size_t p = 0; p < P.size(); ++p) n += P.friction_anchor[p] != P.x[p];
  return n;
}
}  // namespace

// (a''''') With friction there (contact.mu > 0): each particle's stick-spring anchor
// (Particles::friction_anchor) comes back from the checkpoint, so the block sliding on its rigid
// floor continues bit for bit.
BOOST_AUTO_TEST_CASE(a_rigid_friction_at_the_particles_continues_bit_for_bit_from_a_checkpoint) {
  const Scene s = test::verification_scene(
      "sliding_block_rigid.json", {{"physics", {{"contact", {{"rigid_contact", "particles"}}}}}});
  const Continuation r = continue_from_checkpoint(s, 60, 30);
  BOOST_TEST_REQUIRE(r.uninterrupted.friction_anchor.size() == r.uninterrupted.size());
  BOOST_TEST(stretched_springs(r.uninterrupted) > 0u);
  BOOST_TEST(differing(r.uninterrupted, r.continued) == 0u);
  BOOST_TEST(r.rows_differ == 0u);
}

// (a'''''') Walls met at the particles (grid.wall_contact = "particles") with friction and the
// penalty's damping: the anchors come back from the checkpoint as above, and the dashpots' forces
// are evaluated afresh at the restored positions, so the block sliding on its wall continues bit
// for bit, its contact_damping column too.
BOOST_AUTO_TEST_CASE(a_wall_met_at_the_particles_continues_bit_for_bit_from_a_checkpoint) {
  const Scene s = test::verification_scene(
      "sliding_block.json",
      {{"grid", {{"wall_contact", "particles"}, {"wall_penalty_damping", 0.3}}}});
  const Continuation r = continue_from_checkpoint(s, 60, 30);
  BOOST_TEST_REQUIRE(r.uninterrupted.friction_anchor.size() == r.uninterrupted.size());
  BOOST_TEST(stretched_springs(r.uninterrupted) > 0u);
  BOOST_TEST(differing(r.uninterrupted, r.continued) == 0u);
  BOOST_TEST(r.rows_differ == 0u);
  const std::vector<std::string> names = Simulation(s, 1).ledger().sink_names();
  const auto column = std::find(names.begin(), names.end(), "contact_damping");
  BOOST_TEST_REQUIRE((column != names.end()));
  BOOST_TEST(r.last.sinks[std::size_t(column - names.begin())] != 0.0);  // the dashpots acted
}

// (a''') A graded grid (grid.refine): each particle's uGIMP half-width, fixed at seeding, comes
// back from the checkpoint (Particles::half_width, checkpoint version 11), so the Taylor rod with
// its impact end refined continues bit for bit (artificial viscosity on: its length is the cell's).
BOOST_AUTO_TEST_CASE(a_graded_grid_run_continues_bit_for_bit_from_a_checkpoint) {
  const Scene s = test::verification_scene(
      "taylor_rod.json",
      {{"grid",
        {{"refine",
          {{"lower", {0.0, 0.0, 0.0}}, {"upper", {0.004, 0.00886, 0.00886}}, {"factor", 2}}}}}});
  const Continuation r = continue_from_checkpoint(s, 40, 20);
  BOOST_TEST_REQUIRE(r.uninterrupted.half_width.size() == r.uninterrupted.size());
  BOOST_TEST(differing(r.uninterrupted, r.continued) == 0u);
  BOOST_TEST(r.rows_differ == 0u);
}

BOOST_AUTO_TEST_CASE(interrupted_and_restarted_run_matches_the_uninterrupted_one) {
  const fs::path& a = uninterrupted();
  BOOST_TEST(!fs::exists(a / kCheckpointFile));  // off by default
  const fs::path b = scratch("b");
  RunOptions options;
  options.threads = 2;
  options.out_dir = b.string();
  options.faults = {{FaultInjection::Kind::sigterm, 30, 0}};
  BOOST_TEST(run(scene(), options) == 128 + 15);
  const Json status = read_json(b / "status.json");
  BOOST_TEST_MESSAGE("status.json after SIGTERM: " << status.dump());
  BOOST_TEST(status.at("status") == "interrupted");
  BOOST_TEST(status.at("step") == 30);
  BOOST_TEST(status.at("checkpoint").at("step") == 30);
  BOOST_TEST(status.at("message").get<std::string>().find("mpm run --restart") !=
             std::string::npos);
  BOOST_TEST(fs::exists(b / kCheckpointFile));
  BOOST_TEST(read_checkpoint_header(b / kCheckpointFile).step == 30);

  RunOptions again;  // threads from the checkpoint
  BOOST_REQUIRE(restart(b.string(), again) == 0);
  BOOST_TEST(read_json(b / "status.json").at("status") == "completed");
  require_same_outputs(a, b);
  fs::remove_all(b);
}

// (d) On 2D grids (docs/scenes.md#2d-grids): case01 in axisymmetry (friction contact, four
//     fields, artificial viscosity, erosion, particle conversion, the hoop terms) and the Taylor
//     rod in axisymmetry on an x- wall with friction 0.3: 40 steps uninterrupted against 20, a
//     checkpoint and 20, every particle array and ledger row bit for bit; and the run stopped by
//     SIGTERM after step 30 and restarted writes every file as the uninterrupted run.
std::vector<Scene> axisymmetric_scenes() {
  Json case01 = test::axisymmetric_case01_patch();
  case01["time"] = {{"max_time", 4.0e-6}, {"multiplier", 0.2}};
  case01["output"] = {{"interval", 1.0e-6}, {"fields", {"velocity", "pressure", "id"}}};
  Json taylor = {
      {"grid",
       {{"geometry", "axisymmetric"},
        {"lower", {-0.001, 0.0}},
        {"upper", {0.016455833333333336, 0.008860833333333333}},
        {"cells", {28, 14}},
        {"boundary", {{"x-", "wall"}, {"z-", nullptr}, {"z+", nullptr}}},
        {"wall_friction", {{"x-", 0.3}}}}},
      {"objects",
       {{"rod",
         {{"geometry", {{"bottom", {0.0001, 0.0, 0.0}}, {"top", {0.01529, 0.0, 0.0}}}},
          {"particles_per_cell", {2, 2}}}}}},
      {"time", {{"max_time", 6.0e-6}}},
      {"output",
       {{"interval", 1.5e-6}, {"snapshots", true}, {"fields", {"velocity", "temperature"}}}}};
  return {test::shipped_scene("sphere_cylinder/case01.json", case01),
          test::verification_scene("taylor_rod.json", taylor)};
}

BOOST_AUTO_TEST_CASE(an_axisymmetric_run_continues_bit_for_bit_from_a_checkpoint) {
  constexpr int kSteps = 40, kHalf = 20;
  for (const Scene& s : axisymmetric_scenes()) {
    BOOST_REQUIRE(s.grid.geometry == GridGeometry::axisymmetric);
    const Continuation r = continue_from_checkpoint(s, kSteps, kHalf);
    const std::size_t particles_differ = differing(r.uninterrupted, r.continued);
    const std::size_t rows_differ = r.rows_differ;
    BOOST_TEST_MESSAGE(s.file << " (axisymmetric): " << r.uninterrupted.size() << " particles, "
                              << kSteps << " steps against " << kHalf << " + checkpoint + "
                              << kSteps - kHalf << ": " << particles_differ << " particles and "
                              << rows_differ << " ledger rows differ");
    BOOST_TEST(particles_differ == 0u);
    BOOST_TEST(rows_differ == 0u);

    const fs::path a = scratch("axisymmetric_a"), b = scratch("axisymmetric_b");
    RunOptions options;
    options.threads = 2;
    options.out_dir = a.string();
    BOOST_REQUIRE(run(s, options) == 0);
    options.out_dir = b.string();
    options.faults = {{FaultInjection::Kind::sigterm, 30, 0}};
    BOOST_TEST(run(s, options) == 128 + 15);
    RunOptions again;
    BOOST_REQUIRE(restart(b.string(), again) == 0);
    require_same_outputs(a, b);
    fs::remove_all(a);
    fs::remove_all(b);
  }
}

// Issue 52: a restart rewrote the material paths of scene.json to absolute ones before hashing,
// so every checkpoint of a restarted run carried another hash and the second restart was refused
// ("scene.json: changed since the checkpoint was written"). Run from the repository root with the
// scene named by a relative path (scene.json then holds relative material paths, as for every
// shipped scene run from there): stopped three times (SIGTERM, SIGINT, SIGTERM) and restarted
// three times, the second restart from another working directory, every output file is as the
// uninterrupted run's.
BOOST_AUTO_TEST_CASE(a_run_restarts_as_often_as_it_stops) {
  const fs::path& a = uninterrupted();
  const fs::path b = scratch("three_stops");
  const fs::path here = fs::current_path();
  fs::current_path(IMPACT_SOURCE_DIR);
  const Scene relative = load_scene("tests/data/mpm_runs/contact_friction_av.json");
  RunOptions options;
  options.threads = 2;
  options.out_dir = b.string();
  options.faults = {{FaultInjection::Kind::sigterm, 12, 0}};
  BOOST_TEST(run(relative, options) == 128 + 15);
  const std::string scene_text = read_bytes(b / "scene.json");
  BOOST_TEST(scene_text.find("\"file\": \"data/materials/") != std::string::npos,
             "scene.json holds relative material paths");
  const std::vector<std::pair<FaultInjection::Kind, long>> stops = {
      {FaultInjection::Kind::sigint, 25}, {FaultInjection::Kind::sigterm, 40}};
  const fs::path elsewhere = fs::temp_directory_path();
  for (std::size_t i = 0; i < stops.size(); ++i) {
    if (i == 0) fs::current_path(elsewhere);  // the material paths stay the first run's
    RunOptions again;
    again.faults = {{stops[i].first, stops[i].second, 0}};
    const int code = stops[i].first == FaultInjection::Kind::sigint ? 128 + 2 : 128 + 15;
    BOOST_TEST(restart(b.string(), again) == code, "restart " << i + 1);
    BOOST_TEST(read_checkpoint_header(b / kCheckpointFile).step == stops[i].second);
    BOOST_TEST(read_checkpoint_header(b / kCheckpointFile).working_directory ==
               fs::path(IMPACT_SOURCE_DIR).string());
    fs::current_path(IMPACT_SOURCE_DIR);
  }
  BOOST_REQUIRE(restart(b.string(), RunOptions{}) == 0);
  fs::current_path(here);
  BOOST_TEST(read_json(b / "status.json").at("status") == "completed");
  // scene.json as the first run wrote it (the uninterrupted run's names its materials by absolute
  // path: it was loaded by one); every other file as the uninterrupted run's.
  BOOST_TEST(read_bytes(b / "scene.json") == scene_text);
  require_same_outputs(a, b, "scene.json");
  fs::remove_all(b);
}

// A particle path picks the particle nearest its position as seeded; a restarted run picked it
// among the particles as restored, so it followed another one (the audit of issue 52: particle
// 2222 uninterrupted, 2100 after a restart at step 300). The rod on the plate in axisymmetry, a
// path near the rod's impact face: the same particle, and the same end state, after a restart.
BOOST_AUTO_TEST_CASE(a_restarted_run_follows_the_particle_the_first_run_chose) {
  const Json patch = {
      {"time", {{"max_time", 1.2e-5}}},
      {"output",
       {{"snapshots", false},
        {"particle_paths", {{"tip", {{"object", "rod"}, {"position", {-0.0006, 0.0002}}}}}}}}};
  const Scene s = test::shipped_scene("rod_plate/axisymmetric.json", patch);
  const fs::path a = scratch("path_a"), b = scratch("path_b");
  RunOptions options;
  options.threads = 2;
  options.out_dir = a.string();
  BOOST_REQUIRE(run(s, options) == 0);
  options.out_dir = b.string();
  options.faults = {{FaultInjection::Kind::sigterm, 300, 0}};
  BOOST_REQUIRE(run(s, options) == 128 + 15);
  BOOST_REQUIRE(restart(b.string(), RunOptions{}) == 0);
  const Json pa = read_json(a / "summary.json").at("particle_paths").at("tip");
  const Json pb = read_json(b / "summary.json").at("particle_paths").at("tip");
  BOOST_TEST_MESSAGE("path particle: uninterrupted " << pa << ", restarted " << pb);
  BOOST_TEST(pa == pb);
  // The path's last row (the particle's end state): the same bits.
  const auto last_line = [](const fs::path& csv) {
    const std::string text = read_bytes(csv);
    const std::size_t end = text.find_last_not_of('\n');
    return text.substr(text.rfind('\n', end) + 1);
  };
  BOOST_TEST(last_line(a / "paths" / "tip.csv") == last_line(b / "paths" / "tip.csv"));
  fs::remove_all(a);
  fs::remove_all(b);
}

BOOST_AUTO_TEST_CASE(a_restart_drops_history_rows_written_after_the_checkpoint) {
  const fs::path& a = uninterrupted();
  const fs::path c = scratch("c");
  RunOptions options;
  options.threads = 2;
  Json doc = load_scene_document(kScene);
  doc.merge_patch({{"output", {{"checkpoint_interval_steps", 7}}}});
  const Scene every7 = read_scene(doc, kScene);
  options.out_dir = c.string();
  BOOST_REQUIRE(run(every7, options) == 0);
  const CheckpointHeader h = read_checkpoint_header(c / kCheckpointFile);
  const std::string full = read_bytes(c / "history.csv");
  BOOST_TEST_MESSAGE("last checkpoint: step " << h.step << ", time " << h.time << " s; "
                                              << read_json(c / "summary.json").at("steps")
                                              << " steps in all");
  BOOST_TEST(h.step % 7 == 0);
  // A completed run is not restarted (nothing to continue): the directory is made as a SIGKILL
  // after the last history row leaves it, status.json still "running".
  BOOST_CHECK_THROW(restart(c.string(), RunOptions{}), InputError);
  Json status = read_json(c / "status.json");
  status["status"] = "running";
  std::ofstream(c / "status.json") << status.dump(2) << '\n';
  BOOST_REQUIRE(restart(c.string(), RunOptions{}) == 0);
  BOOST_TEST(read_bytes(c / "history.csv") == full);  // no duplicated or lost rows
  // The scene differs only in the checkpoint interval: the particle outputs must match a.
  BOOST_TEST(read_bytes(c / "history.csv") == read_bytes(a / "history.csv"));
  BOOST_TEST(read_bytes(c / "particles.pvd") == read_bytes(a / "particles.pvd"));
  fs::remove_all(c);
}

BOOST_AUTO_TEST_CASE(a_restart_is_refused_for_a_foreign_or_corrupt_checkpoint) {
  const fs::path dir = scratch("refused");
  RunOptions options;
  options.threads = 2;
  options.out_dir = dir.string();
  options.faults = {{FaultInjection::Kind::sigint, 10, 0}};
  BOOST_REQUIRE(run(scene(), options) == 128 + 2);
  const fs::path file = dir / kCheckpointFile;
  const std::string good = read_bytes(file);
  const auto refused = [&](const std::string& expected) {
    try {
      restart(dir.string(), RunOptions{});
    } catch (const InputError& e) {
      BOOST_TEST_MESSAGE("refused: " << e.what());
      BOOST_TEST(std::string(e.what()).find(expected) != std::string::npos, e.what());
      return;
    }
    BOOST_ERROR("restart was not refused (expected \"" << expected << "\")");
  };
  const auto write = [&](const fs::path& f, const std::string& bytes) {
    std::ofstream(f, std::ios::binary) << bytes;
  };
  std::string other = good;
  other[16] = static_cast<char>(kCheckpointVersion + 1);  // the format version (u32 after the
                                                          // 16-byte magic)
  write(file, other);
  refused("checkpoint format version " + std::to_string(kCheckpointVersion + 1) +
          ", this mpm reads version " + std::to_string(kCheckpointVersion));
  // A flipped bit anywhere after the version reads as corruption, whichever field it lands on
  // (the body's layout shifts with the length of the working directory stored in the header).
  // A section tag is checked by the parser: without the trailer checked first, the flip there
  // reads as a misplaced section.
  // Bytes 28-43 are the file's length and its complement: a flip there is corrupt too.
  for (const std::size_t at :
       {std::size_t{30}, std::size_t{40}, std::size_t{50}, good.find("state"), good.size() / 4,
        good.size() / 2, 3 * good.size() / 4, good.size() - 9, good.size() - 1}) {
    std::string corrupt = good;
    corrupt[at] ^= 0x10;
    write(file, corrupt);
    refused("corrupt checkpoint");
  }
  // A file cut short (a copy, a full disk) says so, with its length and the length it should have;
  // before, a cut anywhere read as a checksum mismatch.
  for (const std::size_t length : {good.size() - 1, good.size() / 2, std::size_t{60}}) {
    write(file, good.substr(0, length));
    refused("truncated: " + std::to_string(length) + " of " + std::to_string(good.size()) +
            " bytes");
  }
  write(file, good.substr(0, 20));
  refused("truncated: 20 bytes, shorter than a checkpoint's header");
  write(file, good + "x");
  refused("1 bytes after the end of the checkpoint");
  write(file, good);
  const std::string scene_text = read_bytes(dir / "scene.json");
  write(dir / "scene.json", scene_text + " ");
  refused("changed since the checkpoint was written");
  write(dir / "scene.json", scene_text);
  fs::remove(file);
  refused("no checkpoint");
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
