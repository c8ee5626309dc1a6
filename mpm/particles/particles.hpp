// Material points in structure-of-arrays storage: one std::vector per field, index p throughout.
// The constitutive history (stress, F, R, plastic strain, temperature, damage, ...) is the
// library's PointState, so a new model variable costs no change here.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <tuple>
#include <vector>

#include "models/core/aggregate_arity.hpp"
#include "models/core/point_state.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/scene/seed_points.hpp"

namespace impact::mpm {

struct Particles {
  std::vector<Vec3> x;                  ///< position [m]
  std::vector<Vec3> v;                  ///< velocity [m/s]
  std::vector<double> mass;             ///< [kg], constant
  std::vector<double> volume0;          ///< initial volume [m^3]
  std::vector<double> volume;           ///< current volume V0 det F [m^3]
  std::vector<Mat3> L;                  ///< velocity gradient of the last step [1/s]
  std::vector<PointState> state;        ///< stress, F, history (models/core/point_state.hpp)
  std::vector<double> wave_speed;       ///< longitudinal sound speed of the last update [m/s]
  std::vector<std::uint16_t> material;  ///< index into Scene::materials
  std::vector<std::uint16_t> object;    ///< index into Scene::objects (GIMP half-width, output)
  std::vector<std::uint16_t> field;     ///< velocity field (Scene::field_count; 0 if one field)
  /// Artificial bulk viscosity q of the last update [Pa] (report eq. 12); empty when it is off.
  std::vector<double> q;
  /// 1: the particle's update had a numerical fault and physics.on_numerical_fault =
  /// fail_particle flagged it (it keeps mass and momentum, has zero stress and no further
  /// update); 0: none. Empty when the scene stops on a fault.
  std::vector<std::uint8_t> fault;
  /// 1: the particle left the grid and was removed (grid.outflow = remove): its mass, momentum
  /// and kinetic energy went to the ledger's outflow columns, it keeps zero mass, volume, stress
  /// and velocity, parked inside the grid where it left, and takes no further part in the step;
  /// 0: in play. Empty unless grid.outflow = remove.
  std::vector<std::uint8_t> removed;
  /// The particle's seed index, the same on any number of ranks (mpm/parallel/migration.hpp: a
  /// rank holds some particles, in any order) and in a shuffled store (solver.shuffle_particles);
  /// empty on one rank in seed order, where it is the array index.
  std::vector<std::uint64_t> id;
  /// Reference (seed) position X [m], what the body forces' expressions and the exact
  /// displacement read (scene/expression.hpp); empty unless the scene has either.
  std::vector<Vec3> X;
  /// uGIMP half-width per axis [m] on a graded grid (scene/seed_points.hpp seeded_half_width:
  /// half the sub-cell of the cell it was seeded in, fixed then); empty on a uniform grid, where
  /// the object's half-width in cells serves.
  std::vector<Vec3> half_width;
  /// Anchor a_p [m] of the particle's stick spring against a rigid surface, Coulomb friction at
  /// the particles (contact/rigid_particle_contact.hpp): the point it sticks to, carried with the
  /// surface; x_p itself where it touches nothing. Empty unless rigid_contact = "particles" with
  /// contact.mu > 0.
  std::vector<Vec3> friction_anchor;
  /// The velocity the particle moved with over the last step, (x^n - x^{n-1}) / dt [m/s] (its
  /// initial velocity at the start): what the penalty's dashpot at the particles damps
  /// (contact/rigid_particle_contact.hpp, "damping"). Empty unless that contact is damped.
  std::vector<Vec3> damper_velocity;

  /// f(array) for every per-particle array of kParticleArrays (below), optional ones (q, fault,
  /// removed, id, X) included even when empty: what moves a particle whole (migration between
  /// ranks), resizes, filters and checkpoints the particles visits the table, so a new field is one
  /// member here, one line there and its use.
  template <class F>
  void for_each_array(F&& f);
  template <class F>
  void for_each_array(F&& f) const;

  std::size_t size() const { return x.size(); }

