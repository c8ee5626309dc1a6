// The scene's time, solver and physics blocks (docs/scenes.md).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include "mpm/input/block_readers.hpp"
#include "mpm/input/scene_keys.hpp"
#include "mpm/shape/shape.hpp"

namespace impact::mpm::scene_input {

// The explicit step is stable up to about multiplier 1 (CFL); larger values are allowed so that a
// user can test where it fails (docs/accuracy.md#stability-map), but never silently.
constexpr double kMaxMultiplier = 1.5;
// solver.shuffle_particles: a seed that a double and a JSON number hold exactly.
constexpr double kLargestSeed = 1e15;

void read_time(JsonReader& root, TimeSpec& t, std::vector<std::string>& warnings) {
  JsonReader r = root.child("time", "time stepping (the report's <Time> block)");
  t.max_time = r.number("max_time", Range::positive(), "end time [s]");
  t.initial_dt = r.number_or("initial_dt", kInf, Range::positive(),
                             "first step, capped at the stable step [s]; default: stable step");
  t.min_dt = r.number_or("min_dt", 0.0, Range::non_negative(),
                         "the run stops when the step falls below this [s]");
  t.max_dt = r.number_or("max_dt", kInf, Range::positive(), "cap on the step [s]");
  t.multiplier = r.number_or("multiplier", 0.5, Range::open_closed(0.0, kMaxMultiplier),
                             "factor on the stable step (CFL number) [-]");
  if (t.multiplier > 1.0 && t.multiplier <= kMaxMultiplier) {
    std::ostringstream w;
    w << r.problems().file() << ": " << r.key_path("multiplier") << ": " << t.multiplier
      << " is above 1, the 1-D CFL limit of the stable step: the run may go unstable (the "
         "energy-growth check, time.max_energy_growth, stops it; docs/accuracy.md)";
    warnings.push_back(w.str());
  }
  t.max_energy_growth =
      r.number_or("max_energy_growth", 1.0, Range::positive(),
                  "the run stops when energy_error exceeds this (+1 = +100 % of the energy that "
                  "entered) [-]");
  t.max_estimated_steps = r.number_or(
      "max_estimated_steps", TimeSpec{}.max_estimated_steps, Range::positive(),
      "mpm run refuses a scene whose step count, estimated before the run (max_time over the "
      "first stable step), exceeds this [-]");
  t.max_estimated_particle_steps = r.number_or(
      "max_estimated_particle_steps", TimeSpec{}.max_estimated_particle_steps, Range::positive(),
      "mpm run refuses a scene whose particle-steps, estimated before the run (the particles "
      "the geometry seeds times the estimated steps), exceed this [-]");
  if (t.min_dt > t.max_dt) r.problems().add(r.key_path("min_dt"), "expected min_dt <= max_dt");
  r.reject_unknown_keys();
}

void read_solver(JsonReader& root, const Json& doc, SolverSpec& s) {
  // Every solver and output key has a default, so the blocks themselves are optional.
  JsonReader r = root.optional_child("solver", "algorithm choices")
                     .value_or(JsonReader(empty_json_object(), "/solver", root.problems()));
  s.interpolation = r.choice("interpolation", shape_names(),
                             "shape functions (mpm/shape/shape.hpp)", shape_names().front());
  s.scheme = r.choice("scheme", {"usl", "musl"}, "update scheme", "musl") == "usl" ? Scheme::usl
                                                                                   : Scheme::musl;
  s.f_integration =
      r.choice("deformation_gradient", {"forward_euler", "exponential"},
               "F_{n+1} = (I + L dt) F_n or exp(L dt) F_n", "forward_euler") == "exponential"
          ? FIntegration::exponential
          : FIntegration::forward_euler;
  s.gravity =
      read_vec3(r, at(doc, "solver"), "gravity", "body force per unit mass [m/s^2]", Vec3::Zero());
  s.rebalance_above = r.number_or(
      "rebalance_above", 1.2, Range::open(1.0, std::numeric_limits<double>::infinity()),
      "several ranks: re-balance the boxes when the largest particle count exceeds this multiple "
      "of the mean [-]");
  const Json& solver = at(doc, "solver");
  if (solver.is_object() && solver.contains("ranks_per_axis") &&
      solver["ranks_per_axis"].is_string()) {
    s.split = r.choice("ranks_per_axis", {"fewest_cut_faces", "least_loaded"},
                       "several ranks: the split cutting the fewest node faces, or the least "
                       "loaded boxes",
                       "fewest_cut_faces") == "least_loaded"
                  ? SplitRule::least_loaded
                  : SplitRule::fewest_cut_faces;
  } else {
    s.ranks_per_axis = read_int3(
        r, solver, "ranks_per_axis", 0, 1 << 20,
        "several ranks: boxes per axis, their product the rank count; [0, 0, 0] chooses the "
        "split cutting the fewest node faces (\"fewest_cut_faces\"), \"least_loaded\" the "
        "least loaded boxes",
        std::array<int, 3>{0, 0, 0});
  }
  const auto& p = s.ranks_per_axis;
  if ((p[0] == 0 || p[1] == 0 || p[2] == 0) && !(p[0] == 0 && p[1] == 0 && p[2] == 0))
    r.problems().add(r.key_path("ranks_per_axis"),
                     "expected three integers >= 1 ([px, py] on a 2D grid), [0, 0, 0] for the "
                     "automatic split ([0, 0] on a 2D grid), or \"least_loaded\"");
  const double shuffle = r.number_or(
      "shuffle_particles", 0.0, Range::closed(0.0, kLargestSeed),
      "0: the particles stored in seed order; k >= 1: in a permutation drawn with seed k, for "
      "measuring how round-off in the order of the sums moves the results [-]");
  // A refused read (not a number, out of range) has its problem already.
  if (shuffle >= 0.0 && shuffle <= kLargestSeed) {
    if (shuffle != std::floor(shuffle))
      r.problems().add(r.key_path("shuffle_particles"),
                       "expected a whole number (0: seed order; k >= 1: the shuffle's seed)");
    else
      s.shuffle_particles = static_cast<std::uint64_t>(shuffle);
  }
  r.reject_unknown_keys();
}

void read_physics(JsonReader& root, PhysicsSpec& ph) {
  JsonReader r = root.optional_child("physics", "optional physics (the report's <MPM> flags)")
                     .value_or(JsonReader(empty_json_object(), "/physics", root.problems()));
  // A contact block or type that cannot be read is one error: the multi-field model is then
  // assumed, so that the checks which depend on the type (a rigid object needs it; mu is refused
  // under single_velocity) do not blame the scene's other keys for the slip (a new-user trial:
  // "frictional" drew two such errors after the right one).
  const std::size_t problems_before = r.problems().count();
  if (auto c = r.optional_child("contact", "interaction of the materials' velocity fields")) {
    // "approach" is the report's name for the same model as "friction" (contact/contact.hpp).
    const std::string type = c->choice("type", {"single_velocity", "friction", "approach"},
                                       "contact model", "single_velocity");
    const bool type_unknown = r.problems().count() > problems_before;  // the block or its type
    ph.contact.type = type == "single_velocity" && !type_unknown ? ContactType::single_velocity
                                                                 : ContactType::friction;
    ph.contact.mu =
        c->number_or("mu", 0.0, Range::closed(0.0, 10.0), "Coulomb friction coefficient [-]");
    const std::string normal =
        c->choice("normal", {"mass_gradients", "larger_volume", "logistic_regression"},
                  "contact normal at a node", "mass_gradients");
    ph.contact.normal = normal == "larger_volume"         ? ContactNormal::larger_volume
                        : normal == "logistic_regression" ? ContactNormal::logistic_regression
                                                          : ContactNormal::mass_gradients;
    const std::string detection = c->choice(
        "detection", {"approach", "separation"},
        "when two bodies at a node are in contact: where they approach, or where they approach "
        "and their particles meet (needs \"normal\": \"logistic_regression\")",
        "approach");
    ph.contact.detection =
        detection == "separation" ? ContactDetection::separation : ContactDetection::approach;
    const std::string rigid = c->choice(
        "rigid_contact", {"nodes", "particles"},
        "where bodies meet the rigid objects: at the shared nodes, or at the particles, by a "
        "penalty against the rigid geometry's exact surface, with Coulomb friction mu",
        "nodes");
    ph.contact.rigid = rigid == "particles" ? RigidContact::particles : RigidContact::nodes;
    ph.contact.penalty_damping = c->number_or(
        "penalty_damping", 0.0, Range::closed(0.0, 0.5),
        "damping of the contact at the particles, a fraction of each particle's critical damping "
        "[-]");
    if (ph.contact.type == ContactType::friction && ph.contact.rigid != RigidContact::particles &&
        c->has("penalty_damping"))
      c->problems().add(c->key_path("penalty_damping"),
                        "damps the penalty of the contact at the particles only: set "
                        "\"rigid_contact\": \"particles\", or remove the key");
    if (ph.contact.type == ContactType::friction &&
        ph.contact.detection == ContactDetection::separation &&
        ph.contact.normal != ContactNormal::logistic_regression)
      c->problems().add(c->key_path("detection"),
                        "\"separation\" measures the bodies' gap along the plane the logistic "
                        "regression fits: set \"normal\" to \"logistic_regression\" too");
    // One shared velocity field has no contact surface: a friction coefficient or a normal rule
    // there would be read and ignored, so it is refused (issue 53). A scene that extends one with
    // friction removes the inherited keys with null (RFC 7396).
    if (ph.contact.type == ContactType::single_velocity) {
      for (const char* key : {"mu", "normal", "rigid_contact", "penalty_damping"})
        if (c->has(key))
          c->problems().add(c->key_path(key),
                            "read only by the \"friction\" contact (also called \"approach\"); "
                            "the type here is \"single_velocity\" (the default where \"type\" "
                            "is absent or null), one velocity field with no contact surface: "
                            "remove the key (null removes one inherited through \"extends\") or "
                            "set type to \"friction\"");
      // "approach" is also a type's name: the message says which is meant.
      if (c->has("detection"))
        c->problems().add(c->key_path("detection"),
                          "when bodies touch is decided only by the \"friction\" contact; "
                          "\"single_velocity\" is one velocity field whose bodies never part: "
                          "remove the key (null removes one inherited through \"extends\") or "
                          "set type to \"friction\" (with \"normal\": \"logistic_regression\" "
                          "for \"separation\")");
    }
    c->reject_unknown_keys();
  }
  if (auto a = r.optional_child("artificial_viscosity", "bulk viscosity, report eq. 12")) {
    ph.artificial_viscosity.enabled = a->boolean_or("enabled", true, "switch");
    ph.artificial_viscosity.linear =
        a->number_or("linear", 0.2, Range::non_negative(), "C_L, linear coefficient [-]");
    ph.artificial_viscosity.quadratic =
        a->number_or("quadratic", 2.0, Range::non_negative(), "C_0, quadratic coefficient [-]");
    a->reject_unknown_keys();
  }
  ph.create_new_particles = r.boolean_or("create_new_particles", false,
                                         "move failed particles to a companion velocity field");
  ph.on_numerical_fault =
      r.choice("on_numerical_fault", {"stop", "fail_particle"},
               "what a particle's numerical fault does: stop the run, or flag the particle failed "
               "and go on",
               "stop") == "fail_particle"
          ? NumericalFaultAction::fail_particle
          : NumericalFaultAction::stop;
  if (r.has("erosion")) {
    const std::string e =
        r.choice("erosion", {"none", "AllowNoTension", "KeepStress", "ZeroStress"},
                 "erosion algorithm for every material", "none");
    ph.erosion = erosion_from_name(e);
  }
  if (r.has("do_melting")) {
    ph.do_melting = r.boolean_or("do_melting", true, "remove the deviator of melted particles");
  }
  if (r.has("turn_on_adiabatic_heating")) {
    ph.adiabatic_heating =
        r.boolean_or("turn_on_adiabatic_heating", true, "heat particles by plastic work");
  }
  // Absent, each material keeps its own file's choice: no one default value. The catalogue of
  // keys is shared by every read (mpm keys read the sample scene five times): added once.
  for (const char* key : {"erosion", "do_melting", "turn_on_adiabatic_heating"}) {
    r.amend_description(key, [](KeyDescription& d) {
      constexpr std::string_view kNote = " (absent: each material file's own choice)";
      d.default_value = std::string(kComputedDefault);
      if (d.meaning.find(kNote) == std::string::npos) d.meaning += kNote;
    });
  }
  r.reject_unknown_keys();
}

// The scene's physics flags override every material's own choice (the report set them once, in
// its <MPM> block, for all materials).
void apply_physics_overrides(const PhysicsSpec& ph, std::vector<SceneMaterial>& materials) {
  for (SceneMaterial& m : materials) {
    if (m.material.model.hyperelastic()) continue;  // no erosion, melting or heating to switch
    ElasticPlasticParams p = m.material.model.params();
    if (ph.erosion) p.erosion = *ph.erosion;
    if (ph.do_melting) p.melting.do_melting = *ph.do_melting;
    if (ph.adiabatic_heating) p.heating.enabled = *ph.adiabatic_heating;
    m.material.model = ElasticPlastic(p);
  }
}

}  // namespace impact::mpm::scene_input
