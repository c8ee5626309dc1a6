#include "mpm/scene/face_motion.hpp"

#include <algorithm>
#include <cmath>

namespace impact::mpm {

FaceMotions::FaceMotions(const GridSpec& grid, const NamedConstants& constants) {
  for (int f = 0; f < 6; ++f) {
    const FaceMotion& m = grid.face_velocity[f];
    if (m.text.empty()) {
      numbers_[f] = m.value;
      continue;
    }
    VectorExpression e;  // the velocity as the first component of a field of t alone
    e.text[0] = m.text;
    fields_[f].emplace(e, constants);
  }
}

std::array<double, 6> FaceMotions::at(double t) {
  std::array<double, 6> v = numbers_;
  for (int f = 0; f < 6; ++f)
    if (fields_[f]) v[f] = (*fields_[f])(Vec3::Zero(), t)(0);
  return v;
}

FaceTravel face_travel(const GridSpec& grid, const NamedConstants& constants, double t_end) {
  FaceMotions motions(grid, constants);
  FaceTravel travel;
  std::array<double, 6> position{};
  constexpr int kIntervals = 1000;
  const double dt = t_end / kIntervals;
  std::array<double, 6> v0 = motions.at(0.0);
  travel.initial = v0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double t = i * dt;
    const std::array<double, 6> v1 = i == 0 ? v0 : motions.at(t);
    for (int f = 0; f < 6; ++f) {
      if (!std::isfinite(v1[f])) {
        if (!travel.non_finite_at[f]) travel.non_finite_at[f] = t;
        continue;
      }
      if (i == 0 || !std::isfinite(v0[f])) continue;
      position[f] += 0.5 * (v0[f] + v1[f]) * dt;
      travel.largest[f] = std::max(travel.largest[f], std::abs(position[f]));
      const double out = f % 2 == 0 ? -position[f] : position[f];
      travel.outward[f] = std::max(travel.outward[f], out);
    }
    v0 = v1;
  }
  return travel;
}

}  // namespace impact::mpm