  /// Reserves n particles in every array that is not optional.
  void reserve(std::size_t n);
  /// Keeps the particles p with keep[p] != 0, in order, in every array in use.
  void keep_only(const std::vector<char>& keep);
  /// Reorders every array in use: particle i takes particle order[i]'s data (order a permutation
  /// of 0 .. size() - 1).
  void permute(const std::vector<std::size_t>& order);
  /// Storage per particle [bytes] of the arrays that are not optional (for `mpm check` and the
  /// benchmark; mpm/run/memory.cpp adds the optional ones a scene uses).
  static std::size_t bytes_per_particle();
};

/// One per-particle array: its name (the checkpoint's tag), its SI unit ("-" for indices, codes
/// and flags; a 2D grid's extensive values are per metre of thickness or per ring,
/// scene/grid_geometry.hpp), where it lives, and whether it is optional (empty unless the scene
/// uses it).
template <class T>
struct ParticleArray {
  using Element = T;
  const char* name;
  const char* unit;
  std::vector<T> Particles::*member;
  bool optional;
};

/// Every array of Particles, in declaration order (the order of a checkpoint and of a migrated
/// particle's record). The particle snapshots' fields: mpm/particles/snapshot_fields.hpp.
inline constexpr auto kParticleArrays = std::make_tuple(
    ParticleArray<Vec3>{"x", "m", &Particles::x, false},
    ParticleArray<Vec3>{"v", "m/s", &Particles::v, false},
    ParticleArray<double>{"mass", "kg", &Particles::mass, false},
    ParticleArray<double>{"volume0", "m^3", &Particles::volume0, false},
    ParticleArray<double>{"volume", "m^3", &Particles::volume, false},
    ParticleArray<Mat3>{"L", "1/s", &Particles::L, false},
    ParticleArray<PointState>{"state", "-", &Particles::state, false},  // kPointStateMembers
    ParticleArray<double>{"wave_speed", "m/s", &Particles::wave_speed, false},
    ParticleArray<std::uint16_t>{"material", "-", &Particles::material, false},
    ParticleArray<std::uint16_t>{"object", "-", &Particles::object, false},
    ParticleArray<std::uint16_t>{"field", "-", &Particles::field, false},
    ParticleArray<double>{"q", "Pa", &Particles::q, true},
    ParticleArray<std::uint8_t>{"fault", "-", &Particles::fault, true},
    ParticleArray<std::uint8_t>{"removed", "-", &Particles::removed, true},
    ParticleArray<std::uint64_t>{"id", "-", &Particles::id, true},
    ParticleArray<Vec3>{"X", "m", &Particles::X, true},
    ParticleArray<Vec3>{"half_width", "m", &Particles::half_width, true},
    ParticleArray<Vec3>{"friction_anchor", "m", &Particles::friction_anchor, true},
    ParticleArray<Vec3>{"damper_velocity", "m/s", &Particles::damper_velocity, true});

static_assert(aggregate_arity<Particles>() == std::tuple_size_v<decltype(kParticleArrays)>,
              "a Particles array is missing from kParticleArrays");

/// The seed index of particle p: Particles::id where it is kept (several ranks, a shuffled store),
/// else the array index (one rank in seed order).
inline std::uint64_t seed_index(const Particles& P, std::size_t p) {
  return P.id.empty() ? p : P.id[p];
}

/// f(line) for every line of kParticleArrays, in order.
template <class F>
constexpr void for_each_particle_array(F&& f) {
  std::apply([&](const auto&... a) { (f(a), ...); }, kParticleArrays);
}

template <class F>
void Particles::for_each_array(F&& f) {
  for_each_particle_array([&](const auto& a) { f(this->*a.member); });
}
template <class F>
void Particles::for_each_array(F&& f) const {
  for_each_particle_array([&](const auto& a) { f(this->*a.member); });
}

/// Seeds every object at the ppc^3 sub-cell centres of the grid cells that lie inside its
/// geometry; a point already claimed by an earlier object is skipped. mass = rho0 * cell/ppc^3.
Particles seed_particles(const Scene& scene);

/// Seed points per object and grid cell column along x: counts[object][i] is how many of
/// seed_particles()' points of that object lie in cells i (nothing is stored).
using SeedCounts = std::vector<std::vector<std::size_t>>;
SeedCounts seed_counts_per_column(const Scene& scene);

/// Seed points per cell along each axis, all objects together (what the boxes of a domain
/// decomposition are balanced by), counted in the same pass as seed_counts_per_column.
using SeedAxisCounts = std::array<std::vector<std::size_t>, 3>;
SeedCounts seed_counts_per_column(const Scene& scene, SeedAxisCounts* per_axis);
/// The same counted in the cell columns [first, end) along x only (zero elsewhere): the census
/// of several ranks, each counting a block of columns, the blocks' counts then summed. `each`,
/// when given, also sees every point's cell (i, j, k), in seed order.
SeedCounts seed_counts_per_column(
    const Scene& scene, SeedAxisCounts* per_axis, int first, int end,
    const std::function<void(const std::array<int, 3>&)>& each = nullptr);

/// What seed_particles() creates in the cell columns [first, end) only, in the same order, with
/// the same doubles, and each with its seed index (Particles::id: its index in seed_particles());
/// `counts`: seed_counts_per_column(scene). One x range of cell columns, seeded without the rest.
Particles seed_columns(const Scene& scene, int first, int end, const SeedCounts& counts);

/// What seed_particles() creates in the cells [first_d, end_d) per axis only (one rank's box), as
/// seed_columns() does for columns: it walks its x range's points for their seed indices but
/// stores only its own, in exactly reserved arrays (no more than the box's share at any time).
Particles seed_box(const Scene& scene, const std::array<int, 3>& first,
                   const std::array<int, 3>& end, const SeedCounts& counts);

}  // namespace impact::mpm
