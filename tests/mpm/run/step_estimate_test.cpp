// Step estimate (mpm/run/step_estimate.hpp; docs/mpm.md#memory-and-step-estimates):
// - the first stable step from the scene alone is multiplier x the smallest cell / (c_L + |v0|),
//   c_L = sqrt((K + 4 mu/3)/rho) worked from the material's parameters, and the count is the
//   step count of the run itself where the signal speed stays constant (a stress-free
//   translation: 493 steps);
// - the inputs of issue 52 that loaded and never finished (max_time 1e30 s, multiplier 1e-300, a
//   density of 1e-30 kg/m^3), a tiny max_dt and an absurd velocity are refused by step_refusal
//   and by run() (exit 4, nothing written), each naming the key that drives the count;
//   time.max_estimated_steps raises the bound;
// - a scene within the step bound whose particle-steps (the particles the geometry seeds times
//   the steps) exceed time.max_estimated_particle_steps is refused too: 100000 x 3 x 3 cells of
//   the same block, 4.1e6 steps of 2.7e5 particles (an ETA of 8 days in the second trial).
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "../verification_helpers.hpp"
#include "mpm/run/step_estimate.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string three_digits(double v) {
  std::ostringstream o;
  o.precision(3);
  o << v;
  return o.str();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_step_estimate)

