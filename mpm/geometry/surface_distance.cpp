#include "mpm/geometry/surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace impact::mpm {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

SurfaceDistance union_distance(const std::vector<Geometry>& parts, const Vec3& x, bool prism_z);

double sign(double x) {
  return x > 0.0 ? 1.0 : x < 0.0 ? -1.0 : 0.0;
}

// The distance to a box given, per direction k, how far outside its face pair the point lies
// (q[k] = |p_k| - half-extent_k) and the unit outward normal of the nearer face (face[k]; zero
// where the point is midway between the faces); q = -inf for a direction with no faces. Outside:
// the Euclidean distance to the nearest point; inside: the nearest face (faces equally near
// share the normal).
template <int N>
SurfaceDistance box_distance(const double (&q)[N], const Vec3 (&face)[N]) {
  double outside = 0.0;
  Vec3 out = Vec3::Zero();
  for (int k = 0; k < N; ++k)
    if (q[k] > 0.0) {
      outside += q[k] * q[k];
      out += q[k] * face[k];
    }
  if (outside > 0.0) {
    const double d = std::sqrt(outside);
    return {d, out / d};
  }
  double nearest = -kInf;
  for (int k = 0; k < N; ++k) nearest = std::max(nearest, q[k]);
  // Faces within round-off of the nearest are equally near (an edge, a corner).
  const double tie = 1e-12 * std::max(1.0, std::abs(nearest));
  Vec3 n = Vec3::Zero();
  for (int k = 0; k < N; ++k)
    if (q[k] >= nearest - tie) n += face[k];
  const double norm = n.norm();
  return {nearest, norm > 0.0 ? Vec3(n / norm) : Vec3::Zero()};
}

SurfaceDistance of_box(const Box& b, const Vec3& x, bool prism_z) {
  const Vec3 c = 0.5 * (b.lower + b.upper), half = 0.5 * (b.upper - b.lower), p = x - c;
  double q[3];
  Vec3 face[3];
  for (int d = 0; d < 3; ++d) {
    q[d] = std::abs(p(d)) - half(d);
    face[d] = sign(p(d)) * Vec3::Unit(d);
  }
  if (prism_z) q[2] = -kInf;
  return box_distance(q, face);
}

SurfaceDistance of_sphere(const Sphere& s, const Vec3& x) {
  const Vec3 p = x - s.center;
  const double r = p.norm();
  return {r - s.radius, r > 0.0 ? Vec3(p / r) : Vec3::Zero()};
}

// A body of revolution's nearest surface lies in the meridian half-plane of x: the axial
// coordinate s along e from `origin` and the distance r from the axis. A rectangle of that
// half-plane, s in [s_lo, s_hi] and r in [r_lo, r_hi] (r_lo = 0: it reaches the axis, which is no
// face), revolved: a cylinder, or a tube's wall. `cap_free`: no faces across s (a prism along its
// axis).
SurfaceDistance of_meridian_rectangle(const Vec3& origin, const Vec3& e, double s_lo, double s_hi,
                                      double r_lo, double r_hi, const Vec3& x, bool cap_free) {
  const Vec3 p = x - origin;
  const double s = p.dot(e);
  const Vec3 radial = p - s * e;
  const double r = radial.norm();
  const Vec3 out = r > 0.0 ? Vec3(radial / r) : Vec3::Zero();
  const double s_mid = 0.5 * (s_lo + s_hi);
  const double q_s = cap_free ? -kInf : std::abs(s - s_mid) - 0.5 * (s_hi - s_lo);
  if (r_lo <= 0.0) {  // from the axis out: one radial face
    const double q[2] = {r - r_hi, q_s};
    const Vec3 face[2] = {out, sign(s - s_mid) * e};
    return box_distance(q, face);
  }
  const double r_mid = 0.5 * (r_lo + r_hi);
  const double q[2] = {std::abs(r - r_mid) - 0.5 * (r_hi - r_lo), q_s};
  const Vec3 face[2] = {sign(r - r_mid) * out, sign(s - s_mid) * e};
  return box_distance(q, face);
}

// Whether a cylinder's axis lies along z (a prism along z: its ends are no surfaces).
bool along_z(const Vec3& bottom, const Vec3& top) {
  const Vec3 e = (top - bottom).normalized();
  return std::abs(e(0)) < 1e-12 && std::abs(e(1)) < 1e-12;
}

