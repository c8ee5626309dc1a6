// The checks across a scene's blocks: objects inside the grid, a 2D scene's bodies, the
// velocity fields, contact within one material.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include "mpm/input/block_readers.hpp"
#include "mpm/input/scene_keys.hpp"
#include "mpm/scene/face_motion.hpp"
#include "mpm/scene/grid_coverage.hpp"
#include "mpm/scene/grid_geometry.hpp"
#include "mpm/scene/initial_fields.hpp"
#include "mpm/scene/object_overlap.hpp"
#include "mpm/scene/seed_points.hpp"

namespace impact::mpm::scene_input {

namespace {

std::string vec_text(const Vec3& v) {
  std::ostringstream o;
  o.precision(4);
  o << '[' << v(0) << ", " << v(1) << ", " << v(2) << ']';
  return o.str();
}

// Whether an object's material is the one its scene names: read_objects leaves an unknown
// material, or one that failed to load, at index 0 (another material), with a problem of its
// own; a check comparing objects' materials must not read that index as a shared material.
bool material_resolved(const Scene& s, const SceneObject& o) {
  if (std::size_t(o.material) >= s.materials.size() || !s.resolved.is_object()) return false;
  const auto objects = s.resolved.find("objects");
  if (objects == s.resolved.end() || !objects->is_object()) return false;
  const auto object = objects->find(o.name);
  if (object == objects->end() || !object->is_object()) return false;
  const auto named = object->find("material");
  return named != object->end() && named->is_string() &&
         named->get<std::string>() == s.materials[std::size_t(o.material)].name;
}

}  // namespace

// Below this fraction of its volume inside the grid a body is refused: a length typed in mm
// makes a body 1e9 times too large (mpm check measured a volume ratio of 1.9e-9), and a scene
// that means to seed a thousandth of a body should give the body the size it means.
constexpr double kMinInside = 1e-3;
// Above this fraction lost beyond the grid (not mirrored by a symmetric face) a body is warned
// about; below it the loss is within the seeding's own staircase (volume ratios 0.97-1.03 on the
// shipped scenes) and the coverage lattice's resolution.
constexpr double kMaxSilentLoss = 0.01;

// Every object must lie in the grid: one wholly or almost wholly outside (no particle, or a
// body typed in mm on a grid in m) is refused, one the grid clips is warned about. The checks are
// on the whole scene, so every rank of a run finds the same.
void check_objects_in_grid(InputProblems& problems, const Scene& s) {
  const GridSpec& g = s.grid;
  // A 2D grid as it was typed, [x, y] (its z extent is the reader's, scene/grid_geometry.hpp).
  const auto corner = [&](const Vec3& v) {
    if (!g.planar()) return vec_text(v);
    std::ostringstream o;
    o.precision(4);
    o << '[' << v(0) << ", " << v(1) << ']';
    return o.str();
  };
  const std::string grid_text = corner(g.lower) + " to " + corner(g.upper) + " m";
  for (std::size_t oi = 0; oi < s.objects.size(); ++oi) {
    const SceneObject& o = s.objects[oi];
    const std::string key = "/objects/" + pointer_token(o.name) + "/geometry";
    const auto [lo, hi] = bounds(o.geometry);
    const std::string box_text = "its bounding box " + vec_text(lo) + " to " + vec_text(hi) + " m";
    const GridCoverage c = grid_coverage(o.geometry, g);
    std::ostringstream m;
    m.precision(3);
    if (c.disjoint || (c.sampled && c.inside == 0.0 && c.inside_bound >= kMinInside)) {
      m << "lies wholly outside the grid " << grid_text << " (" << box_text
        << "): no particle would be seeded; expected a body inside the grid";
      problems.add(key, m.str());
      continue;
    }
    // The bound is exact; the lattice may miss a sliver inside a body much larger than the grid.
    const bool bounded = c.inside_bound < kMinInside;
    if (bounded || (c.sampled && c.inside < kMinInside)) {
      const double share = bounded ? c.inside_bound : c.inside;
      m << (bounded ? "at most " : "only about ");
      if (share > 0.0) {
        m << share;
      } else {  // below the doubles: a body of 1e300 m
        m << "a share below 1e-300";
      }
      const double v = volume(o.geometry);
      m << " of its volume (";
      if (std::isfinite(v)) {
        m << v;
      } else {
        m << "beyond 1.8e+308";
      }
      m << " m^3) lies inside the grid " << grid_text << " (" << box_text << "); expected at least "
        << kMinInside << " (lengths in m";
      if (auto hint = unit_hint(Quantity::length, (hi - lo).maxCoeff()))
        m << "; its largest extent " << *hint;
      m << ')';
      problems.add(key, m.str());
      continue;
    }
    if (!seeds_a_point(s, oi)) {
      const Vec3 spacing = g.smallest_cell().cwiseQuotient(
          Vec3(o.particles_per_cell[0], o.particles_per_cell[1], o.particles_per_cell[2]));
      m << "no particle would be seeded: none of the seed points (sub-cell centres, spacing "
        << vec_text(spacing) << " m) lies inside it and outside every earlier object (" << box_text
        << "); expected a body larger than the seed spacing (refine grid.cells or "
        << "particles_per_cell)";
      problems.add(key, m.str());
      continue;
    }
    if (c.lost > kMaxSilentLoss) {
      std::string faces;
      for (std::size_t f = 0; f < 6; ++f)
        if (c.lost_through[f]) faces += (faces.empty() ? "" : ", ") + std::string(kFaceNames[f]);
      m << "clipped by the grid: about " << c.inside << " of its volume lies inside the grid "
        << grid_text << "; " << c.lost << " lies beyond the face(s) " << faces
        << " and is not seeded (" << box_text << "); the part inside is used as given";
      problems.warn(key, m.str());
    }
    // A body placed into an earlier one loses the shared part to it (seed_points.hpp): warned as
    // a clip by the grid is.
    const ObjectOverlap overlap = object_overlap(s, oi);
    // A deformable body that keeps part of a rigid one would sit embedded in it for ever (the
    // rigid body never deforms nor pushes it out): refused. Named the other way round, the
    // deformable body loses the shared part and is warned about, as any overlap.
    std::string embedded;
    for (const std::size_t a : overlap.by)
      if (o.rigid && !s.objects[a].rigid) embedded = s.objects[a].name;
    if (overlap.claimed > kMaxSilentLoss && !embedded.empty()) {
      std::ostringstream e;
      e.precision(3);
      e << "a rigid object overlaps the earlier deformable object \"" << embedded << "\": about "
        << overlap.claimed
        << " of its volume lies inside it, and that part of the deformable body would stay "
           "embedded in the rigid one (a point inside an earlier object, in alphabetical order of "
           "the names, belongs to that object); expected bodies that do not overlap";
      problems.add(key, e.str());
      continue;
    }
    if (overlap.claimed > kMaxSilentLoss) {
      std::ostringstream w;
      w.precision(3);
      w << "overlaps the earlier object" << (overlap.by.size() > 1 ? "s " : " ");
      for (std::size_t a = 0; a < overlap.by.size(); ++a)
        w << (a ? ", " : "") << '"' << s.objects[overlap.by[a]].name << '"';
      w << ": about " << overlap.claimed << " of its volume lies inside "
        << (overlap.by.size() > 1 ? "them" : "it")
        << " and is not seeded (a point inside an earlier object, in alphabetical order of the "
           "names, belongs to that object); expected bodies that do not overlap, or names "
           "that put first the body that should keep the shared part";
      problems.warn(key, w.str());
    }
  }
}

// What a field's varying part may do on grid G (appended to the refusal of a uniform part).
template <class G>
std::string varying_part_note() {
  if constexpr (G::kRings)  // a body of revolution
    return " (a radial component may be an expression of X and Y that vanishes on the axis, a "
           "field of revolution)";
  return "";
}

// Every body must have its grid's form (scene/grid_geometry.hpp form_problem: on a 2D grid the
// 2D form, mpm/scene/planar_form.hpp) and move as the grid models: along the axis when
// axisymmetric (a uniform radial velocity is no body of revolution's), with no z component in
// plane strain; gravity likewise. A 2D grid has one cell and one box along z.
void check_planar_scene(InputProblems& problems, Scene& s) {
  visit_geometry(s.grid.geometry, [&](auto geometry) {
    using Grid = decltype(geometry);
    const std::string grid = "grid.geometry \"" + std::string(Grid::kName) + "\"";
    const std::string expected(Grid::kExpectedMotion);
    for (SceneObject& o : s.objects) {
      const std::string key = "/objects/" + pointer_token(o.name);
      const std::string why = Grid::form_problem(o.geometry);
      if (!why.empty()) problems.add(key + "/geometry", why + " (" + grid + ")");
      // The uniform part of a field (numbers, and texts without a variable) must move the body as
      // the grid models; a part that varies may be radial on an axisymmetric grid (a field of
      // revolution, which vanishes on the axis), never along z on a 2D grid.
      const Vec3 v = o.velocity_field.uniform_part(s.constants);
      if (Grid::kMeshAxes < 3 && !o.velocity_field.text[2].empty())
        problems.add(key + "/velocity/2",
                     "no expression along z on " + grid + " (a 2D grid has no motion along z)");
      if (!Grid::moves_in_model(v))
        problems.add(key + "/velocity", "initial velocity " + vec_text(v) + " on " + grid + ": " +
                                            expected + varying_part_note<Grid>());
      const VectorExpression& b = o.body_force;
      if (Grid::kMeshAxes < 3 && !b.text[2].empty())
        problems.add(key + "/body_force/2",
                     "no expression along z on " + grid + " (a 2D grid has no motion along z)");
      const Vec3 uniform = b.uniform_part(s.constants);
      if (!Grid::moves_in_model(uniform))
        problems.add(key + "/body_force", "body force " + vec_text(uniform) + " on " + grid + ": " +
                                              expected + varying_part_note<Grid>());
      if constexpr (Grid::kMeshAxes < 3) o.particles_per_cell[2] = 1;  // the one cell along z
    }
    // The exact displacement likewise: its z component is the particles' z motion, 0 on a 2D grid.
    if constexpr (Grid::kMeshAxes < 3)
      if (const auto& u = s.output.exact_displacement;
          u && (!u->text[2].empty() || u->uniform_part(s.constants)(2) != 0.0))
        problems.add("/output/exact_displacement/2",
                     "expected 0 on " + grid + " (a 2D grid has no motion along z)");
    if (!Grid::moves_in_model(s.solver.gravity))
      problems.add("/solver/gravity",
                   "gravity " + vec_text(s.solver.gravity) + " on " + grid + ": " + expected);
    if constexpr (Grid::kMeshAxes < 3)
      if (s.solver.ranks_per_axis[2] > 1)
        problems.add("/solver/ranks_per_axis",
                     "a 2D grid is split in x and y only; expected [px, py] (" + grid + ")");
  });
}

void check_initial_fields(InputProblems& problems, Scene& s) {
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    SceneObject& o = s.objects[i];
    // A body force of numbers is its own peak (the scaled norm: 1e160 squares beyond a double).
    if (!o.body_force.has_text()) o.initial_body_force_peak = o.body_force.value.stableNorm();
    if (!o.velocity_field.has_text() && !o.body_force.has_text()) continue;
    const InitialFields f = initial_fields(s, i);
    const std::string key = "/objects/" + pointer_token(o.name);
    if (f.non_finite_velocity)
      problems.add(key + "/velocity", "not finite at the seed point X = " +
                                          vec_text(*f.non_finite_velocity) + " m (t = 0)");
    if (f.non_finite_body_force)
      problems.add(key + "/body_force", "not finite at the seed point X = " +
                                            vec_text(*f.non_finite_body_force) + " m at t = 0");
    if (o.velocity_field.has_text()) {
      o.velocity = f.velocity_peak;
      for (int d = 0; d < 3; ++d)
        if (!o.velocity_field.text[std::size_t(d)].empty())
          problems.check_units(key + "/velocity/" + std::to_string(d), Quantity::speed,
                               f.velocity_peak(d));
    }
    o.initial_body_force_peak = f.body_force_peak;
  }
}

