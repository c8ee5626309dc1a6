// Stability where methods fail: the energy-growth check (time.max_energy_growth,
// docs/mpm.md#failure-handling) on data/scenes/verification/two_spheres.json (two elastic spheres,
// 4304 particles, head-on at 2 x 10 m/s in one velocity field, 30 us) and contact_blocks.json.
// (a) Stable: at multiplier 0.5 the run completes and |energy_error| stays below 3 % of E0 at every
//     step, for the default gimp/MUSL and for linear/USL (measured max 1.61 % and 2.34 %; end
//     +0.36 % and -0.52 %): 30 times below the default limit of +100 %.
// (b) Unstable: USL goes unstable above multiplier ~0.7 on this scene (bisected over 30 us:
//     linear/USL stable at 0.691, unstable from 0.695; gimp/USL stable at 0.716, unstable from
//     0.719; MUSL, either interpolation, stays stable up to the cap 1.5). At 1.2 the check stops
//     linear/USL with SolverFailure at step 5 (asserted: within 10 steps) and at 0.75 at step 27
//     (asserted: within 60); the message names the step, the time, the energies, and the fastest
//     particle with its material, object and position. With the check off (max_energy_growth
//     1e300) the same run at 1.2 goes on until a negative Jacobian at step 8 (asserted: later
//     than the check), and at 0.72 (gimp/USL) it even completes: energy_error peaks at +7 (700 %
//     of E0) and comes back as the stable step shrinks with the particle speeds; only the check
//     reports it.
// (c) The report's case 2 observation, "initial dt 1e-11 s / delt_min below 5e-8 s makes the run
//     unstable", does not apply: contact_blocks (two touching elastic blocks, 3072 particles)
//     with initial_dt = 1e-11 s, and with every step capped at max_dt = 2e-8 s (all 201 steps
//     below 5e-8 s), completes with |energy_error| below 6 % at every step (measured 5.29 % and
//     1.10 %: the bound is that of the same scene at the stable step, 5.29 %, which is the
//     eq. 14 staggering of this coarse impact, docs/mpm.md#ledger).
#include <boost/test/unit_test.hpp>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Outcome {
  bool failed = false;
  std::string message;
  long steps = 0;              ///< steps completed (incl. the failing one for the energy check)
  double max_abs_error = 0.0;  ///< max over steps of |energy_error|
  double max_error = 0.0;      ///< max over steps of energy_error
  double end_error = 0.0;
};

Outcome run(const std::string& scene_file, const Json& patch) {
  const Scene scene = test::verification_scene(scene_file, patch);
  Simulation sim(scene);
  Outcome o;
  try {
    while (!sim.finished()) {
      sim.step();
      const double e = sim.ledger().row().energy_error;
      o.max_abs_error = std::max(o.max_abs_error, std::abs(e));
      o.max_error = std::max(o.max_error, e);
    }
  } catch (const SolverFailure& f) {
    o.failed = true;
    o.message = f.what();
  }
  o.steps = sim.steps();
  o.end_error = sim.ledger().row().energy_error;
  BOOST_TEST_MESSAGE(scene_file << " " << patch.dump() << ": "
                                << (o.failed ? "FAILED" : "completed") << " after " << o.steps
                                << " steps, t = " << sim.time() * 1e6 << " us; energy_error end "
                                << o.end_error << ", max " << o.max_error << ", max |.| "
                                << o.max_abs_error << (o.failed ? "; " + o.message : ""));
  return o;
}

Json spheres(const char* interpolation, const char* scheme, double multiplier,
             double max_energy_growth = 1.0) {
  Json p = test::with_solver(interpolation, scheme);
  p["time"] = {{"multiplier", multiplier}, {"max_energy_growth", max_energy_growth}};
  return p;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_stability)

