#include "mpm/geometry/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace impact::mpm {

namespace {

// Axial coordinate s in [0, H] and radial distance of x from the axis bottom -> top.
struct AxisCoords {
  double s, r, height;
};
AxisCoords axis_coords(const Vec3& bottom, const Vec3& top, const Vec3& x) {
  const Vec3 axis = top - bottom;
  const double height = axis.norm();
  const Vec3 e = axis / height;
  const Vec3 d = x - bottom;
  const double s = d.dot(e);
  return {s, (d - s * e).norm(), height};
}

std::pair<Vec3, Vec3> cylinder_bounds(const Vec3& a, const Vec3& b, double radius) {
  // Exact box of a cylinder: along each axis the end discs reach radius * sqrt(1 - e_d^2).
  const Vec3 e = (b - a).normalized();
  Vec3 ext;
  for (int d = 0; d < 3; ++d) ext(d) = radius * std::sqrt(std::max(0.0, 1.0 - e(d) * e(d)));
  return {a.cwiseMin(b) - ext, a.cwiseMax(b) + ext};
}

}  // namespace

bool inside(const Geometry& g, const Vec3& x) {
  return std::visit(
      [&](const auto& s) -> bool {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return (x.array() >= s.lower.array()).all() && (x.array() <= s.upper.array()).all();
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return (x - s.center).squaredNorm() <= s.radius * s.radius;
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          const AxisCoords c = axis_coords(s.bottom, s.top, x);
          return c.s >= 0.0 && c.s <= c.height && c.r <= s.radius;
        } else if constexpr (std::is_same_v<T, HollowCylinder>) {
          const AxisCoords c = axis_coords(s.bottom, s.top, x);
          if (c.s < 0.0 || c.s > c.height || c.r > s.radius) return false;
          return c.r >= s.radius - s.thickness || c.s <= s.cap_thickness;
        } else {
          return std::any_of(s.parts.begin(), s.parts.end(),
                             [&](const Geometry& p) { return inside(p, x); });
        }
      },
      g.shape);
}

double volume(const Geometry& g) {
  constexpr double pi = std::numbers::pi;
  return std::visit(
      [&](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return (s.upper - s.lower).prod();
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return 4.0 / 3.0 * pi * std::pow(s.radius, 3);
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return pi * s.radius * s.radius * (s.top - s.bottom).norm();
        } else if constexpr (std::is_same_v<T, HollowCylinder>) {
          const double h = (s.top - s.bottom).norm();
          const double ri = s.radius - s.thickness;
          return pi * (s.radius * s.radius - ri * ri) * h + pi * ri * ri * s.cap_thickness;
        } else {
          const std::vector<double> shared = union_overlap_shares(s);
          double v = 0.0;
          for (std::size_t k = 0; k < s.parts.size(); ++k)
            v += volume(s.parts[k]) * (1.0 - shared[k]);
          return v;
        }
      },
      g.shape);
}

std::vector<double> union_overlap_shares(const Union& u, bool plane) {
  std::vector<double> shares(u.parts.size(), 0.0);
  for (std::size_t k = 1; k < u.parts.size(); ++k) {
    const auto box = bounds(u.parts[k]);
    const auto& [lo, hi] = box;
    bool meets = false;  // an earlier part's bounding box meets this one's
    for (std::size_t j = 0; j < k && !meets; ++j) meets = boxes_meet(bounds(u.parts[j]), box);
    if (!meets) continue;
    std::size_t in_part = 0, in_earlier = 0;
    const auto count = [&](const Vec3& x) {
      if (!inside(u.parts[k], x)) return;
      ++in_part;
      for (std::size_t j = 0; j < k; ++j)
        if (inside(u.parts[j], x)) {
          ++in_earlier;
          return;
        }
    };
    if (plane) {
      constexpr int n = 512;
      const double z = 0.0;  // a 2D grid's seed points lie in the section z = 0
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          count(Vec3(lo(0) + (hi(0) - lo(0)) * (i + 0.5) / n,
                     lo(1) + (hi(1) - lo(1)) * (j + 0.5) / n, z));
    } else {
      for_each_lattice_point(lo, hi, 64, count);
    }
    if (in_part > 0) shares[k] = double(in_earlier) / double(in_part);
  }
  return shares;
}

std::pair<Vec3, Vec3> bounds(const Geometry& g) {
  return std::visit(
      [&](const auto& s) -> std::pair<Vec3, Vec3> {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return {s.lower, s.upper};
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return {s.center.array() - s.radius, s.center.array() + s.radius};
        } else if constexpr (std::is_same_v<T, Cylinder> || std::is_same_v<T, HollowCylinder>) {
          return cylinder_bounds(s.bottom, s.top, s.radius);
        } else {
          Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
          Vec3 hi = -lo;
          for (const Geometry& p : s.parts) {
            const auto [a, b] = bounds(p);
            lo = lo.cwiseMin(a);
            hi = hi.cwiseMax(b);
          }
          return {lo, hi};
        }
      },
      g.shape);
}

