#include "mpm/scene/planar_form.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace impact::mpm {

namespace {

// Relative tolerance on "on the axis" and "along an axis": a coordinate typed as 0 is exactly 0;
// this admits round-off from a generated scene.
constexpr double kTolerance = 1e-12;

bool on_x_axis(const Vec3& p, double scale) {
  return std::abs(p(1)) <= kTolerance * scale && std::abs(p(2)) <= kTolerance * scale;
}

// The direction bottom -> top lies along `axis`.
bool along(const Vec3& bottom, const Vec3& top, int axis) {
  const Vec3 d = top - bottom;
  for (int a = 0; a < 3; ++a)
    if (a != axis && std::abs(d(a)) > kTolerance * d.norm()) return false;
  return true;
}

std::string text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string text(const Vec3& v) {
  std::ostringstream s;
  s << '[' << v(0) << ", " << v(1) << ", " << v(2) << ']';
  return s.str();
}

}  // namespace

std::string revolution_problem(const Geometry& g) {
  return std::visit(
      [&](const auto& s) -> std::string {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          std::string m = "a box is not a body of revolution about the x axis";
          if (s.lower(1) < 0.0) m += " (and it lies partly at y < 0, below the axis)";
          return m +
                 "; expected a cylinder or hollow_cylinder along x on the axis (a plate is a "
                 "cylinder of the plate's radius)";
        } else if constexpr (std::is_same_v<T, Sphere>) {
          if (on_x_axis(s.center, s.radius)) return "";
          return "a sphere centred at " + text(s.center) +
                 " is off the axis of symmetry (the x axis, y = z = 0)" +
                 (s.center(1) < 0.0 ? ", at y < 0" : "") +
                 "; expected its centre on the axis, [x, 0, 0]";
        } else if constexpr (std::is_same_v<T, Cylinder> || std::is_same_v<T, HollowCylinder>) {
          if (on_x_axis(s.bottom, s.radius) && on_x_axis(s.top, s.radius)) return "";
          return "a cylinder from " + text(s.bottom) + " to " + text(s.top) +
                 " is not a body of revolution about the x axis" +
                 (s.bottom(1) < 0.0 || s.top(1) < 0.0 ? " (it lies at y < 0)" : "") +
                 "; expected bottom and top on the axis, [x, 0, 0]";
        } else {
          for (std::size_t i = 0; i < s.parts.size(); ++i) {
            const std::string why = revolution_problem(s.parts[i]);
            if (!why.empty()) return "union part " + std::to_string(i) + ": " + why;
          }
          return "";
        }
      },
      g.shape);
}

std::string prism_problem(const Geometry& g) {
  return std::visit(
      [&](const auto& s) -> std::string {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          if (s.lower(2) <= 0.0 && s.upper(2) >= 0.0) return "";
          return "a box from z = " + text(s.lower(2)) + " to " + text(s.upper(2)) +
                 " m misses the plane z = 0 that a plane-strain grid models; expected lower[2] "
                 "<= 0 <= upper[2]";
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return "a sphere has no plane-strain form (its section is the disc of an infinitely "
                 "long cylinder); expected a cylinder along z for a disc";
        } else if constexpr (std::is_same_v<T, Cylinder> || std::is_same_v<T, HollowCylinder>) {
          if (!along(s.bottom, s.top, 2))
            return "a cylinder from " + text(s.bottom) + " to " + text(s.top) +
                   " is not a prism along z; expected bottom and top differing in z only";
          if (std::min(s.bottom(2), s.top(2)) > 0.0 || std::max(s.bottom(2), s.top(2)) < 0.0)
            return "a cylinder from " + text(s.bottom) + " to " + text(s.top) +
                   " misses the plane z = 0 that a plane-strain grid models";
          if constexpr (std::is_same_v<T, HollowCylinder>) {
            if (s.cap_thickness > 0.0)
              return "a hollow_cylinder with a cap is not a prism along z; expected "
                     "cap_thickness 0";
          }
          return "";
        } else {
          for (std::size_t i = 0; i < s.parts.size(); ++i) {
            const std::string why = prism_problem(s.parts[i]);
            if (!why.empty()) return "union part " + std::to_string(i) + ": " + why;
          }
          return "";
        }
      },
      g.shape);
}

double section_area(const Geometry& g) {
  constexpr double pi = std::numbers::pi;
  return std::visit(
      [&](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return (s.upper(0) - s.lower(0)) * (s.upper(1) - s.lower(1));
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return pi * s.radius * s.radius;  // no plane-strain form: refused by the reader
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return pi * s.radius * s.radius;
        } else if constexpr (std::is_same_v<T, HollowCylinder>) {
          const double ri = s.radius - s.thickness;
          return pi * (s.radius * s.radius - ri * ri);
        } else {  // a shared part once (geometry.hpp)
          const std::vector<double> shared = union_overlap_shares(s, true);
          double a = 0.0;
          for (std::size_t k = 0; k < s.parts.size(); ++k)
            a += section_area(s.parts[k]) * (1.0 - shared[k]);
          return a;
        }
      },
      g.shape);
}

// The meridian half-section y >= 0 of a body of revolution about x.
double meridian_area(const Geometry& g) {
  constexpr double pi = std::numbers::pi;
  return std::visit(
      [&](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return (s.upper(0) - s.lower(0)) * (s.upper(1) - s.lower(1));  // refused by the reader
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return 0.5 * pi * s.radius * s.radius;
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return (s.top - s.bottom).norm() * s.radius;
        } else if constexpr (std::is_same_v<T, HollowCylinder>) {
          // the wall over the whole length, the cap inside it (geometry.cpp inside())
          return (s.top - s.bottom).norm() * s.thickness +
                 s.cap_thickness * (s.radius - s.thickness);
        } else {
          double a = 0.0;  // an estimate of the seed count: a shared part counts twice
          for (const Geometry& p : s.parts) a += meridian_area(p);
          return a;
        }
      },
      g.shape);
}

}  // namespace impact::mpm
