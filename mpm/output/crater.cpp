#include "mpm/output/crater.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impact::mpm {

namespace {

// The weighted median of u: the smallest u at which the weight below it reaches half.
double weighted_median(std::vector<FacePoint> face) {
  std::sort(face.begin(), face.end(),
            [](const FacePoint& a, const FacePoint& b) { return a.u < b.u; });
  double total = 0.0;
  for (const FacePoint& q : face) total += q.weight;
  double below = 0.0;
  for (const FacePoint& q : face) {
    below += q.weight;
    if (below >= 0.5 * total) return q.u;
  }
  return face.back().u;
}

struct Ring {
  double w = 0.0, r = 0.0, u = 0.0;  // weight, then the weighted mean radius and u
};

// A raised rim is looked for out to kRimReach half-depth radii, and must stand above the far
// field by more than kRimFloor of the depth: lower, a crest is the particle scatter's (a flat
// far field has ring means on both sides of its median), not a rim. Simple craters' rims stand
// about a fifth of their depth high (Pike 1977: h_r / d = 0.036 D / 0.196 D).
constexpr double kRimReach = 3.0;
constexpr double kRimFloor = 0.05;

// The target's extent along +x from x0 (a particle's initial position, inside the body) at
// (y, z), in steps of a hundredth of a cell: how far that particle may move before it passes the
// back face.
double thickness_along_x(const Geometry& g, double x0, double y, double z, double dx,
                         double upper) {
  const double step = 0.01 * dx;
  double x = x0 + 0.5 * step;
  while (x < upper && inside(g, Vec3(x, y, z))) x += step;
  return x - 0.5 * step - x0;
}

}  // namespace

