#include "mpm/particles/snapshot_fields.hpp"

#include <type_traits>

#include "models/core/point_state_fields.hpp"

namespace impact::mpm {

namespace {

// The name a Particles array has in a snapshot: the position is the snapshot's points, and the
// arrays of the step's own bookkeeping (L, the wave speed, q, fault, removed) are not drawn.
const char* snapshot_name(const std::string& array) {
  if (array == "v") return "velocity";
  for (const char* kept : {"mass", "volume", "material", "object", "field", "id"})
    if (array == kept) return kept;
  return nullptr;
}

template <class T>
void write_value(const T& value, double* out) {
  if constexpr (std::is_same_v<T, Vec3>) {
    for (int d = 0; d < 3; ++d) out[d] = value(d);
  } else if constexpr (std::is_same_v<T, Mat3>) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out[3 * r + c] = value(r, c);
  } else {
    *out = static_cast<double>(value);  // numbers, indices, flags (0 or 1) and codes
  }
}

template <class T>
constexpr int components_of() {
  return std::is_same_v<T, Vec3> ? 3 : std::is_same_v<T, Mat3> ? 9 : 1;
}

std::vector<SnapshotField> catalogue() {
  std::vector<SnapshotField> fields;
  for_each_particle_array([&](const auto& a) {
    using T = typename std::decay_t<decltype(a)>::Element;
    const char* name = snapshot_name(a.name);
    if constexpr (!std::is_same_v<T, PointState> && !std::is_same_v<T, Mat3>) {
      if (!name) return;
      const auto member = a.member;
      // An optional array not in use (the id on one rank) is the particle's index.
      fields.push_back({name, a.unit, components_of<T>(),
                        [member](const Particles& P, std::size_t p, double* out) {
                          const auto& values = P.*member;
                          if (values.empty())
                            *out = static_cast<double>(p);
                          else
                            write_value(values[p], out);
                        }});
    }
  });
  for_each_state_member([&](const auto& m) {
    using T = typename std::decay_t<decltype(m)>::Type;
    const auto member = m.member;
    if (std::string(m.name) == "stress") {  // symmetric: xx yy zz xy yz xz
      fields.push_back({m.name, m.unit, 6, [](const Particles& P, std::size_t p, double* out) {
                          const Mat3& s = P.state[p].stress;
                          const double c[6] = {s(0, 0), s(1, 1), s(2, 2),
                                               s(0, 1), s(1, 2), s(0, 2)};
                          for (int k = 0; k < 6; ++k) out[k] = c[k];
                        }});
      return;
    }
    fields.push_back({m.name, m.unit, components_of<T>(),
                      [member](const Particles& P, std::size_t p, double* out) {
                        write_value(P.state[p].*member, out);
                      }});
  });
  fields.push_back({"pressure", "Pa", 1, [](const Particles& P, std::size_t p, double* out) {
                      *out = -mean(P.state[p].stress);
                    }});
  fields.push_back({"von_mises", "Pa", 1, [](const Particles& P, std::size_t p, double* out) {
                      *out = von_mises(P.state[p].stress);
                    }});
  return fields;
}

}  // namespace

const std::vector<SnapshotField>& snapshot_fields() {
  static const std::vector<SnapshotField> fields = catalogue();
  return fields;
}

const SnapshotField* find_snapshot_field(const std::string& name) {
  for (const SnapshotField& f : snapshot_fields())
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace impact::mpm