// A speed at or above light's is no impact speed: it is a slip (a unit, an exponent). Refused by
// its key rather than left to the step estimate, which read 1e300 m/s as an infinite speed.
void check_object_speeds(InputProblems& problems, const Scene& s) {
  constexpr double kSpeedOfLight = 299792458.0;  // m/s, exact (SI definition of the metre)
  for (const SceneObject& o : s.objects) {
    if (o.velocity.norm() < kSpeedOfLight) continue;  // a norm that overflows is inf: refused
    std::ostringstream m;
    m.precision(4);
    m << "expected a speed below that of light (2.998e8 m/s), got " << vec_text(o.velocity)
      << " m/s" << (o.velocity_field.has_text() ? " at its fastest seed point" : "");
    problems.add("/objects/" + pointer_token(o.name) + "/velocity", m.str());
  }
}

// A rigid object keeps its velocity: where that carries its body to a face of the grid before
// time.max_time, its particles leave and stop the run (grid.outflow "stop") at a time known now;
// a `wall` does not hold it (grid/wall.cpp), so one driven into a wall went through it and the
// run stopped at step 10 after `mpm check` had passed it. Measured on the geometry's bounding box
// (within the grid), so it errs early by at most a particle's half-width over the speed.
void check_rigid_object_stays_in_grid(InputProblems& problems, const Scene& s, const SceneObject& o,
                                      const std::string& key) {
  if (s.grid.outflow != Outflow::stop || o.velocity_field.has_text() || o.velocity.isZero(0.0))
    return;
  const GridSpec& g = s.grid;
  const auto [lo, hi] = bounds(o.geometry);
  double first = std::numeric_limits<double>::infinity();
  int face = -1;
  for (int d = 0; d < (g.planar() ? 2 : 3); ++d) {
    const double v = o.velocity(d);
    if (v == 0.0) continue;
    const double t = v > 0.0 ? (g.upper(d) - std::min(hi(d), g.upper(d))) / v
                             : (std::max(lo(d), g.lower(d)) - g.lower(d)) / -v;
    if (t < first) {
      first = t;
      face = 2 * d + (v > 0.0 ? 1 : 0);
    }
  }
  if (!(first < s.time.max_time)) return;
  std::ostringstream m;
  m.precision(4);
  m << "a rigid object keeps its velocity " << vec_text(o.velocity) << " m/s, and it carries its "
    << "body to the grid's " << kFaceNames[face] << " face at t = " << first
    << " s, before time.max_time = " << s.time.max_time
    << " s: its particles would leave the grid and stop the run (a wall does not hold a rigid "
       "object); expected a velocity or a time.max_time that keeps it inside, or grid.outflow "
       "\"remove\"";
  problems.add(key + "/velocity", m.str());
}