Vec3 read_vec3(JsonReader& r, const Json& node, std::string_view key, std::string_view meaning,
               std::optional<Vec3> fallback) {
  r.read_elsewhere(key, [&] {
    std::optional<std::string> value;
    if (fallback) {
      std::ostringstream text;
      text << '[' << (*fallback)(0) << ", " << (*fallback)(1) << ", " << (*fallback)(2) << ']';
      value = text.str();
    }
    return KeyDescription{"[3 numbers]", "", value, std::string(meaning)};
  });
  const std::string k(key);
  if (!node.is_object() || !node.contains(k)) {
    if (fallback) return *fallback;
    r.problems().add(r.key_path(key),
                     "missing required array of 3 numbers (" + std::string(meaning) + ")");
    return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  const Json& v = node[k];
  if (!v.is_array() || v.size() != 3 ||
      !std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_number(); })) {
    r.problems().add(r.key_path(key), "expected an array of 3 numbers, got " + v.dump() + " (" +
                                          std::string(meaning) + ")");
    return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  return Vec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
}

Geometry read_geometry(JsonReader& r, const Json& node) {
  const std::string type =
      r.choice("type", {"box", "sphere", "cylinder", "hollow_cylinder", "union"}, "geometry type");
  Geometry g{Box{Vec3::Zero(), Vec3::Zero()}};
  const double inf = std::numeric_limits<double>::infinity();
  if (type == "box") {
    Box b{read_vec3(r, node, "lower", "lower corner [m]"),
          read_vec3(r, node, "upper", "upper corner [m]")};
    // (A corner missing or not numbers is NaN, reported by read_vec3: no second problem.)
    if (!b.lower.hasNaN() && !b.upper.hasNaN() && !((b.upper - b.lower).array() > 0.0).all()) {
      r.problems().add(r.key_path("upper"), "expected upper > lower on every axis");
    }
    g.shape = b;
  } else if (type == "sphere") {
    g.shape = Sphere{read_vec3(r, node, "center", "centre [m]"),
                     r.number("radius", Range::positive(), "radius [m]")};
  } else if (type == "cylinder" || type == "hollow_cylinder") {
    const Vec3 bottom = read_vec3(r, node, "bottom", "centre of the bottom face [m]");
    const Vec3 top = read_vec3(r, node, "top", "centre of the top face [m]");
    const double radius = r.number("radius", Range::positive(), "outer radius [m]");
    if (!bottom.hasNaN() && !top.hasNaN() && !((top - bottom).norm() > 0.0)) {
      r.problems().add(r.key_path("top"), "expected top different from bottom");
    }
    if (type == "cylinder") {
      g.shape = Cylinder{bottom, top, radius};
    } else {
      const double t = r.number("thickness", Range::open(0.0, inf), "wall thickness [m]");
      const double cap = r.number_or("cap_thickness", 0.0, Range::non_negative(),
                                     "length of the solid cap at the bottom end [m]; 0: open");
      if (t > radius) r.problems().add(r.key_path("thickness"), "expected thickness <= radius");
      if (cap > (top - bottom).norm()) {
        r.problems().add(r.key_path("cap_thickness"), "expected cap_thickness <= length");
      }
      g.shape = HollowCylinder{bottom, top, radius, t, cap};
    }
  } else if (type == "union") {
    Union u;
    JsonReader parts = r.child("parts", "named parts of the union, each a geometry");
    const Json& pn = node.contains("parts") ? node["parts"] : empty_json_object();
    if (pn.is_object()) {
      for (const auto& item : pn.items()) {
        JsonReader pr = parts.child(item.key(), "geometry of one part");
        u.parts.push_back(read_geometry(pr, item.value()));
        pr.reject_unknown_keys();
      }
    }
    if (u.parts.empty()) r.problems().add(r.key_path("parts"), "expected at least one part");
    g.shape = std::move(u);
  }
  return g;
}

Json to_json(const Geometry& g) {
  const auto vec = [](const Vec3& v) { return Json::array({v(0), v(1), v(2)}); };
  return std::visit(
      [&](const auto& s) -> Json {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return {{"type", "box"}, {"lower", vec(s.lower)}, {"upper", vec(s.upper)}};
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return {{"type", "sphere"}, {"center", vec(s.center)}, {"radius", s.radius}};
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return {{"type", "cylinder"},
                  {"bottom", vec(s.bottom)},
                  {"top", vec(s.top)},
                  {"radius", s.radius}};
        } else if constexpr (std::is_same_v<T, HollowCylinder>) {
          return {{"type", "hollow_cylinder"}, {"bottom", vec(s.bottom)},
                  {"top", vec(s.top)},         {"radius", s.radius},
                  {"thickness", s.thickness},  {"cap_thickness", s.cap_thickness}};
        } else {
          Json parts = Json::object();
          int i = 0;
          for (const Geometry& p : s.parts) parts["part" + std::to_string(i++)] = to_json(p);
          return {{"type", "union"}, {"parts", parts}};
        }
      },
      g.shape);
}

}  // namespace impact::mpm
