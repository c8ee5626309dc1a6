// The scene's grid block: bounds, cells, geometry, faces (docs/scenes.md#grid); a 2D grid's
// [x, y] arrays completed to the 3D ones they stand for.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include "mpm/input/block_readers.hpp"
#include "mpm/input/scene_keys.hpp"
#include "mpm/shape/shape.hpp"

namespace impact::mpm::scene_input {

std::array<int, 3> read_int3(JsonReader& r, const Json& node, std::string_view key, int lo, int hi,
                             std::string_view meaning, std::optional<std::array<int, 3>> fallback) {
  const Vec3 v =
      read_vec3(r, node, key, meaning,
                fallback ? std::optional<Vec3>(Vec3((*fallback)[0], (*fallback)[1], (*fallback)[2]))
                         : std::nullopt);
  r.amend_description(key, [&](KeyDescription& d) {
    d.type = "[3 integers]";
    d.range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  });
  std::array<int, 3> out{};
  for (int d = 0; d < 3; ++d) {
    if (!(v(d) >= lo && v(d) <= hi && v(d) == std::floor(v(d)))) {
      if (!std::isnan(v(d))) {
        r.problems().add(r.key_path(key), "expected integers in [" + std::to_string(lo) + ", " +
                                              std::to_string(hi) + "] (" + std::string(meaning) +
                                              ")");
      }
      return fallback.value_or(std::array<int, 3>{1, 1, 1});
    }
    out[d] = static_cast<int>(v(d));
  }
  return out;
}

namespace {

// The grid geometry the document asks for (grid.geometry, validated by read_grid; an unknown
// value reads as 3d here).
GridGeometry document_geometry(const Json& doc) {
  const Json& g = at(at(doc, "grid"), "geometry");
  if (g.is_string())
    if (const auto named = geometry_named(g.get<std::string>())) return *named;
  return kDefaultGeometry;
}

}  // namespace

// A 2D grid is written in its plane: grid.lower, grid.upper and grid.cells take [x, y], as do
// objects' particles_per_cell and solver.ranks_per_axis. They are read as the 3D grid of one
// cell of 1 m along z, centred on z = 0 (scene/grid_geometry.hpp): this completes each [x, y]
// with its z value, and refuses three numbers where two are expected. Every other vector (the
// objects' geometry, velocities, gauge regions) stays 3D: the bodies are the 3D twin's.
Json with_plane_arrays_completed(const Json& doc, InputProblems& problems) {
  if (!facts(document_geometry(doc)).planar()) return doc;
  Json out = doc;
  const auto complete = [&](Json& node, const std::string& path, const char* key, double z) {
    if (!node.is_object() || !node.contains(key) || !node[key].is_array()) return;
    Json& a = node[key];
    if (a.size() == 2) {
      a.push_back(z);
    } else if (a.size() == 3) {
      problems.add(path + "/" + key,
                   "expected an array of 2 numbers [x, y] on a 2D grid "
                   "(grid.geometry \"" +
                       at(doc["grid"], "geometry").get<std::string>() + "\"), got " + a.dump());
      a[2] = z;  // read on, so that the other problems show too
    }
  };
  Json& grid = out["grid"];
  complete(grid, "/grid", "lower", -0.5);
  complete(grid, "/grid", "upper", 0.5);
  complete(grid, "/grid", "cells", 1);
  if (grid.contains("refine") && grid["refine"].is_object()) {
    complete(grid["refine"], "/grid/refine", "lower", -0.5);
    complete(grid["refine"], "/grid/refine", "upper", 0.5);
  }
  if (grid.contains("refine") && grid["refine"].is_array())
    for (std::size_t i = 0; i < grid["refine"].size(); ++i) {
      const std::string path = "/grid/refine/" + std::to_string(i);
      complete(grid["refine"][i], path, "lower", -0.5);
      complete(grid["refine"][i], path, "upper", 0.5);
    }
  if (out.contains("solver") && out["solver"].is_object()) {
    // [0, 0] is the automatic split ([0, 0, 0]); any other [px, py] has one box along z.
    const Json& p =
        out["solver"].contains("ranks_per_axis") ? out["solver"]["ranks_per_axis"] : Json();
    const bool automatic = p.is_array() && p.size() == 2 && p[0] == 0 && p[1] == 0;
    complete(out["solver"], "/solver", "ranks_per_axis", automatic ? 0.0 : 1.0);
  }
  if (out.contains("objects") && out["objects"].is_object())
    for (auto& item : out["objects"].items())
      complete(item.value(), "/objects/" + pointer_token(item.key()), "particles_per_cell", 1);
  // Positions in the plane may be written [x, y] too (the particles lie at z = 0); [x, y, z]
  // stays valid for them, as for the bodies.
  const auto position = [](Json& node, const char* key) {
    if (node.is_object() && node.contains(key) && node[key].is_array() && node[key].size() == 2)
      node[key].push_back(0.0);
  };
  if (out.contains("output") && out["output"].is_object()) {
    Json& output = out["output"];
    if (output.contains("gauges") && output["gauges"].is_object())
      for (auto& item : output["gauges"].items())
        if (item.value().is_object() && item.value().contains("region")) {
          position(item.value()["region"], "lower");
          position(item.value()["region"], "upper");
        }
    if (output.contains("particle_paths") && output["particle_paths"].is_object())
      for (auto& item : output["particle_paths"].items()) position(item.value(), "position");
  }
  return out;
}

namespace {

// A 2D grid's z faces, named under grid.boundary or grid.wall_friction.
std::string no_face_along_z(const std::string& geometry) {
  return "a 2D grid (grid.geometry \"" + geometry +
         "\") has no face along z; expected faces x-, x+, y- and y+ only";
}

// grid.boundary, grid.face_velocity and grid.wall_friction: the condition of each face the geometry
// reads (the rest, a 2D grid's z faces, are free), its axis face a mirror, a velocity only on a
// mirror, friction only on a wall.
void read_faces(JsonReader& r, const Json& grid, GridSpec& g, const std::string& geometry) {
  g.faces.fill(FaceCondition::symmetric);
  // A 2D grid has no faces along z (its one cell of 1 m is not a mesh axis): they are free.
  const int faces = g.geometry_facts().faces_read, axis_face = g.geometry_facts().axis_face;
  for (int f = faces; f < 6; ++f) g.faces[f] = FaceCondition::free;
  if (auto b = r.optional_child("boundary", "condition per face: symmetric, fixed, free or wall")) {
    for (int f = faces; f < 6; ++f)
      if (b->has(kFaceNames[f])) {
        b->problems().add(b->key_path(kFaceNames[f]), no_face_along_z(geometry));
        b->ignore(kFaceNames[f]);
      }
    for (int f = 0; f < faces; ++f) {
      const std::string c = b->choice(kFaceNames[f], {"symmetric", "fixed", "free", "wall"},
                                      "grid face condition (symmetric: frictionless mirror plane; "
                                      "wall: rigid wall that never pulls, with friction)",
                                      "symmetric");
      g.faces[f] = c == "fixed"  ? FaceCondition::fixed
                   : c == "free" ? FaceCondition::free
                   : c == "wall" ? FaceCondition::wall
                                 : FaceCondition::symmetric;
      if (f == axis_face && c != "symmetric")
        b->problems().add(b->key_path(kFaceNames[f]),
                          "the face y- of an axisymmetric grid is the axis of symmetry, where the "
                          "radial velocity is zero: expected \"symmetric\", got \"" +
                              c + "\"");
    }
    b->reject_unknown_keys();
  }
  // grid.face_velocity: a moving mirror plane (a frictionless piston, a load curve); its
  // expressions are checked with the constants (check_face_velocities).
  if (auto v = r.optional_child("face_velocity",
                                "velocity along its axis of a moving symmetric face [m/s]: a "
                                "number or an expression of t")) {
    const Json& block = at(grid, "face_velocity");
    for (int f = 0; f < 6; ++f) {
      if (!v->has(kFaceNames[f])) {  // a known name all the same: "X-" gets "did you mean x-?"
        v->ignore(kFaceNames[f]);
        continue;
      }
      const std::string key = v->key_path(kFaceNames[f]);
      const Json& value = block[kFaceNames[f]];
      v->read_elsewhere(kFaceNames[f], [] {
        return KeyDescription{"number or expression of t", "", "",
                              "velocity of a symmetric face along its axis, positive toward "
                              "+axis (docs/scenes.md#moving-faces)"};
      });
      if (f >= faces) {
        v->problems().add(key, no_face_along_z(geometry));
      } else if (f == axis_face) {
        v->problems().add(key, "the face y- of an axisymmetric grid is the axis: it cannot move");
      } else if (g.faces[f] != FaceCondition::symmetric) {
        v->problems().add(key, std::string("face ") + kFaceNames[f] +
                                   " is not symmetric: a face moves as a mirror plane, so its "
                                   "grid.boundary." +
                                   kFaceNames[f] + " must be \"symmetric\"");
      } else if (value.is_string() && value.get<std::string>().empty()) {
        v->problems().add(key, "expected a number or an expression of t, got an empty string");
      } else if (value.is_number()) {
        g.face_velocity[f] = {"", value.get<double>(), true};
      } else if (value.is_string()) {
        g.face_velocity[f] = {value.get<std::string>(), 0.0, true};
      } else {
        v->problems().add(
            key, "expected a number or an expression of t (a string) [m/s], got " + value.dump());
      }
    }
    v->reject_unknown_keys();
  }
  if (auto w = r.optional_child("wall_friction", "Coulomb friction coefficient per wall face")) {
    for (int f = 0; f < 6; ++f) {
      if (!w->has(kFaceNames[f])) {  // a known name all the same: "X-" gets "did you mean x-?"
        w->ignore(kFaceNames[f]);
        continue;
      }
      if (f >= faces) {  // a 2D grid: the face along z does not exist
        w->problems().add(w->key_path(kFaceNames[f]), no_face_along_z(geometry));
        w->ignore(kFaceNames[f]);
        continue;
      }
      if (g.faces[f] != FaceCondition::wall) {
        w->problems().add(w->key_path(kFaceNames[f]),
                          std::string("face ") + kFaceNames[f] +
                              " is not a wall: friction acts only on a face whose "
                              "grid.boundary." +
                              kFaceNames[f] + " is \"wall\"");
        w->ignore(kFaceNames[f]);  // reported above, not also as an unknown key
        continue;
      }
      g.wall_friction[f] =
          w->number(kFaceNames[f], Range::closed(0.0, 10.0), "Coulomb coefficient mu [-]");
      w->amend_description(kFaceNames[f], [](KeyDescription& d) { d.default_value = "0"; });
    }
    w->reject_unknown_keys();
  }
  // How the walls meet the bodies: at their face nodes (grid/wall.cpp) or at the particles, by
  // the penalty against each wall's plane (contact/rigid_particle_contact.hpp).
  const std::string wall_contact =
      r.choice("wall_contact", {"nodes", "particles"},
               "where the wall faces meet the bodies: at the face nodes, or at the particles, by a "
               "penalty against the face's plane (with Coulomb friction wall_friction)",
               "nodes");
  g.wall_contact = wall_contact == "particles" ? WallContact::particles : WallContact::nodes;
  if (r.has("wall_contact") && !g.has_walls())
    r.problems().add(r.key_path("wall_contact"),
                     "no face is a wall: set a grid.boundary face to \"wall\", or remove the key");
  g.wall_penalty_damping = r.number_or(
      "wall_penalty_damping", 0.0, Range::closed(0.0, 0.5),
      "damping of the walls' contact at the particles, a fraction of each particle's critical "
      "damping [-]");
  if (r.has("wall_penalty_damping") && g.wall_contact != WallContact::particles)
    r.problems().add(r.key_path("wall_penalty_damping"),
                     "damps the walls' penalty at the particles only: set \"wall_contact\": "
                     "\"particles\", or remove the key");
  // A moving face beside a no-slip face or a wall with friction: their edge nodes would be held by
  // both (the fixed face zeroes the velocity the moving one imposes, or the wall's friction slows
  // it), with work booked at a velocity the nodes do not have. Refused. A wall met at the
  // particles holds no node (its friction acts on the particles), so it may be rough there.
  for (int f = 0; f < 6; ++f) {
    if (!g.face_velocity[f].set) continue;
    for (int o = 0; o < 6; ++o) {
      if (o / 2 == f / 2) continue;
      const bool fixed = g.faces[o] == FaceCondition::fixed;
      const bool rough = g.faces[o] == FaceCondition::wall && g.wall_friction[o] > 0.0 &&
                         g.wall_contact != WallContact::particles;
      if (!fixed && !rough) continue;
      r.problems().add(r.key_path("face_velocity") + "/" + kFaceNames[f],
                       std::string("the face ") + kFaceNames[o] + " beside it is " +
                           (fixed ? "fixed" : "a wall with friction") +
                           ": their edge nodes would be held by both; expected the faces beside a "
                           "moving face symmetric, free or a wall without friction, or the walls "
                           "met at the particles (grid.wall_contact \"particles\")");
    }
  }
}

// One box of grid.refine (docs/scenes.md#graded-grids), inside the grid on every mesh axis; none
// when it is invalid (reported) or refines nothing (factor 1, warned).
std::optional<GridRefinement> read_refined_box(JsonReader& f, const Json& n, const GridSpec& g,
                                               bool listed) {
  GridRefinement refine;
  refine.lower =
      read_vec3(f, n, "lower", "lower corner of the refined box [m] ([x, y] on a 2D grid)");
  refine.upper =
      read_vec3(f, n, "upper", "upper corner of the refined box [m] ([x, y] on a 2D grid)");
  refine.factor =
      f.number("factor", Range::closed(1.0, 64.0), "base cell size over the refined cell size [-]");
  refine.growth = f.number_or("growth", 1.2, Range::closed(1.05, 2.0),
                              "largest ratio of neighbouring cells outside the box [-]");
  f.reject_unknown_keys();
  const int axes = g.dimensions();
  bool valid = true;
  for (int d = 0; d < axes; ++d) {
    const double lo = refine.lower(d), hi = refine.upper(d);
    std::ostringstream m;
    if (std::isnan(lo) || std::isnan(hi)) return std::nullopt;  // reported by read_vec3
    if (!(lo < hi)) {
      m << "expected upper > lower on every axis of the grid; axis " << d << " has lower " << lo
        << " m and upper " << hi << " m";
      f.problems().add(f.key_path("upper") + "/" + std::to_string(d), m.str());
      valid = false;
    } else if (lo < g.lower(d) || hi > g.upper(d)) {
      m << "expected the refined box inside the grid [" << g.lower(d) << ", " << g.upper(d)
        << "] m along axis " << d << ", got [" << lo << ", " << hi << "] m";
      f.problems().add(f.key_path(lo < g.lower(d) ? "lower" : "upper") + "/" + std::to_string(d),
                       m.str());
      valid = false;
    } else if (const double inside =
                   (hi - lo) / (g.upper(d) - g.lower(d)) * g.cells[std::size_t(d)] * refine.factor;
               inside > 100000.0) {
      m << "the refined box would get " << inside << " cells along axis " << d
        << ": expected at most 100000 (lower factor or narrow the box)";
      f.problems().add(f.key_path("factor"), m.str());
      valid = false;
    }
  }
  if (!valid || !std::isfinite(refine.factor) || !std::isfinite(refine.growth)) return std::nullopt;
  if (refine.factor == 1.0) {  // the base cells everywhere: the uniform grid, its own path
    f.problems().warn(f.key_path("factor"),
                      listed
                          ? "factor 1 refines nothing: this box is left out of the list"
                          : "factor 1 refines nothing: the grid is the uniform one of grid.cells");
    return std::nullopt;
  }
  // A factor that does not divide the box's base cells into whole cells is rounded (the
  // refined cells are equal and end on the box's base nodes): where that moves the factor by more
  // than 5 %, say what it became, axes that came out alike together. (A ladder's levels round
  // by a few per cent: 1.5 on 17 base cells is 1.53; its h is the cells' own.)
  struct Rounded {
    std::string axes;
    double h0;
    SpanCells cells;
  };
  std::vector<Rounded> rounded;
  for (int d = 0; d < axes; ++d) {
    const auto c = span_cells(g.lower(d), g.upper(d), g.cells[std::size_t(d)],
                              RefinedSpan{refine.lower(d), refine.upper(d), refine.factor, 1.2});
    const double asked = c ? double(c->base) * refine.factor : 0.0;
    if (!c || std::abs(double(c->refined) - asked) <= 0.05 * asked) continue;
    const double h0 = (g.upper(d) - g.lower(d)) / g.cells[std::size_t(d)];
    const auto same = std::find_if(rounded.begin(), rounded.end(), [&](const Rounded& r) {
      return r.cells.base == c->base && r.cells.refined == c->refined && r.h0 == h0;
    });
    if (same != rounded.end()) {
      same->axes += ", " + std::to_string(d);
    } else {
      rounded.push_back({std::to_string(d), h0, *c});
    }
  }
  if (!rounded.empty()) {
    std::ostringstream m;
    m << "factor " << refine.factor << " does not divide the box into whole cells:";
    for (std::size_t i = 0; i < rounded.size(); ++i) {
      const auto& [along, h0, c] = rounded[i];
      m << (i ? ";" : "") << (along.size() > 1 ? " along axes " : " along axis ") << along
        << " the box covers " << c.base << " base cell" << (c.base == 1 ? "" : "s")
        << " (widened to the base nodes), " << double(c.base) * refine.factor
        << " cells rounded to " << c.refined << " of " << h0 * double(c.base) / c.refined
        << " m (a factor of " << double(c.refined) / double(c.base) << ")";
    }
    m << "; choose a factor that makes the box's base cells times it whole";
    f.problems().warn(f.key_path("factor"), m.str());
  }
  return refine;
}

// A list of boxes longer than this is more likely a generated mistake than a grid: each box
// refines whole strips of the grid along every axis.
constexpr std::size_t kMaxRefinedBoxes = 16;

// grid.refine: one box of finer cells, or a list of them; the graded axes are made from them
// (GridSpec::grade).
void read_refinement(JsonReader& r, const Json& grid, GridSpec& g) {
  if (grid.contains("refine") && grid["refine"].is_array()) {
    const Json& list = grid["refine"];
    r.ignore("refine");  // read element by element below
    if (list.empty() || list.size() > kMaxRefinedBoxes) {
      r.problems().add(r.key_path("refine"),
                       "expected one box (an object with lower, upper, factor, growth) or a list "
                       "of 1 to " +
                           std::to_string(kMaxRefinedBoxes) + " of them, got a list of " +
                           std::to_string(list.size()));
      return;
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string path = r.key_path("refine") + "/" + std::to_string(i);
      if (!list[i].is_object()) {
        r.problems().add(
            path,
            "expected a box (an object with lower, upper, factor, growth), got " + list[i].dump());
        continue;
      }
      JsonReader f(list[i], path, r.problems());
      if (auto box = read_refined_box(f, list[i], g, true)) g.refine.push_back(*box);
    }
    return;
  }
  auto f = r.optional_child("refine",
                            "a box of finer cells (or a list of boxes): a graded "
                            "(tartan) grid");
  // A present non-object is reported by optional_child: its keys are not read as missing.
  if (!f || !at(grid, "refine").is_object()) return;
  if (auto box = read_refined_box(*f, at(grid, "refine"), g, false)) g.refine.push_back(*box);
}

// What a graded grid turned out to be, where a user would not expect it: a factor so close to 1
// that no axis got finer cells (then the uniform grid, its own path), or a growth so slow that
// the cells never grow back to the base size (the axis is fine everywhere: the cost of the fine
// grid, not of a box).
void warn_of_grading(JsonReader& r, GridSpec& g, bool listed) {
  // A list of boxes is graded as one (along each axis the spans of all of them): its warnings
  // name the list.
  const auto refine_key = [&](const char* key) {
    return r.key_path("refine") + (listed ? std::string() : "/" + std::string(key));
  };
  const Vec3 h0 = g.spacing();
  bool finer = false;
  for (int d = 0; d < g.dimensions(); ++d) {
    const GradedAxis& a = g.axes[std::size_t(d)];
    finer = finer || a.smallest() < (1.0 - 1e-9) * h0(d);
    if (a.smallest() < (1.0 - 1e-9) * h0(d) && a.largest() < 0.9 * h0(d)) {
      std::ostringstream m;
      m << "along axis " << d << " the cells grow only to " << a.largest() << " m of the base "
        << h0(d) << " m: the axis is fine everywhere (" << a.cells() << " cells for "
        << g.base_cells[std::size_t(d)] << "); raise growth or narrow the box";
      r.problems().warn(refine_key("growth"), m.str());
    }
  }
  // A list's boxes whose spans merge get round(base cells x finest factor) cells together; each
  // box alone was checked for rounding (read_refined_box), the merged span was not (the trial: 2.5
  // on two boxes merging into 3 base cells gave 8 cells, a factor of 2.67, without a word).
  // Axes that came out alike are named together, as a box's own rounding is.
  if (listed) {
    double finest = 1.0;
    for (const GridRefinement& box : g.refine) finest = std::max(finest, box.factor);
    struct Merged {
      std::string axes;
      double h0, h;  // the base cell and the merged span's cell [m]
    };
    std::vector<Merged> merged;
    for (int d = 0; d < g.dimensions(); ++d) {
      const double h = g.axes[std::size_t(d)].smallest();
      const double got = h0(d) / h;
      if (std::abs(got / finest - 1.0) <= 0.05) continue;
      bool warned = false;  // a box of the finest factor rounds so alone: said at its key already
      for (const GridRefinement& box : g.refine) {
        const auto c = span_cells(g.lower(d), g.upper(d), g.base_cells[std::size_t(d)],
                                  RefinedSpan{box.lower(d), box.upper(d), box.factor, box.growth});
        warned = warned || (box.factor == finest && c &&
                            std::abs(double(c->refined) / double(c->base) / finest - 1.0) > 0.05);
      }
      if (warned) continue;
      const auto same = std::find_if(merged.begin(), merged.end(),
                                     [&](const Merged& m) { return m.h0 == h0(d) && m.h == h; });
      if (same != merged.end()) {
        same->axes += ", " + std::to_string(d);
      } else {
        merged.push_back({std::to_string(d), h0(d), h});
      }
    }
    for (const Merged& a : merged) {
      std::ostringstream m;
      m << (a.axes.size() > 1 ? "along axes " : "along axis ") << a.axes
        << " the boxes' spans merge into one whose cells are " << a.h << " m, a factor of "
        << a.h0 / a.h << " against the finest " << finest << ": the merged span's base cells times "
        << finest << " are rounded to whole cells; choose factors that make them whole";
      r.problems().warn(refine_key("factor"), m.str());
    }
  }
  // Neighbouring cells that differ by more than the growth asked for: a gap between two boxes
  // (or a side between a box and a face) too short to grade gets equal cells beside the finer
  // ones (graded_axis.cpp). Waves reflect more at such a step (docs/scenes.md, graded_wave_test).
  double growth = 1.0;
  for (const GridRefinement& box : g.refine) growth = std::max(growth, box.growth);
  for (int d = 0; d < g.dimensions(); ++d) {
    const GradedAxis& a = g.axes[std::size_t(d)];
    double worst = 1.0, at = 0.0;
    for (int i = 1; i < a.cells(); ++i) {
      const double ratio = std::max(a.size(i) / a.size(i - 1), a.size(i - 1) / a.size(i));
      if (ratio > worst) worst = ratio, at = a.node(i);
    }
    if (worst > growth * (1.0 + 1e-9)) {
      std::ostringstream m;
      m << "along axis " << d << " neighbouring cells differ by " << worst << " at " << at
        << " m, more than the growth " << growth
        << ": the gap between boxes (or between a box and a face) is too short to grade; "
           "move the boxes apart, merge them, or lower the finer factor";
      r.problems().warn(refine_key("growth"), m.str());
    }
  }
  // A tartan grid refines whole strips: where the box's strip along one axis crosses the coarse
  // cells of another, the cells are up to `factor` times longer than wide. A Taylor rod with a
  // 0.5 mm box refined 16 times gained +1.9 % energy at impact there (a uniform grid of such
  // cells does the same).
  const auto aspect = [&](const Vec3& small, const Vec3& large) {
    const int n = g.dimensions();
    return large.head(n).maxCoeff() / small.head(n).minCoeff();
  };
  const double graded_aspect = aspect(g.smallest_cell(), g.largest_cell());
  const double base_aspect = aspect(h0, h0);
  // (1 + 1e-9: at factor 4 exactly the smallest cell is a round-off under h0 / 4.)
  if (finer && graded_aspect > 4.0 * base_aspect * (1.0 + 1e-9)) {
    std::ostringstream m;
    m << "where the refined box's strips cross the coarse cells the cells are up to "
      << graded_aspect << ":1 in shape (the base cells " << base_aspect
      << ":1); cells that long gain energy at an impact: keep factor at most 4, or refine the "
         "base grid";
    r.problems().warn(refine_key("factor"), m.str());
  }
  if (!finer) {
    r.problems().warn(refine_key("factor"),
                      "no axis gets cells finer than grid.cells' with this factor: the grid is "
                      "the uniform one of grid.cells");
    g.ungrade();
  }
}

}  // namespace

void read_grid(JsonReader& root, const Json& doc, GridSpec& g) {
  JsonReader r = root.child("grid", "background grid");
  const Json& n = at(doc, "grid");
  const std::vector<std::string_view> names = geometry_names();
  const std::string geometry = r.choice("geometry", names, geometry_description(), names.front());
  g.geometry = geometry_named(geometry).value_or(kDefaultGeometry);
  g.lower = read_vec3(r, n, "lower", "lower corner of the grid [m] ([x, y] on a 2D grid)");
  g.upper = read_vec3(r, n, "upper", "upper corner of the grid [m] ([x, y] on a 2D grid)");
  g.cells =
      read_int3(r, n, "cells", 1, 100000, "cells per axis ([x, y] on a 2D grid)", std::nullopt);
  const Vec3 extent = g.upper - g.lower;
  if (g.lower.hasNaN() || g.upper.hasNaN()) {
    // reported by read_vec3 (missing or not numbers): no second problem about their order
  } else if (!(extent.array() > 0.0).all()) {
    r.problems().add(r.key_path("upper"), "expected upper > lower on every axis");
  } else if (!extent.allFinite()) {  // both finite, their difference beyond the doubles
    std::ostringstream m;
    m << "expected a finite extent upper - lower on every axis, got [" << extent(0) << ", "
      << extent(1) << ", " << extent(2) << "] m (lower and upper overflow when subtracted)";
    r.problems().add(r.key_path("upper"), m.str());
  } else if (auto hint = unit_hint(Quantity::length, extent.maxCoeff())) {
    // A scene typed in millimetres shows in the grid, which spans every object.
    r.problems().warn(r.key_path("upper"),
                      "largest extent (upper - lower) " + *hint + "; the value is used as given");
  }
  const int axis_face = g.geometry_facts().axis_face;
  // The axis of symmetry lies in the lower face of the radial axis: its coordinate must be 0.
  const int axis = axis_face / 2;
  if (axis_face >= 0 && g.lower(axis) != 0.0 && std::isfinite(g.lower(axis))) {
    std::ostringstream got;  // as typed, 1e-09 too (std::to_string would print 0.000000)
    got << g.lower(axis);
    r.problems().add(r.key_path("lower") + "/" + std::to_string(axis),
                     "an axisymmetric grid starts at the axis, y = 0 (y is the radius); expected "
                     "0, got " +
                         got.str());
  }
  read_faces(r, n, g, geometry);
  read_refinement(r, n, g);
  if (!r.problems().empty()) g.refine.clear();  // graded only from valid bounds and cells
  g.grade();
  // Each box's cells are bounded above; boxes whose spans merge along an axis can still exceed
  // the bound together.
  bool too_many = false;
  for (int d = 0; g.graded() && d < g.dimensions(); ++d)
    if (const int c = g.axes[std::size_t(d)].cells(); c > 100000) {
      r.problems().add(r.key_path("refine"),
                       "along axis " + std::to_string(d) +
                           " the boxes' refined spans together get " + std::to_string(c) +
                           " cells: expected at most 100000 (lower a factor or narrow the boxes)");
      too_many = true;
    }
  if (too_many) g.ungrade();  // the base grid from here on, as after any other problem
  if (g.graded()) warn_of_grading(r, g, n.contains("refine") && n["refine"].is_array());
  // The grid stores (cells + 3) nodes per axis (ghost layers) and indexes them with int; a 2D
  // grid one node plane along z.
  const double stored_nodes =
      (g.cells[0] + 3.0) * (g.cells[1] + 3.0) * (g.planar() ? 1.0 : g.cells[2] + 3.0);
  if (stored_nodes > static_cast<double>(std::numeric_limits<int>::max())) {
    std::ostringstream m;
    m << "(cells + 3) per axis multiplied" << (g.graded() ? " (the graded axes' cells)" : "")
      << " is " << stored_nodes << " stored grid nodes: expected at most 2147483647 (2^31 - 1)";
    r.problems().add(r.key_path(g.graded() ? "refine" : "cells"), m.str());
  }
  g.active_blocks = r.boolean_or(
      "active_blocks", true,
      "grid work only where the particles are (false: every node of the box every step)");
  g.outflow = r.choice("outflow", {"stop", "remove"},
                       "a particle that leaves the grid: stop the run, or remove it and book its "
                       "mass, momentum and kinetic energy as outflow",
                       "stop") == "remove"
                  ? Outflow::remove
                  : Outflow::stop;
  r.reject_unknown_keys();
}

}  // namespace impact::mpm::scene_input