// A rigid object (SceneObject::rigid) is a velocity field held at one velocity: it needs fields of
// its own (multi-field contact, a material no deformable body shares) and numbers for that
// velocity; a body force on it would do nothing. Rigid bodies alone compute nothing: no wave,
// no contact, a time step of time.max_time (the run completed in one step).
void check_rigid_objects(InputProblems& problems, const Scene& s) {
  if (!s.objects.empty() &&
      std::all_of(s.objects.begin(), s.objects.end(), [](const SceneObject& o) { return o.rigid; }))
    problems.add("/objects",
                 "every object is rigid: expected at least one deformable object "
                 "(rigid objects move at their velocity and, alone, leave nothing "
                 "to compute)");
  // The particles' contact with rigid objects (contact/rigid_particle_contact.hpp).
  // (Under single_velocity its keys are refused where they are read.)
  if (s.physics.contact.type == ContactType::friction &&
      s.physics.contact.rigid == RigidContact::particles) {
    if (!s.has_rigid_objects())
      problems.add("/physics/contact/rigid_contact",
                   "\"particles\" is how bodies meet rigid objects, and no object is rigid: "
                   "remove the key, or make an object rigid (objects.<name>.rigid)");
    // There a rigid object is its geometry's exact surface: one that an earlier object of another
    // body cuts is seeded without the cut part, and its surface would be none of its own.
    for (std::size_t oi = 0; oi < s.objects.size(); ++oi) {
      const SceneObject& o = s.objects[oi];
      if (!o.rigid || !material_resolved(s, o)) continue;
      for (const std::size_t a : object_overlap(s, oi).by) {
        const SceneObject& by = s.objects[a];
        if (!material_resolved(s, by) || s.parent_field(by.material) == s.parent_field(o.material))
          continue;
        problems.add("/objects/" + pointer_token(o.name) + "/geometry",
                     "the earlier object \"" + by.name +
                         "\" cuts this rigid object, which the contact at the particles "
                         "(rigid_contact \"particles\") meets as its geometry's whole surface: "
                         "place the objects apart, or use rigid_contact \"nodes\"");
        break;
      }
    }
  }
  for (const SceneObject& o : s.objects) {
    const std::string key = "/objects/" + pointer_token(o.name);
    if (!o.rigid && o.mu)
      problems.add(key + "/mu",
                   s.physics.contact.type == ContactType::friction
                       ? "only a rigid object takes a Coulomb coefficient of its own: between "
                         "deformable bodies physics.contact.mu acts; remove the key, or set "
                         "physics.contact.mu"
                       : "only a rigid object takes a Coulomb coefficient of its own, and "
                         "under contact \"single_velocity\" bodies share one velocity field "
                         "with no friction: remove the key");
    if (!o.rigid) continue;
    if (s.physics.contact.type == ContactType::single_velocity)
      problems.add(key + "/rigid",
                   "a rigid object meets the other bodies through multi-field contact: expected "
                   "physics.contact.type \"friction\" (under \"single_velocity\" every body "
                   "shares one velocity field)");
    if (o.velocity_field.has_text())
      problems.add(key + "/velocity",
                   "a rigid object moves at one velocity for ever: expected three numbers [m/s], "
                   "not expressions");
    if (o.has_body_force())
      problems.add(key + "/body_force",
                   "a rigid object keeps its velocity, so a body force would not act on it: "
                   "remove the key");
    check_rigid_object_stays_in_grid(problems, s, o, key);
    if (!material_resolved(s, o)) continue;  // its own problem already
    for (const SceneObject& other : s.objects) {
      if (&other == &o || other.material != o.material || !material_resolved(s, other)) continue;
      if (other.rigid && other.velocity == o.velocity && !other.velocity_field.has_text()) {
        // One material's rigid objects are one velocity field: one Coulomb coefficient.
        const double mu = s.friction_of(o), other_mu = s.friction_of(other);
        if (mu != other_mu && &other < &o) {
          const auto whence = [](const SceneObject& x) {
            return x.mu ? "" : " (physics.contact.mu)";
          };
          // Named at a mu that is written (an inherited one has no key of its own to point at):
          // this object's, else the other's, whose message then speaks of this one.
          const SceneObject& here = o.mu ? o : other;
          const SceneObject& there = o.mu ? other : o;
          std::ostringstream m;
          m << "object \"" << there.name << "\" of material \""
            << s.materials[std::size_t(o.material)].name << "\" meets the bodies with mu "
            << s.friction_of(there) << whence(there) << ", this one with " << s.friction_of(here)
            << whence(here)
            << ": a material's rigid objects are one body; expected one mu for them, or a "
               "material each";
          problems.add("/objects/" + pointer_token(here.name) + "/mu", m.str());
        }
        continue;
      }
      problems.add(key + "/material",
                   "material \"" + s.materials[std::size_t(o.material)].name +
                       "\" is also that of object \"" + other.name + "\", which " +
                       (other.rigid ? "moves at another velocity" : "is not rigid") +
                       ": a material's particles share one velocity field; give the rigid "
                       "object a material of its own (the same file under another name)");
      break;
    }
  }
}

