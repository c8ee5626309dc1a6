#include "mpm/scene/fitted_range.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include "models/core/input.hpp"

namespace impact::mpm {

namespace {

// The extent of a box along the unit direction d [m].
double extent_along(const std::pair<Vec3, Vec3>& box, const Vec3& d) {
  return (box.second - box.first).cwiseAbs().dot(d.cwiseAbs());
}

}  // namespace

double nominal_strain_rate(const Scene& scene, std::size_t o) {
  const SceneObject& object = scene.objects[o];
  const auto box = bounds(object.geometry);
  double rate = 0.0;
  // Every other object it approaches (two bodies flying apart load neither): the relative speed
  // over its extent along it. Approaching: the bounding boxes overlap on every axis (nested
  // bodies, a rod in a sleeve), or on an axis along which they are apart (or touch) the relative
  // velocity closes the gap.
  for (std::size_t q = 0; q < scene.objects.size(); ++q) {
    if (q == o) continue;
    const Vec3 v = object.velocity - scene.objects[q].velocity;
    const double speed = v.norm();
    if (speed == 0.0) continue;
    const auto other = bounds(scene.objects[q].geometry);
    bool apart = false, closing = false;
    for (int a = 0; a < 3; ++a) {
      if (other.first(a) >= box.second(a)) {  // the other lies beyond along +a
        apart = true;
        closing = closing || v(a) > 0.0;
      } else if (other.second(a) <= box.first(a)) {  // beyond along -a
        apart = true;
        closing = closing || v(a) < 0.0;
      }
    }
    if (apart && !closing) continue;
    const double length = extent_along(box, v / speed);
    if (length > 0.0) rate = std::max(rate, speed / length);
  }
  // Every face that holds (a wall, a mirror: the image of an impact on a rigid wall, a fixed
  // face) and that the body moves toward: the normal speed over the extent along the normal.
  const GridSpec& g = scene.grid;
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2;
    if (!g.is_domain_face(f) || g.faces[f] == FaceCondition::free) continue;
    const double toward = (f % 2 == 0 ? -1.0 : 1.0) * object.velocity(axis);
    const double length = box.second(axis) - box.first(axis);
    if (toward > 0.0 && length > 0.0) rate = std::max(rate, toward / length);
  }
  return rate;
}

std::vector<std::string> fitted_range_warnings(const Scene& scene) {
  std::vector<std::string> warnings;
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& material = scene.materials[m].material;
    if (!material.fitted_range) continue;
    const FittedRange& f = *material.fitted_range;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
      if (scene.objects[o].material != int(m)) continue;
      const double rate = nominal_strain_rate(scene, o);
      const double temperature = scene.objects[o].temperature;
      const bool fast = rate > f.strain_rate_max;
      const bool hot = temperature > f.temperature_max || temperature < f.temperature_min;
      if (!fast && !hot) continue;
      std::ostringstream w;
      w.precision(3);
      w << scene.file << ": /materials/" << pointer_token(scene.materials[m].name)
        << "/file: " << material.file << " was fitted on strain rates " << f.strain_rate_min
        << " to " << f.strain_rate_max << " /s and temperatures " << f.temperature_min << " to "
        << f.temperature_max << " K (its fitted_range); object " << scene.objects[o].name;
      if (fast)
        w << "'s nominal strain rate is " << rate
          << " /s (its speed relative to what it hits over its length)";
      if (fast && hot) w << " and";
      if (hot) w << (fast ? " its" : "'s") << " initial temperature " << temperature << " K";
      w << ": the flow stress extrapolates its fit there (docs/models.md, fitted_range)";
      warnings.push_back(w.str());
      break;  // one warning per material
    }
  }
  return warnings;
}

}  // namespace impact::mpm
