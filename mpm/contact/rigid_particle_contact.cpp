#include "mpm/contact/rigid_particle_contact.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "models/thermal/adiabatic_heating.hpp"
#include "mpm/geometry/surface_distance.hpp"
#include "mpm/threads/chunk_sums.hpp"
#include "mpm/threads/threads.hpp"

namespace impact::mpm {

RigidParticleContact::RigidParticleContact(const Scene& scene,
                                           std::vector<std::optional<Geometry>> surfaces,
                                           std::vector<Vec3> velocities,
                                           std::vector<Vec3> half_widths)
    : scene_(scene),
      half_widths_(std::move(half_widths)),
      h_(scene.grid.min_spacing()),
      prism_z_(scene.grid.per_metre_of_thickness()),
      axes_(scene.grid.dimensions()) {
  const std::vector<std::optional<Vec3>> rigid = scene.rigid_field_velocities();
  const std::vector<double> rigid_mu = scene.rigid_field_friction();
  for (std::size_t f = 0; f < rigid.size(); ++f) {
    rigid_.push_back(rigid[f].has_value());
    if (!rigid[f] || !scene.rigid_contact_at_particles()) continue;
    if (f >= surfaces.size() || !surfaces[f])
      throw std::invalid_argument(
          "/physics/contact/rigid_contact: \"particles\" needs each rigid object's own surface, "
          "and a rigid object here is cut by an earlier object (its seeded body is not its "
          "geometry): place the objects apart, or use \"nodes\"");
    Surface s;
    s.geometry = std::move(surfaces[f]);
    s.velocity = f < velocities.size() ? velocities[f] : Vec3::Zero();
    s.mu = rigid_mu[f];
    s.damping = scene.physics.contact.penalty_damping;
    surfaces_.push_back(std::move(s));
  }
  // The `wall` faces (grid.wall_contact "particles"): each a plane at rest, inward . x = offset.
  const GridSpec& g = scene.grid;
  if (g.walls_at_particles())
    for (int f = 0; f < 6; ++f) {
      if (g.faces[std::size_t(f)] != FaceCondition::wall || !g.is_domain_face(f)) continue;
      const int axis = f / 2;
      const bool lower = f % 2 == 0;
      Surface s;
      s.inward = (lower ? 1.0 : -1.0) * Vec3::Unit(axis);
      s.offset = lower ? g.lower(axis) : -g.upper(axis);
      s.mu = g.wall_friction[std::size_t(f)];
      s.damping = g.wall_penalty_damping;
      surfaces_.push_back(s);
    }
  for (const Surface& s : surfaces_) {
    friction_ = friction_ || s.mu > 0.0;
    damped_ = damped_ || s.damping > 0.0;
  }
  // The closing speed the scene starts with: its fastest deformable body's and its fastest
  // rigid object's speeds added (header comment, "speed").
  double body_speed = 0.0;
  std::vector<std::uint8_t> deformable(scene.materials.size(), 0);
  for (const SceneObject& o : scene.objects) {
    if (o.rigid) continue;
    body_speed = std::max(body_speed, o.velocity.norm());
    deformable[std::size_t(o.material)] = 1;
  }
  const double closing = body_speed + scene.rigid_speed();
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const auto& p = scene.materials[i].material.model.params();
    const double c =
        std::sqrt((p.bulk_modulus + 4.0 / 3.0 * p.shear_modulus) / p.density) + closing;
    // Above time.multiplier 0.5 the stiffness falls with its square: the penalty's frequency
    // times the step stays at most 1 (at 1.5 the full stiffness, added to the elastic one, made
    // a block dropped on a floor at 600 m/s fail the energy check).
    const double slower = std::min(1.0, std::pow(0.5 / scene.time.multiplier, 2));
    stiffness_.push_back(slower * kStiffness * c * c / (h_ * h_));
    // A wall's: kWallSpeed times the closing speed (header comment, "walls").
    const double c_wall = c + (kWallSpeed - 1.0) * closing;
    wall_stiffness_.push_back(slower * kStiffness * c_wall * c_wall / (h_ * h_));
    if (deformable[i])
      signal_speed_ = std::max(signal_speed_, scene.grid.walls_at_particles() ? c_wall : c);
  }
}