BOOST_AUTO_TEST_CASE(a_stable_run_stays_within_3_percent_of_e0) {
  for (const auto& [interpolation, scheme] : {std::pair{"gimp", "musl"}, {"linear", "usl"}}) {
    const Outcome o = run("two_spheres.json", spheres(interpolation, scheme, 0.5));
    BOOST_TEST(!o.failed);
    BOOST_TEST(o.max_abs_error < 0.03);
  }
}

BOOST_AUTO_TEST_CASE(an_unstable_run_is_stopped_within_a_few_steps_and_named) {
  const Outcome o = run("two_spheres.json", spheres("linear", "usl", 1.2));
  BOOST_TEST_REQUIRE(o.failed);
  BOOST_TEST(o.steps <= 10);
  BOOST_TEST(o.max_error <= 1.0);  // every completed step was below the limit
  BOOST_TEST(o.end_error > 1.0);   // the failing step is the first above it
  // "step N, time T s: particle P (material M, object O, x = [...] m): energy: kinetic + strain
  // energy ... against ... J that entered ...; this particle is the fastest, |v| = ... m/s"
  BOOST_TEST(contains(o.message, "step " + std::to_string(o.steps) + ", time "));
  BOOST_TEST(contains(o.message, ": particle "));
  BOOST_TEST(contains(o.message, "(material elastic_al, object "));
  BOOST_TEST(contains(o.message, "x = ["));
  BOOST_TEST(contains(o.message, "): energy: kinetic + strain energy "));
  BOOST_TEST(contains(o.message, "J that entered (E0 "));
  BOOST_TEST(contains(o.message, "above time.max_energy_growth = 1"));
  BOOST_TEST(contains(o.message, "the fastest, |v| = "));

  // Just above the bisected limit the growth is slower but still caught.
  const Outcome near = run("two_spheres.json", spheres("linear", "usl", 0.75));
  BOOST_TEST(near.failed);
  BOOST_TEST(near.steps <= 60);
  BOOST_TEST(contains(near.message, "): energy: "));

  // Without the check the same run goes on: a negative Jacobian only later.
  const Outcome off = run("two_spheres.json", spheres("linear", "usl", 1.2, 1e300));
  BOOST_TEST(off.steps > o.steps);
  BOOST_TEST(!contains(off.message, "): energy: "));
}

BOOST_AUTO_TEST_CASE(without_the_check_an_unstable_run_completes_silently) {
  // gimp/USL at 0.72: energy_error grows to +7 and falls back as dt shrinks: a run that
  // "completes" with garbage. The check stops it at the first step above +100 %.
  const Outcome off = run("two_spheres.json", spheres("gimp", "usl", 0.72, 1e300));
  BOOST_TEST(!off.failed);
  BOOST_TEST(off.max_error > 2.0);
  const Outcome on = run("two_spheres.json", spheres("gimp", "usl", 0.72));
  BOOST_TEST(on.failed);
  BOOST_TEST(contains(on.message, "): energy: "));
}

BOOST_AUTO_TEST_CASE(a_tiny_time_step_does_not_make_the_run_unstable) {
  // The report's case 2: initial dt 1e-11 s; then every step below its delt_min 5e-8 s.
  const Outcome reference = run("contact_blocks.json", Json::object());
  const Outcome tiny = run("contact_blocks.json", {{"time", {{"initial_dt", 1e-11}}}});
  const Outcome capped =
      run("contact_blocks.json",
          {{"time", {{"initial_dt", 1e-11}, {"max_dt", 2e-8}, {"max_time", 4e-6}}}});
  for (const Outcome* o : {&reference, &tiny, &capped}) {
    BOOST_TEST(!o->failed);
    BOOST_TEST(o->max_abs_error < 0.06);
  }
  BOOST_TEST(tiny.steps == reference.steps + 1);  // one extra step of 1e-11 s, nothing else
  BOOST_TEST(std::abs(tiny.end_error - reference.end_error) < 1e-3);
  BOOST_TEST(capped.steps >= 200);
}

BOOST_AUTO_TEST_SUITE_END()