BOOST_AUTO_TEST_CASE(the_estimate_is_the_first_stable_step_and_the_runs_count) {
  const Scene scene = test::verification_scene("rigid_translation.json");
  const double c = test::longitudinal_wave_speed(scene);
  const double speed = std::sqrt(30.0 * 30.0 + 20.0 * 20.0 + 10.0 * 10.0);
  const double dt = 0.5 * (0.06 / 12) / (c + speed);  // multiplier 0.5, 12 cells over 0.06 m
  const StepEstimate e = estimate_steps(scene);
  BOOST_TEST(e.dt == dt, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(e.wave_speed == c, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(e.steps == std::ceil(2e-4 / dt));
  // The block's stress stays zero, so every step is the first one's: the run takes the count.
  Simulation sim(scene);
  while (!sim.finished()) sim.step();
  BOOST_TEST(sim.steps() == 493);
  BOOST_TEST(e.steps == 493.0);
  BOOST_TEST(step_refusal(scene).empty());
  // time.max_dt below the stable step takes its place.
  const StepEstimate capped = estimate_steps(
      test::verification_scene("rigid_translation.json", {{"time", {{"max_dt", 1e-8}}}}));
  BOOST_TEST(capped.capped);
  BOOST_TEST(capped.steps == std::ceil(2e-4 / 1e-8));
}

BOOST_AUTO_TEST_CASE(an_absurd_count_is_refused_naming_the_key_that_drives_it) {
  const auto refusal = [](const Json& patch) {
    return step_refusal(test::verification_scene("rigid_translation.json", patch));
  };
  const std::string max_time = refusal({{"time", {{"max_time", 1e30}}}});
  BOOST_TEST(contains(max_time,
                      "refusing to start: an estimated 2.5e+36 steps (time.max_time "
                      "1e+30 s over a first step of 4.06e-07 s: time.multiplier 0.5 x "
                      "the smallest cell 0.005 m / the fastest signal"),
             max_time);
  BOOST_TEST(contains(max_time,
                      "exceed time.max_estimated_steps = 1e+07; the key that drives the "
                      "count: time.max_time (1e+30 s); correct it, or raise "
                      "time.max_estimated_steps to run the scene anyway"),
             max_time);
  BOOST_TEST(contains(refusal({{"time", {{"multiplier", 1e-300}}}}),
                      "the key that drives the count: time.multiplier (1e-300)"));
  BOOST_TEST(contains(refusal({{"time", {{"max_dt", 1e-20}}}}),
                      "first step of 1e-20 s: time.max_dt, below the stable step) exceed"));
  BOOST_TEST(contains(refusal({{"time", {{"max_dt", 1e-20}}}}),
                      "the key that drives the count: time.max_dt (1e-20 s)"));
  // Below light's speed (faster is an input error, input_scene_velocity_beyond_light), yet 1.6e7
  // steps.
  BOOST_TEST(contains(refusal({{"objects", {{"block", {{"velocity", {2e8, 0.0, 0.0}}}}}}}),
                      "the key that drives the count: /objects/block/velocity (2e+08 m/s)"));
  // A density of 1e-30 kg/m^3 (admissible: above 0) makes the wave speed 1e15 times faster.
  const Json light = {{"materials", {{"elastic_al", {{"overrides", {{"density", 1e-30}}}}}}}};
  const Scene scene = test::verification_scene("rigid_translation.json", light);
  const auto& p = scene.materials.front().material.model.params();
  const double c = std::sqrt((p.bulk_modulus + 4.0 * p.shear_modulus / 3.0) / 1e-30);
  BOOST_TEST(contains(step_refusal(scene),
                      "the key that drives the count: /materials/elastic_al (its density "
                      "1e-30 kg/m^3, from its file or overrides/density, and moduli give a "
                      "wave speed of " +
                          three_digits(c) + " m/s)"),
             step_refusal(scene));
  // The bound is a key: raised, the same scene starts.
  BOOST_TEST(refusal({{"time",
                       {{"max_time", 1e30},
                        {"max_estimated_steps", 1e37},
                        {"max_estimated_particle_steps", 1e40}}}})
                 .empty());
  BOOST_TEST(!refusal({{"time", {{"max_time", 10.0}}}}).empty());  // 2.5e7 steps
  BOOST_TEST(refusal({{"time", {{"max_time", 10.0}, {"max_estimated_steps", 1e8}}}}).empty());
}

BOOST_AUTO_TEST_CASE(run_refuses_before_it_writes_anything) {
  const fs::path dir =
      fs::temp_directory_path() / ("step_estimate_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  RunOptions options;
  options.out_dir = dir.string();
  const Scene scene =
      test::verification_scene("rigid_translation.json", {{"time", {{"max_time", 1e30}}}});
  BOOST_TEST(run(scene, options) == kExitMemory);
  BOOST_TEST(!fs::exists(dir));
  BOOST_TEST(start_refusal(scene) == step_refusal(scene));
}

BOOST_AUTO_TEST_CASE(very_many_particle_steps_are_refused_naming_the_cells) {
  const Json fine = {{"grid", {{"cells", {100000, 3, 3}}}}};
  const Scene scene = test::verification_scene("rigid_translation.json", fine);
  const StepEstimate e = estimate_steps(scene);
  BOOST_TEST(e.steps < scene.time.max_estimated_steps);  // the step bound alone lets it pass
  // The block's 0.02 m cube (rigid_translation.json) at 2 particles per cell per axis: its
  // volume over the cell's, times 8.
  const Vec3 h = scene.grid.spacing();
  BOOST_TEST(e.particles == std::ceil(std::pow(0.02, 3) / h.prod() * 8.0),
             boost::test_tools::tolerance(1e-9));
  BOOST_TEST(e.particle_steps == e.particles * e.steps);
  const std::string refusal = step_refusal(scene);
  BOOST_TEST(contains(refusal,
                      "refusing to start: an estimated 1.1e+12 particle-steps (266667 "
                      "particles estimated from the geometry on 100000 x 3 x 3 cells"),
             refusal);
  BOOST_TEST(contains(refusal, "exceed time.max_estimated_particle_steps = 3e+11"), refusal);
  // Raised, the same scene starts; the shipped scenes are far below (5.96e7 the largest).
  BOOST_TEST(
      step_refusal(test::verification_scene("rigid_translation.json",
                                            {{"grid", {{"cells", {100000, 3, 3}}}},
                                             {"time", {{"max_estimated_particle_steps", 2e12}}}}))
          .empty());
}

// The body-force step (mpm/step/time_step.cpp): a particle released at rest under a gravity that
// outruns the wave speed's step moves multiplier cells per step at most, (g dt) dt = multiplier dx.
// Before it, 1e12 m/s^2 carried the block 10 cells in its first step, through the wall below it,
// and the run stopped on "left the grid"; 1e300 m/s^2 was accepted by mpm check.
BOOST_AUTO_TEST_CASE(gravity_that_outruns_the_waves_limits_the_step) {
  const double dx = 0.06 / 12, multiplier = 0.5;  // rigid_translation.json
  const double g = 1e12;
  const Json patch = {{"objects", {{"block", {{"velocity", {0.0, 0.0, 0.0}}}}}},
                      {"solver", {{"gravity", {-g, 0.0, 0.0}}}},
                      {"time", {{"max_time", 1e-6}, {"initial_dt", 1.0}}}};
  const Scene scene = test::verification_scene("rigid_translation.json", patch);
  const double body = std::sqrt(multiplier * dx / g);  // 5e-8 s
  const double waves = multiplier * dx / test::longitudinal_wave_speed(scene);
  BOOST_TEST(body < waves);  // gravity binds: 5e-8 against 4.1e-7 s
  BOOST_TEST(body_force_time_step(dx, g, multiplier) == body, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(std::isinf(body_force_time_step(dx, 0.0, multiplier)));
  const StepEstimate e = estimate_steps(scene);
  BOOST_TEST(e.gravity_limited);
  BOOST_TEST(e.dt == body, boost::test_tools::tolerance(1e-14));
  // The run takes the same step, and its first step moves the block by exactly the bound:
  // x^1 - x^0 = dt v^1, v^1 = g dt (a free fall on a free grid, 4 cells clear of x-).
  Simulation sim(scene);
  const double x0 = sim.particles().x[0](0);
  sim.step();
  BOOST_TEST(sim.time() == body, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(x0 - sim.particles().x[0](0) == multiplier * dx, boost::test_tools::tolerance(1e-9));
  // 1e300 m/s^2: refused before it starts, naming the key.
  const std::string refusal = step_refusal(test::verification_scene(
      "rigid_translation.json", {{"solver", {{"gravity", {-1e300, 0.0, 0.0}}}}}));
  BOOST_TEST(contains(refusal,
                      "over a first step of 5e-152 s: sqrt(time.multiplier 0.5 x the "
                      "smallest cell 0.005 m / solver.gravity 1e+300 m/s^2)"),
             refusal);
  BOOST_TEST(contains(refusal, "the key that drives the count: solver.gravity (1e+300 m/s^2)"),
             refusal);
  // A body-force step below time.min_dt would stop the run at step 1 blaming the fastest signal:
  // refused first, naming both keys (5e-8 s against 1e-7 s).
  const std::string below = step_refusal(test::verification_scene(
      "rigid_translation.json",
      {{"solver", {{"gravity", {-g, 0.0, 0.0}}}}, {"time", {{"min_dt", 1e-7}}}}));
  BOOST_TEST(
      contains(below, "solver.gravity 1e+12 m/s^2) = 5e-08 s is below time.min_dt = 1e-07 s"),
      below);
  BOOST_TEST(step_refusal(test::verification_scene("rigid_translation.json",
                                                   {{"solver", {{"gravity", {-g, 0.0, 0.0}}}},
                                                    {"time", {{"min_dt", 1e-8}}}}))
                 .empty());
  // The shipped gravity scenes (1e5 m/s^2 on 1 mm cells: 7.1e-5 s) are far from the bound: 850
  // times the step aluminium's waves allow there (0.5 x 1 mm / 6000 m/s).
  BOOST_TEST(body_force_time_step(1e-3, 1e5, 0.5) > 500.0 * 0.5 * 1e-3 / 6000.0);
}

BOOST_AUTO_TEST_SUITE_END()
