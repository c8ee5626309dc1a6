#include "mpm/output/face_reach.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace impact::mpm {

namespace {

constexpr double kNotReached = std::numeric_limits<double>::quiet_NaN();
constexpr double kNearFraction = 0.05;  ///< of the grid's extent: "near a face at the start"

const char* condition_name(FaceCondition c) {
  switch (c) {
    case FaceCondition::symmetric:
      return "symmetric";
    case FaceCondition::fixed:
      return "fixed";
    case FaceCondition::free:
      return "free";
    case FaceCondition::wall:
      return "wall";
  }
  return "?";
}

}  // namespace

FaceReach::FaceReach(const Scene& scene, const Particles& initial, const Communicator& comm)
    : comm_(comm) {
  const GridSpec& g = scene.grid;
  first_time_.fill(kNotReached);
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2;
    // The cell at the face (graded grids: the edge cell; uniform: every cell).
    Vec3 h = Vec3::Zero();
    h(axis) = g.cell_size(axis, f % 2 == 0 ? 0 : g.cells[axis] - 1);
    condition_[f] = g.faces[f];
    plane_[f] = f % 2 == 0 ? g.lower(axis) : g.upper(axis);
    layer_[f] = h(axis);
    // "Near at the start": within one cell, or 5 % of the grid's extent along the axis when that
    // is more, so that whether a face is watched does not change with the grid (a body 3 mm from
    // a face of a 60 mm grid was near at 12 cells and far at 120; issue 52): with 20 cells or
    // more along the axis the extent decides.
    near_[f] = std::max(h(axis), kNearFraction * (g.upper(axis) - g.lower(axis)));
    // A 2D grid has no z faces; the y- face of an axisymmetric grid is its axis.
    watched_[f] = g.is_domain_face(f) && g.faces[f] != FaceCondition::wall;
  }
  const std::array<double, 6> start = count(initial, near_);
  for (int f = 0; f < 6; ++f) watched_[f] = watched_[f] && start[f] == 0.0;
}

std::array<double, 6> FaceReach::count(const Particles& P) const {
  return count(P, layer_);
}

std::array<double, 6> FaceReach::count(const Particles& P,
                                       const std::array<double, 6>& within) const {
  std::vector<double> n(6, 0.0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.mass[p] == 0.0) continue;  // removed (grid.outflow = remove)
    for (int f = 0; f < 6; ++f) {
      if (!watched_[f]) continue;
      const double d = std::abs(P.x[p](f / 2) - plane_[f]);
      if (d <= within[f]) n[f] += 1.0;
    }
  }
  n = comm_.sum(n);
  return {n[0], n[1], n[2], n[3], n[4], n[5]};
}

std::vector<int> FaceReach::sample(const Particles& P, double time) {
  bool any = false;
  for (const bool w : watched_) any = any || w;
  if (!any) return {};
  const std::array<double, 6> n = count(P);
  std::vector<int> reached;
  for (int f = 0; f < 6; ++f) {
    if (n[f] == 0.0) continue;
    if (std::isnan(first_time_[f])) {
      first_time_[f] = time;
      reached.push_back(f);
    }
    most_[f] = std::max(most_[f], n[f]);
  }
  return reached;
}

Json FaceReach::summary() const {
  Json faces = Json::array();
  for (int f = 0; f < 6; ++f) {
    if (std::isnan(first_time_[f])) continue;
    faces.push_back({{"face", kFaceNames[f]},
                     {"condition", condition_name(condition_[f])},
                     {"first_time [s]", first_time_[f]},
                     {"particles", static_cast<std::int64_t>(most_[f])}});
  }
  return faces;
}

std::string FaceReach::warning(int f) const {
  std::ostringstream m;
  m.precision(4);
  const int axis = f / 2;
  const char* key = f % 2 == 0 ? "grid.lower" : "grid.upper";
  m << "material reached the " << kFaceNames[f] << " face (" << condition_name(condition_[f])
    << ", " << key << "[" << axis << "] = " << plane_[f] << " m) at t = " << first_time_[f]
    << " s, which no body was near at the start (within one cell or 5 % of the grid's extent): "
    << (condition_[f] == FaceCondition::free
            ? "it is about to leave the grid"
            : "the face confines it (reflects or holds it) as no far field would")
    << "; results from then on are those of a smaller domain. Move " << key << "[" << axis
    << "] away, or make the face a wall if the contact is meant (summary.json "
       "material_reached_faces)";
  return m.str();
}

std::vector<double> FaceReach::state() const {
  std::vector<double> s(first_time_.begin(), first_time_.end());
  s.insert(s.end(), most_.begin(), most_.end());
  return s;
}

void FaceReach::restore(const std::vector<double>& state) {
  if (state.size() != 12) {
    throw std::invalid_argument("faces reached: " + std::to_string(state.size()) +
                                " values, expected 12");
  }
  for (int f = 0; f < 6; ++f) {
    first_time_[f] = state[std::size_t(f)];
    most_[f] = state[std::size_t(f) + 6];
  }
}

}  // namespace impact::mpm