namespace {
// W(delta), the contact's energy at overlap delta [J] (header comment): zero apart.
double stored_energy(double k, double onset, double delta) {
  if (!(delta > 0.0)) return 0.0;
  if (delta < onset) return k * delta * delta * delta / (6.0 * onset);
  const double beyond = delta - 0.5 * onset;
  return 0.5 * k * beyond * beyond + k * onset * onset / 24.0;
}
// dW / d delta.
double push(double k, double onset, double delta) {
  if (!(delta > 0.0)) return 0.0;
  return delta < onset ? k * delta * delta / (2.0 * onset) : k * (delta - 0.5 * onset);
}

// Coulomb's stick spring at one particle (header comment, "friction"), pushed by F_n along
// `normal` (F_n = 0: it touches nothing) by a surface moving at V. With `advance` (the time moved
// on since the last evaluation, by `carried` seconds) the anchor is carried with the surface,
// brought into the plane through x_p normal to the push, and moved where the particle slips;
// without (a second evaluation at one time, on several ranks or after a restart) it stays, and
// the same anchor gives the same bits.
struct Rub {
  Vec3 force = Vec3::Zero();  ///< f_t [N]
  double energy = 0.0;        ///< the spring's k |s|^2 / 2 [J]
  double heat = 0.0;          ///< the slip's mu F_n (|s*| - |s|) [J]
};
Rub stick_or_slip(Vec3& anchor, const Vec3& x, double F_n, const Vec3& normal, const Vec3& V,
                  bool advance, double carried, double k, double mu) {
  Rub rub;
  if (!(F_n > 0.0)) {  // free: the spring is slack; the anchor waits where the particle is
    if (advance) anchor = x;
    return rub;
  }
  const auto stretch = [&] {  // the spring's extension along the surface, from the anchor
    const Vec3 d = x - anchor;
    return Vec3(d - d.dot(normal) * normal);
  };
  const double longest = mu * F_n / k;  // Coulomb's bound on |s| [m]
  Vec3 s;
  if (advance) {
    anchor += carried * V;
    s = stretch();   // the trial s*
    anchor = x - s;  // in the plane normal to the push: the force is the energy's gradient
    const double length = s.norm();
    if (length > longest) {  // slips: back onto Coulomb's cone; the slip's work is heat
      anchor = x - (longest / length) * s;
      rub.heat = mu * F_n * (length - longest);
    }
  }
  s = stretch();  // from the stored anchor, as a second evaluation finds it
  const double length = s.norm();
  if (length > longest) s *= longest / length;  // round-off beyond the cone
  rub.force = -k * s;
  rub.energy = 0.5 * k * s.squaredNorm();
  return rub;
}
}  // namespace

SurfaceDistance RigidParticleContact::distance(const Surface& s, const Vec3& x, double t) const {
  if (s.geometry) return surface_distance(*s.geometry, x - s.velocity * t, prism_z_);
  return {s.inward.dot(x) - s.offset, s.inward};  // a wall's plane
}

