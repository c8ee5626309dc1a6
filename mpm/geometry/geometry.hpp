// Solid shapes that objects are seeded from: an inside test for particle seeding and the exact
// volume that `mpm check` compares the seeded particle volume with. Lengths in metres.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "models/core/input.hpp"
#include "models/core/tensor.hpp"

namespace impact::mpm {

struct Box {
  Vec3 lower, upper;
};
struct Sphere {
  Vec3 center;
  double radius;
};
/// Solid circular cylinder between the centres of its end faces.
struct Cylinder {
  Vec3 bottom, top;
  double radius;
};
/// Tube of outer radius `radius` and wall `thickness`, optionally closed at its bottom end by a
/// solid cap `cap_thickness` long (the report's end plate plus hollow cylinder is one such tube).
struct HollowCylinder {
  Vec3 bottom, top;
  double radius, thickness, cap_thickness;
};
struct Geometry;
/// Union of parts; a point shared by several parts is seeded once, and volume() counts it once
/// (union_overlap_shares below).
struct Union {
  std::vector<Geometry> parts;
};
struct Geometry {
  std::variant<Box, Sphere, Cylinder, HollowCylinder, Union> shape;
};

bool inside(const Geometry& g, const Vec3& x);
/// Volume [m^3]: exact, and for a union the sum of its parts' volumes less what they share,
/// exact where the parts' bounding boxes do not meet and sampled where they do.
double volume(const Geometry& g);
/// Axis-aligned bounding box (lower, upper).
std::pair<Vec3, Vec3> bounds(const Geometry& g);
/// Whether two such boxes meet (touching counts).
inline bool boxes_meet(const std::pair<Vec3, Vec3>& a, const std::pair<Vec3, Vec3>& b) {
  return (a.first.array() <= b.second.array()).all() && (b.first.array() <= a.second.array()).all();
}

/// f(x) at the cell centres of an n[0] x n[1] x n[2] lattice on the box [lo, hi] (a flat box,
/// lo(2) = hi(2), with n[2] = 1: its plane): the points the checks that measure a body's shares
/// sample it at (scene/grid_coverage.cpp, scene/object_overlap.cpp, run/seeding_check.cpp).
template <class F>
void for_each_lattice_point(const Vec3& lo, const Vec3& hi, const std::array<long, 3>& n, F&& f) {
  const Vec3 step = (hi - lo).cwiseQuotient(Vec3(double(n[0]), double(n[1]), double(n[2])));
  for (long i = 0; i < n[0]; ++i)
    for (long j = 0; j < n[1]; ++j)
      for (long k = 0; k < n[2]; ++k)
        f(Vec3(lo + step.cwiseProduct(Vec3(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5))));
}
/// The same on an n^3 lattice.
template <class F>
void for_each_lattice_point(const Vec3& lo, const Vec3& hi, int n, F&& f) {
  for_each_lattice_point(lo, hi, std::array<long, 3>{n, n, n}, f);
}

/// Per part of a union, the share of it that lies in an earlier part: sampled at the cell
/// centres of a lattice over the part's bounding box (64^3 points; in the plane z = 0, 512^2, with
/// `plane`: the section a 2D grid seeds, of prisms along z), and 0 exactly where no earlier
/// part's bounding box meets it. A union's measure counts a shared part once: sum over the parts
/// of m_k (1 - share_k). (Summed, the ramp scene's union of a box and a tilted cylinder read 11 %
/// more volume than it has, and its volume_ratio 0.897 showed a loss that was not there.)
std::vector<double> union_overlap_shares(const Union& u, bool plane = false);

/// Reads {"type": "box"|"sphere"|"cylinder"|"hollow_cylinder"|"union", ...}; problems go to
/// r.problems() with their key paths.
Geometry read_geometry(JsonReader& r, const Json& node);
Json to_json(const Geometry& g);

/// A 3-vector at `key` of `node` (the object `r` reads); problems name the key path.
Vec3 read_vec3(JsonReader& r, const Json& node, std::string_view key, std::string_view meaning,
               std::optional<Vec3> fallback = {});

}  // namespace impact::mpm