// Multi-field contact keeps per-node arrays of kMaxContactFields fields (contact.cpp): a scene
// with more velocity fields is refused here rather than have the rest ignored.
void check_field_count(InputProblems& problems, const Scene& s) {
  const int fields = s.field_count();
  if (fields <= kMaxContactFields) return;
  const bool conversion = s.physics.create_new_particles;
  std::ostringstream m;
  m << s.materials.size() << " materials make " << fields << " velocity fields"
    << (conversion ? " (each with a companion field: physics.create_new_particles)" : "")
    << " under physics.contact.type \""
    << (s.physics.contact.type == ContactType::friction ? "friction" : "approach")
    << "\": expected at most " << kMaxContactFields << " fields ("
    << (conversion ? kMaxContactFields / 2 : kMaxContactFields)
    << " materials), or contact \"single_velocity\" (one field)";
  problems.add("/materials", m.str());
}

// Contact separates materials, not objects (a material's particles share one velocity field): two
// objects of one material meet as one body, as with single_velocity. Valid, and what a scene of
// one body cut into objects wants, but a user who set friction between them gets no contact.
void warn_of_contact_within_one_material(Scene& s) {
  if (s.physics.contact.type != ContactType::friction || s.physics.create_new_particles ||
      s.objects.size() < 2)
    return;
  for (const SceneObject& o : s.objects)
    if (o.material != s.objects.front().material) return;
  s.warnings.push_back(
      "/physics/contact: \"friction\" acts between materials, and every object here is of "
      "material \"" +
      s.materials[s.objects.front().material].name +
      "\": they share one velocity field and meet as one body, as with \"single_velocity\"; "
      "give each body its own material (the same file under another name) for contact between "
      "them");
}

