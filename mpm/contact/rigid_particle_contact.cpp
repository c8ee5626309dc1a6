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
      surfaces_(std::move(surfaces)),
      velocities_(std::move(velocities)),
      half_widths_(std::move(half_widths)),
      h_(scene.grid.min_spacing()),
      prism_z_(scene.grid.per_metre_of_thickness()),
      axes_(scene.grid.dimensions()),
      mu_(scene.physics.contact.mu),
      damping_(scene.physics.contact.penalty_damping) {
  const std::vector<std::optional<Vec3>> rigid = scene.rigid_field_velocities();
  for (std::size_t f = 0; f < rigid.size(); ++f) {
    rigid_.push_back(rigid[f].has_value());
    if (rigid[f] && (f >= surfaces_.size() || !surfaces_[f]))
      throw std::invalid_argument(
          "/physics/contact/rigid_contact: \"particles\" needs each rigid object's own surface, "
          "and a rigid object here is cut by an earlier object (its seeded body is not its "
          "geometry): place the objects apart, or use \"nodes\"");
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
    if (deformable[i]) signal_speed_ = std::max(signal_speed_, c);
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

void RigidParticleContact::evaluate(Particles& P, double t, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  force_.resize(P.size());
  const bool friction = mu_ > 0.0;
  const bool damped = damping_ > 0.0;
  if (damped) {  // the dashpots' forces, and where they act from: their work over the step
    damper_force_.assign(P.size(), Vec3::Zero());
    evaluated_at_ = P.x;
  }
  // The anchors are carried with their surfaces over the time since the last evaluation (none at
  // the first, also after a restart: the checkpoint's anchors were carried to its time).
  const double carried = last_time_ ? t - *last_time_ : 0.0;
  const bool advance = carried > 0.0;
  last_time_ = t;
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
      // The surface that pushes hardest: its friction acts (header comment, "corners").
      double hardest = 0.0;
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
      double reach = -1.0;                                     // not yet clipped
      const double k = stiffness_[P.material[p]] * P.mass[p];  // k_p [N/m]
      for (std::size_t r = 0; r < surfaces_.size(); ++r) {
        if (!surfaces_[r]) continue;
        const SurfaceDistance s =
            surface_distance(*surfaces_[r], P.x[p] - velocities_[r] * t, prism_z_);
        if (!(widest - s.distance > 0.0)) continue;  // no overlap, whatever the clips
        if (reach < 0.0)
          reach = std::min(
              widest,
              std::max(
                  0.0,
                  -surface_distance(scene_.objects[object].geometry, P.X[p], prism_z_).distance));
        const Vec3& normal = s.outward;
        if (normal.squaredNorm() == 0.0) continue;  // no direction (a joint, an axis): no push
        // ... nor further than the seed point lay from this object as seeded: a body seeded
        // around a rigid object (cut by it) starts without overlap too.
        const double seeded = surface_distance(*surfaces_[r], P.X[p], prism_z_).distance;
        const double overlap = std::min(reach, std::max(0.0, seeded)) - s.distance;
        if (!(overlap > 0.0)) continue;
        // The push, with the dashpot's -c u_n where damped.
        double F = push(k, onset, overlap);
        if (damped) {
          const double u_n = (P.v[p] - velocities_[r]).dot(normal);  // < 0: approaching
          const double F_d =
              std::max(-F, -2.0 * damping_ * std::sqrt(k * P.mass[p]) * u_n);  // never a pull
          damper_force_[p] += F_d * normal;
          sum.damper_power += F_d * normal.dot(velocities_[r]);
          F += F_d;
        }
        const Vec3 f = F * normal;
        f_p += f;
        if (F > hardest) {
          hardest = F;
          rubbing = r;
          rubbing_normal = normal;
        }
        sum.energy += stored_energy(k, onset, overlap);
        sum.force += f;
        sum.power += f.dot(velocities_[r]);
      }
      if (!friction) continue;
      const Vec3 V = hardest > 0.0 ? velocities_[rubbing] : Vec3::Zero();
      const Rub rub = stick_or_slip(P.friction_anchor[p], P.x[p], hardest, rubbing_normal, V,
                                    advance, carried, k, mu_);
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
  if (!(damping_ > 0.0)) return 0.0;
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
