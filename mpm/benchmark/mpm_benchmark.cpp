// mpm_benchmark [--quick] [--large]: particle-steps per second of the explicit step on the
// report's sphere-cylinder geometry (data/scenes/sphere_cylinder/case01.json), for linear and GIMP,
// elastic (A = 1e15) and Johnson-Cook plastic, at ~30 k particles (the deck's grid) and ~240 k
// (grid refined 2x per axis; --large adds ~1.9 M at 4x), with 1 and 2 threads. Prints the time
// per phase and memory per particle. Not a test: numbers go to docs/performance_mpm.md.
#include <omp.h>

#include <cstring>
#include <iostream>
#include <string>

#include "mpm/solver.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Case {
  const char* interpolation;
  bool plastic;
  int refine;
  int threads;
};

void run_case(const Json& base, const std::string& file, const Case& c, int steps) {
  Json doc = base;
  doc["solver"]["interpolation"] = c.interpolation;
  doc["solver"]["scheme"] = "musl";
  doc["grid"]["cells"] = {50 * c.refine, 20 * c.refine, 20 * c.refine};
  doc["output"]["snapshots"] = false;
  Json cm = {{"damage", {{"type", "none"}}}, {"erosion", {{"algorithm", "none"}}}};
  if (!c.plastic) cm["flow_stress"] = {{"A", 1e15}};
  doc["materials"]["al6061_t6"]["overrides"] = {{"constitutive_model", cm}};
  const Scene scene = read_scene(doc, file);
  Simulation sim(scene, c.threads);
  sim.step();  // warm-up (first touch of the grid buffers)
  PhaseTimes total;
  const double t0 = omp_get_wtime();
  for (int s = 0; s < steps; ++s) {
    const PhaseTimes& p = sim.step().seconds;
    total.particles_to_grid += p.particles_to_grid;
    total.grid_update += p.grid_update;
    total.grid_to_particles += p.grid_to_particles;
    total.remap += p.remap;
    total.stress += p.stress;
  }
  const double wall = omp_get_wtime() - t0;
  const double n = double(sim.particles().size());
  const double rate = n * steps / wall;
  const double bytes = Particles::bytes_per_particle() + double(sim.grid().bytes()) / n;
  std::printf(
      "%-6s %-7s %9.0f %2d | %8.3f M/s | P2G %4.1f%%  grid %4.1f%%  G2P %4.1f%%  remap+move "
      "%4.1f%%  stress %4.1f%% | %5.0f B/particle\n",
      c.interpolation, c.plastic ? "JC" : "elastic", n, c.threads, rate / 1e6,
      100 * total.particles_to_grid / wall, 100 * total.grid_update / wall,
      100 * total.grid_to_particles / wall, 100 * total.remap / wall, 100 * total.stress / wall,
      bytes);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, large = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else if (std::strcmp(argv[i], "--large") == 0) {
      large = true;
    } else {
      std::cerr << "usage: mpm_benchmark [--quick] [--large]\n";
      return 1;
    }
  }
  const std::string file =
      std::string(IMPACT_SOURCE_DIR) + "/data/scenes/sphere_cylinder/case01.json";
  try {
    const Json base = load_scene_document(file);
    std::printf("shape  model   particles th | throughput   | share of step wall time (MUSL)\n");
    std::vector<int> refines = {1, 2};
    if (large) refines.push_back(4);
    for (int refine : refines) {
      const int steps = quick ? 3 : (refine == 1 ? 40 : refine == 2 ? 10 : 3);
      for (const char* interp : {"linear", "gimp"})
        for (bool plastic : {false, true})
          for (int threads : {1, 2})
            run_case(base, file, {interp, plastic, refine, threads}, steps);
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 2;
  }
  return 0;
}