// Long on purpose (about 125 lines): the crater steps of docs/mpm.md in that order, each on the
// profile the one before built.
Crater crater_of(const std::vector<FacePoint>& all, double ring_width,
                 const std::optional<std::array<double, 2>>& axis, bool revolved,
                 std::optional<double> thickness) {
  Crater c;
  c.ring_width = ring_width;
  c.face_particles = all.size();
  c.thickness = thickness;
  // A particle whose position is not finite (a run that is failing) has no place in the profile.
  std::vector<FacePoint> face;
  for (const FacePoint& q : all) {
    if (std::isfinite(q.u) && std::isfinite(q.y) && std::isfinite(q.z) && q.weight > 0.0 &&
        std::isfinite(q.weight))
      face.push_back(q);
  }
  if (face.empty()) {
    c.status = "no face particle";
    return c;
  }
  c.floor_displacement =
      std::max_element(face.begin(), face.end(), [](const FacePoint& a, const FacePoint& b) {
        return a.u < b.u;
      })->u;
  c.far_field_displacement = weighted_median(face);
  const double far = c.far_field_displacement, floor = c.floor_displacement;
  const double half = far + 0.5 * (floor - far);
  c.depth = floor - far;
  // The axis: given, the axis of symmetry, or the weighted mean position of the bowl's lower half.
  if (axis) {
    c.axis_y = (*axis)[0];
    c.axis_z = (*axis)[1];
  } else if (!revolved) {
    double w = 0.0, sy = 0.0, sz = 0.0;
    for (const FacePoint& q : face) {
      if (q.u < half) continue;
      w += q.weight;
      sy += q.weight * q.y;
      sz += q.weight * q.z;
    }
    c.axis_y = sy / w;  // w > 0: the deepest particle is at or below half
    c.axis_z = sz / w;
  }
  // An axisymmetric particle is a ring: its y is its radius (the axis is y = 0 there).
  const auto radius = [&](const FacePoint& q) {
    return revolved ? std::abs(q.y) : std::hypot(q.y - c.axis_y, q.z - c.axis_z);
  };
  if (!(floor > far)) {
    c.status = "no crater: the face moved as a whole";
    return c;
  }
  // The rings' weighted profile, from the floor on the axis outwards.
  double largest = 0.0;
  for (const FacePoint& q : face) largest = std::max(largest, radius(q));
  std::vector<Ring> rings(static_cast<std::size_t>(largest / ring_width) + 1);
  for (const FacePoint& q : face) {
    const double r = radius(q);
    Ring& k = rings[std::min(rings.size() - 1, static_cast<std::size_t>(r / ring_width))];
    k.w += q.weight;
    k.r += q.weight * r;
    k.u += q.weight * q.u;
  }
  std::vector<Ring> profile = {{1.0, 0.0, floor}};
  for (Ring& k : rings) {
    if (k.w == 0.0) continue;
    k.r /= k.w;
    k.u /= k.w;
    profile.push_back(k);
  }
  // Where the profile first rises to `level` going out from the axis (linear between its
  // points), and the index of the first point at or above it; none if it never does.
  const auto rise_to = [&](double level) -> std::optional<std::pair<double, std::size_t>> {
    for (std::size_t k = 1; k < profile.size(); ++k) {
      if (profile[k].u > level) continue;
      const Ring& a = profile[k - 1];
      const Ring& b = profile[k];
      return std::pair{a.r + (a.u - level) / (a.u - b.u) * (b.r - a.r), k};
    }
    return std::nullopt;
  };
  std::ostringstream status;
  const auto at_half = rise_to(half);
  double crater_radius = 0.0;  // the crater's extent on the face, for crater_fraction
  if (!at_half) {
    status << "no wall: the surface stays below half the depth out to the face's edge (no "
              "diameter)";
    crater_radius = largest;
  } else {
    const double r_half = at_half->first;
    c.half_depth_diameter = 2.0 * r_half;
    const auto at_surface = rise_to(far);
    if (at_surface) c.surface_diameter = 2.0 * at_surface->first;
    crater_radius = at_surface ? at_surface->first : r_half;
    // A raised rim: the highest ring (least u) from R_half out to kRimReach R_half, if it is a
    // crest (a ring further out lies lower) and stands above the far field by more than the
    // particle scatter: kRimFloor of the depth. The first crest is not enough: a shoulder in the
    // wall would hide the rim beyond it, and noise makes a crest at the wall's foot.
    std::optional<std::size_t> crest;
    for (std::size_t k = at_half->second; k < profile.size(); ++k) {
      if (profile[k].r > kRimReach * r_half) break;
      if (!crest || profile[k].u < profile[*crest].u) crest = k;
    }
    if (crest && *crest + 1 < profile.size() && profile[*crest + 1].u > profile[*crest].u &&
        far - profile[*crest].u > kRimFloor * c.depth) {
      const Ring& rim = profile[*crest];
      c.rim_diameter = 2.0 * rim.r;
      c.rim_to_floor = floor - rim.u;
      c.rim_height = far - rim.u;
      crater_radius = rim.r;
    }
    status << "crater; " << (c.rim_diameter ? "a raised rim" : "no raised rim");
  }
  double inside = 0.0, total = 0.0;
  for (const FacePoint& q : face) {
    total += q.weight;
    inside += radius(q) <= crater_radius ? q.weight : 0.0;
  }
  c.crater_fraction = inside / total;
  if (c.crater_fraction > 0.5)
    status << "; it covers more than half of the face: the median is no far field";
  if (thickness && c.depth >= *thickness) {
    status << "; the floor sank " << c.depth << " m below the far field, as far as the target is "
           << "thick there (" << *thickness << " m): perforated or a plug pushed through (the "
           << "numbers then measure the plug)";
  }
  c.status = status.str();
  return c;
}