void RigidParticleContact::evaluate(Particles& P, double t, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  force_.resize(P.size());
  const bool friction = friction_;
  const bool damped = damped_;
  // The anchors are carried with their surfaces over the time since the last evaluation (none at
  // the first, also after a restart: the checkpoint's anchors were carried to its time).
  const double carried = last_time_ ? t - *last_time_ : 0.0;
  const bool advance = carried > 0.0;
  last_time_ = t;
  if (damped) {  // the dashpots' forces, and where they act from: their work over the step
    if (P.damper_velocity.size() != P.size())
      throw std::logic_error("RigidParticleContact::evaluate: no damper velocity per particle");
    // The velocity each particle moved with since the last evaluation, in the same order (the
    // step's: on several ranks the last one came after the migration); a second evaluation at
    // the same time reads the stored one (header comment, "damping").
    if (advance)
      for (std::size_t p = 0; p < std::min(P.size(), evaluated_at_.size()); ++p)
        P.damper_velocity[p] = (P.x[p] - evaluated_at_[p]) / carried;
    damper_force_.assign(P.size(), Vec3::Zero());
    evaluated_at_ = P.x;
  }
  if (friction && P.friction_anchor.size() != P.size())
    throw std::logic_error("RigidParticleContact::evaluate: no friction anchor per particle");
  const double onset = kOnset * h_;  // delta_s [m]
  const bool outflow = !P.removed.empty();
  struct Sums {
    double energy = 0.0, power = 0.0, heat = 0.0, damper_power = 0.0;
    Vec3 force = Vec3::Zero();
  };
  // Per chunk, then in chunk order: the same bits on any thread count (threads/chunk_sums.hpp).
  ChunkSums<Sums> sums(n, 512);
  const std::ptrdiff_t chunks = sums.chunks();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t chunk = 0; chunk < chunks; ++chunk) {
    Sums& sum = sums[chunk];
    for (std::ptrdiff_t p = sums.begin(chunk); p < sums.end(chunk); ++p) {
      Vec3& f_p = force_[p];
      f_p.setZero();
      // The surface with the largest Coulomb bound mu F: its friction acts (header comment,
      // "corners").
      double rub_push = 0.0, bound = -1.0;  // its push F_n [N] and mu F_n
      std::size_t rubbing = 0;
      Vec3 rubbing_normal = Vec3::Zero();
      const std::size_t field = P.field[p];
      if ((field < rigid_.size() && rigid_[field]) || (outflow && P.removed[p]) ||
          !(P.mass[p] > 0.0)) {
        if (friction) P.friction_anchor[p] = P.x[p];
        continue;
      }
      const std::uint16_t object = P.object[p];
      // The domain's reach: the largest sphere in it (its smallest half-width over the mesh's
      // axes), no further than the seed point lay inside its own object's geometry. The seed
      // point's distances are measured only for a particle within that sphere of a surface: the
      // clips only shorten the reach, and most particles lie further away.
      const Vec3& l = P.half_width.empty() ? half_widths_[object] : P.half_width[p];
      double widest = l(0);
      for (int d = 1; d < axes_; ++d) widest = std::min(widest, l(d));
      double reach = -1.0;  // not yet clipped
      double rub_k = 0.0;   // the rubbing surface's k_p [N/m]
      for (std::size_t r = 0; r < surfaces_.size(); ++r) {
        const Surface& surface = surfaces_[r];
        const SurfaceDistance s = distance(surface, P.x[p], t);
        if (!(widest - s.distance > 0.0)) continue;  // no overlap, whatever the clips
        const bool wall = !surface.geometry;
        const double k =
            (wall ? wall_stiffness_ : stiffness_)[P.material[p]] * P.mass[p];  // k_p [N/m]
        if (reach < 0.0 && !wall)
          reach = std::min(
              widest,
              std::max(
                  0.0,
                  -surface_distance(scene_.objects[object].geometry, P.X[p], prism_z_).distance));
        const Vec3& normal = s.outward;
        if (normal.squaredNorm() == 0.0) continue;  // no direction (a joint, an axis): no push
        // ... nor further than the seed point lay from this object as seeded: a body seeded
        // around a rigid object (cut by it) starts without overlap too.
        const double seeded = distance(surface, P.X[p], 0.0).distance;
        const double overlap = std::min(wall ? widest : reach, std::max(0.0, seeded)) - s.distance;
        if (!(overlap > 0.0)) continue;
        // The push, with the dashpot's -c u_n where damped.
        double F = push(k, onset, overlap);
        if (surface.damping > 0.0) {
          const double u_n =
              (P.damper_velocity[p] - surface.velocity).dot(normal);  // < 0: approaching
          const double F_d = std::max(
              -F, -2.0 * surface.damping * std::sqrt(k * P.mass[p]) * u_n);  // never a pull
          damper_force_[p] += F_d * normal;
          sum.damper_power += F_d * normal.dot(surface.velocity);
          F += F_d;
        }
        const Vec3 f = F * normal;
        f_p += f;
        if (F > 0.0 && surface.mu * F > bound) {
          bound = surface.mu * F;
          rub_push = F;
          rub_k = k;
          rubbing = r;
          rubbing_normal = normal;
        }
        sum.energy += stored_energy(k, onset, overlap);
        sum.force += f;
        sum.power += f.dot(surface.velocity);
      }
      if (!friction) continue;
      const Vec3 V = rub_push > 0.0 ? surfaces_[rubbing].velocity : Vec3::Zero();
      const double mu = rub_push > 0.0 ? surfaces_[rubbing].mu : 0.0;
      const Rub rub = stick_or_slip(P.friction_anchor[p], P.x[p], rub_push, rubbing_normal, V,
                                    advance, carried, rub_k, mu);
      if (rub.heat > 0.0) {
        const auto& params = scene_.materials[P.material[p]].material.model.params();
        retain_heat(P.state[p], rub.heat / P.mass[p], params.heating.enabled, params.specific_heat);
      }
      f_p += rub.force;
      sum.energy += rub.energy;
      sum.heat += rub.heat;
      sum.force += rub.force;
      sum.power += rub.force.dot(V);
    }
  }
  Sums total;
  sums.add_in_order([&](const Sums& s) {
    total.energy += s.energy;
    total.power += s.power;
    total.heat += s.heat;
    total.damper_power += s.damper_power;
    total.force += s.force;
  });
  energy_ = total.energy;
  power_ = total.power;
  heat_ = total.heat;
  damper_power_ = total.damper_power;
  total_force_ = total.force;
}

double RigidParticleContact::damper_work(const Particles& P, double dt, int threads) const {
  if (!damped_) return 0.0;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(std::min(P.size(), evaluated_at_.size()));
  ChunkSums<double> sums(n, 512);
  const std::ptrdiff_t chunks = sums.chunks();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t chunk = 0; chunk < chunks; ++chunk)
    for (std::ptrdiff_t p = sums.begin(chunk); p < sums.end(chunk); ++p)
      sums[chunk] -= damper_force_[p].dot(P.x[p] - evaluated_at_[p]);
  double taken = dt * damper_power_;  // the dashpots' work at the surfaces' velocities, -f_d . V dt
  sums.add_in_order([&](double s) { taken += s; });
  return taken;
}

}  // namespace impact::mpm