// Of two distances, the nearer surface: outside both, the smaller distance (a union's, exact);
// `inside`, the larger, the face less deep. Equally near (a point on the bisector of two faces,
// in the corner they make), their normals' mean, normalised, as at a box's edge.
SurfaceDistance nearer(const SurfaceDistance& a, const SurfaceDistance& b, bool inside = false) {
  if (!std::isfinite(a.distance)) return b;
  const double tie = 1e-12 * std::max({1.0, std::abs(a.distance), std::abs(b.distance)});
  if (std::abs(a.distance - b.distance) > tie) return (b.distance < a.distance) != inside ? b : a;
  const Vec3 n = a.outward + b.outward;
  const double norm = n.norm();
  return {a.distance, norm > 0.0 ? Vec3(n / norm) : Vec3::Zero()};
}

// A union. Outside every part, the nearest part's distance is the union's (exact). Inside, a
// part's nearest face may be buried in another part (two boxes that touch: their shared face; an
// overlap): its foot point x - d n, just past the face, lies inside that other part, and the
// face is no surface of the union. The nearest face of a part that holds x and is not buried
// serves; none (x beside a joint, its faces all buried): no direction (zero normal). Before this
// screen the joint of two touching rigid boxes read as a surface at any depth, and a block
// resting over it was pushed sideways (issue 53's audit).
SurfaceDistance union_distance(const std::vector<Geometry>& parts, const Vec3& x, bool prism_z) {
  std::vector<SurfaceDistance> d;
  d.reserve(parts.size());
  bool inside_any = false;
  for (const Geometry& part : parts) {
    d.push_back(surface_distance(part, x, prism_z));
    inside_any = inside_any || d.back().distance <= 0.0;
  }
  SurfaceDistance best{kInf, Vec3::Zero()};
  if (!inside_any) {
    for (const SurfaceDistance& k : d) best = nearer(best, k);
    return best;
  }
  std::vector<std::size_t> open;  // the parts holding x whose nearest face is not buried
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (d[k].distance > 0.0 || d[k].outward.squaredNorm() == 0.0) continue;
    const double past = std::max(1e-9 * std::abs(d[k].distance), 1e-15);
    const Vec3 foot = x - (d[k].distance - past) * d[k].outward;
    bool buried = false;
    for (std::size_t j = 0; j < parts.size() && !buried; ++j)
      buried = j != k && inside(parts[j], foot);
    if (!buried) open.push_back(k);
  }
  const bool found = !open.empty();
  for (const std::size_t k : open) best = nearer(best, d[k], true);
  if (found) return best;
  double deepest = 0.0;  // no unburied face: the depth of the deepest part, no direction
  for (const SurfaceDistance& k : d) deepest = std::min(deepest, k.distance);
  return {deepest, Vec3::Zero()};
}

}  // namespace

SurfaceDistance surface_distance(const Geometry& g, const Vec3& x, bool prism_z) {
  return std::visit(
      [&](const auto& s) -> SurfaceDistance {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return of_box(s, x, prism_z);
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return of_sphere(s, x);
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          const Vec3 e = (s.top - s.bottom).normalized();
          const double length = (s.top - s.bottom).norm();
          return of_meridian_rectangle(s.bottom, e, 0.0, length, 0.0, s.radius, x,
                                       prism_z && along_z(s.bottom, s.top));
        } else if constexpr (std::is_same_v<T, HollowCylinder>) {
          const Vec3 e = (s.top - s.bottom).normalized();
          const double length = (s.top - s.bottom).norm();
          if (!(s.cap_thickness > 0.0))  // the wall's meridian rectangle
            return of_meridian_rectangle(s.bottom, e, 0.0, length, s.radius - s.thickness, s.radius,
                                         x, prism_z && along_z(s.bottom, s.top));
          // The open tube and its cap, a solid cylinder.
          HollowCylinder tube = s;
          tube.cap_thickness = 0.0;
          const std::vector<Geometry> parts{
              Geometry{tube},
              Geometry{Cylinder{s.bottom, s.bottom + s.cap_thickness * e, s.radius}}};
          return union_distance(parts, x, prism_z);
        } else {
          return union_distance(s.parts, x, prism_z);
        }
      },
      g.shape);
}

}  // namespace impact::mpm