CraterMeasure::CraterMeasure(const Scene& scene, const CraterSpec& spec, const Particles& initial,
                             const Communicator& comm)
    : spec_(spec),
      geometry_(scene.objects[std::size_t(spec.object)].geometry),
      // The cell along x at the face (graded: the one the face lies in).
      dx_(scene.grid.cell_size(0, scene.grid.cell_along(0, spec.face))),
      grid_upper_x_(scene.grid.upper(0)),
      rings_(scene.grid.geometry_facts().rings),
      comm_(comm) {
  // The rings' width: the cell edge across the face (the radial one on a 2D grid); on a graded
  // grid the cells at the crater's axis when the scene gives it, else the smallest (the refined
  // cells a crater is meant to lie in).
  Vec3 h = scene.grid.smallest_cell();
  if (scene.grid.graded() && spec.axis) {
    h(1) = scene.grid.cell_size(1, scene.grid.cell_along(1, (*spec.axis)[0]));
    h(2) = scene.grid.cell_size(2, scene.grid.cell_along(2, (*spec.axis)[1]));
  }
  ring_width_ = scene.grid.planar() ? h(1) : 0.5 * (h(1) + h(2));
  struct Seed {
    std::uint64_t id;
    double x0[3];
  };
  std::vector<Seed> layer;
  for (std::size_t p = 0; p < initial.size(); ++p) {
    if (initial.object[p] != spec.object) continue;
    if (std::abs(initial.x[p](0) - spec.face) > dx_) continue;
    layer.push_back({seed_index(initial, p), {initial.x[p](0), initial.x[p](1), initial.x[p](2)}});
  }
  // In seed-index order, the order of the set's ids (ParticleSets): the storage order is not
  // that on several ranks nor in a shuffled store (solver.shuffle_particles; the layer's initial
  // positions, kept in storage order, were matched to other particles there, and case 1's crater
  // depth read 4.74 mm where the particles made 4.28).
  if (comm_.several()) layer = comm_.concatenate(layer);
  std::sort(layer.begin(), layer.end(), [](const Seed& a, const Seed& b) { return a.id < b.id; });
  std::vector<std::uint64_t> ids;
  for (const Seed& s : layer) {
    ids.push_back(s.id);
    face_x0_.emplace_back(s.x0[0], s.x0[1], s.x0[2]);
  }
  face_.add(std::move(ids));  // already every rank's
}

Crater CraterMeasure::measure(const Particles& P) const {
  struct Point {
    std::size_t i;  // the place in the face layer (seed-index order)
    FacePoint q;
  };
  std::vector<Point> mine;
  const std::vector<std::vector<ParticleSets::Member>> found = face_.find(P);
  for (const ParticleSets::Member& m : found[0]) {
    if (P.mass[m.p] == 0.0) continue;  // removed (grid.outflow = remove)
    const Vec3& x = P.x[m.p];
    mine.push_back({m.i, {x(0) - face_x0_[m.i](0), x(1), x(2), P.volume0[m.p]}});
  }
  // In seed-index order on any number of ranks: the rings' sums add in the same order.
  mine = comm_.concatenate(mine);
  std::sort(mine.begin(), mine.end(), [](const Point& a, const Point& b) { return a.i < b.i; });
  std::vector<FacePoint> face;
  face.reserve(mine.size());
  for (const Point& m : mine) face.push_back(m.q);
  // The target's thickness along x where the deepest particle started.
  std::optional<double> thickness;
  if (!mine.empty()) {
    const Point& deepest = *std::max_element(
        mine.begin(), mine.end(), [](const Point& a, const Point& b) { return a.q.u < b.q.u; });
    const Vec3& x0 = face_x0_[deepest.i];
    thickness = thickness_along_x(geometry_, x0(0), x0(1), x0(2), dx_, grid_upper_x_);
  }
  Crater c = crater_of(face, ring_width_, spec_.axis, rings_, thickness);
  c.face_particles = face_.ids(0).size();
  return c;
}

Json Crater::json(const std::string& object, double face) const {
  const auto or_null = [](const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); };
  return {{"object", object},
          {"face [m]", face},
          {"depth [m]", depth},
          {"half_depth_diameter [m]", or_null(half_depth_diameter)},
          {"surface_diameter [m]", or_null(surface_diameter)},
          {"rim_diameter [m]", or_null(rim_diameter)},
          {"rim_to_floor_depth [m]", or_null(rim_to_floor)},
          {"rim_height [m]", or_null(rim_height)},
          {"floor_displacement [m]", floor_displacement},
          {"far_field_displacement [m]", far_field_displacement},
          {"thickness [m]", or_null(thickness)},
          {"axis_yz [m]", Json::array({axis_y, axis_z})},
          {"ring_width [m]", ring_width},
          {"crater_fraction [-]", crater_fraction},
          {"face_particles", face_particles},
          {"status", status}};
}

}  // namespace impact::mpm