// physics.erosion, do_melting and turn_on_adiabatic_heating switch the elastic-plastic models'
// damage, melting and heating (apply_physics_overrides); a hyperelastic law has none of them, so
// on a scene of neo-Hookean solids alone the keys do nothing. Valid (a scene may change its
// materials and keep its physics block), but a user who set them expects them to act.
void warn_of_physics_no_material_uses(Scene& s) {
  const bool set = s.physics.erosion || s.physics.do_melting || s.physics.adiabatic_heating;
  if (!set || s.materials.empty()) return;
  for (const SceneMaterial& m : s.materials)
    if (!m.material.model.hyperelastic()) return;
  std::string keys;
  int count = 0;
  const auto add = [&](bool on, const char* key) {
    if (!on) return;
    keys += (keys.empty() ? "/physics/" : ", /physics/") + std::string(key);
    ++count;
  };
  add(s.physics.erosion.has_value(), "erosion");
  add(s.physics.do_melting.has_value(), "do_melting");
  add(s.physics.adiabatic_heating.has_value(), "turn_on_adiabatic_heating");
  s.warnings.push_back(s.file + ": " + keys +
                       ": every material here is hyperelastic (constitutive_model.type "
                       "\"neo_hookean\"), which has no erosion, melting or heating: " +
                       (count == 1 ? "the key does" : "the keys do") + " nothing (docs/models.md)");
}

void check_face_velocities(InputProblems& problems, const Scene& s) {
  const std::size_t before = problems.count();
  for (int f = 0; f < 6; ++f) {
    const FaceMotion& m = s.grid.face_velocity[f];
    if (m.text.empty()) continue;
    const std::string key = std::string("/grid/face_velocity/") + kFaceNames[f];
    if (const auto problem = check_expression(m.text, s.constants)) {
      problems.add(key, expression_problem_message(m.text, *problem));
      continue;
    }
    VectorExpression e;
    e.text[0] = m.text;
    bool of_t = true;
    for (const char* x : {"X", "Y", "Z"})
      if (e.uses(x, s.constants)) {
        problems.add(key, "expression \"" + m.text + "\" reads " + x +
                              ": a face moves as a whole, its velocity is a function of t alone");
        of_t = false;
      }
    if (!of_t) continue;
  }
  if (problems.count() > before) return;
  // Finite over the run, at the 1001 times the travel is measured at (numbers included: 1e400
  // reads as inf).
  const FaceTravel travel = face_travel(s.grid, s.constants, s.time.max_time);
  for (int f = 0; f < 6; ++f)
    if (s.grid.face_velocity[f].set && travel.non_finite_at[f]) {
      std::ostringstream m;
      m << "not finite at t = " << *travel.non_finite_at[f] << " s";
      problems.add(std::string("/grid/face_velocity/") + kFaceNames[f], m.str());
    }
}

void warn_of_face_travel(Scene& s) {
  const FaceTravel travel = face_travel(s.grid, s.constants, s.time.max_time);
  for (int f = 0; f < 6; ++f) {
    if (!s.grid.face_velocity[f].set) continue;
    const int axis = f / 2;
    Vec3 h = Vec3::Zero();  // the cell at the face
    h(axis) = s.grid.cell_size(axis, f % 2 == 0 ? 0 : s.grid.cells[axis] - 1);
    const std::string key = s.file + ": /grid/face_velocity/" + kFaceNames[f] + ": ";
    std::ostringstream m;
    if (travel.largest[f] > 0.25 * h(axis)) {
      m << key << "the face travels up to " << travel.largest[f]
        << " m by time.max_time, more than a quarter of its cell (" << 0.25 * h(axis) << " m of "
        << h(axis)
        << " m): the mirror plane stays at its grid position, so the material it drives leaves "
           "the face's layer beyond that (docs/scenes.md#moving-faces)";
      s.warnings.push_back(m.str());
      m.str("");
    }
    // Pulling: the material follows the face out of the grid once it has moved beyond its first
    // row of particles, h / (2 ppc) from the face.
    int ppc = 1;
    for (const SceneObject& o : s.objects) ppc = std::max(ppc, o.particles_per_cell[axis]);
    const double first_row = h(axis) / (2.0 * ppc);
    if (travel.outward[f] > first_row) {
      m << key << "the face moves outward by up to " << travel.outward[f]
        << " m by time.max_time, beyond the first row of particles (" << first_row
        << " m from the face at " << ppc
        << " particles per cell): the material it pulls leaves the grid there";
      s.warnings.push_back(m.str());
      m.str("");
    }
    if (travel.initial[f] != 0.0) {
      m << key << "the face starts at " << travel.initial[f]
        << " m/s: the particles take that jump through the stress over the first steps (their "
           "velocities lag the face, and energy_error shows a start-up residual of a few "
           "percent of 1/2 M V^2 over them, M the deformable bodies' mass); a ramp such as "
           "min(t/t_r,1)*V from 0 avoids it "
           "(docs/scenes.md#moving-faces)";
      s.warnings.push_back(m.str());
    }
  }
}

}  // namespace impact::mpm::scene_input
