// The phases of one explicit MPM step, each a free function templated on the shape (LinearShape
// or GimpShape); advance() in mpm/solver.cpp strings them together on one screen.
// Notation: p particles, I nodes, S_Ip weights, grad S_Ip gradients (at the start-of-step x_p).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/shape.hpp"

namespace impact::mpm {

/// The first particle (lowest index) whose update failed, and why.
struct Failure {
  std::size_t particle = 0;
  std::string field;  ///< e.g. "position", "velocity", "stress"
  std::string message;
};

/// The stencils (1-D weights and derivatives, base node) of every particle at its start-of-step
/// position: computed once per step and reused by P2G, G2P and the MUSL re-map.
template <class Shape>
using Stencils = std::vector<Stencil<Shape::N>>;
template <class Shape>
void compute_stencils(const Particles& P, const Shape& shape, Stencils<Shape>& S, int threads);

/// Particles to grid (Sulsky et al. 1994 eqs. 20-22):
///   m_I = sum_p S_Ip m_p,  p_I = sum_p S_Ip m_p v_p,
///   f_I = -sum_p V_p sigma_p . grad S_Ip   (gravity is added as m_I g in grid_update).
template <class Shape>
void particles_to_grid(const Particles& P, Grid& G, const Stencils<Shape>& S);

/// USL's velocity gradient limits the acceleration part of v*_I at nodes lighter than this
/// fraction of the lightest particle mass: v^L_I = v_I + min(1, m_I/m_light) (v*_I - v_I). Why:
/// with trilinear weights a particle that has just entered a cell gives the node ahead a mass
/// S m_p -> 0 but a gradient ~ 1/dx, so dt f_I/m_I fed back through L multiplies that particle's
/// stress by about (c dt/dx)^2 / S per step (> 8 for S < 0.03 at CFL 0.5): any round-off grows
/// without bound. The limiter bounds the factor by (c dt/dx)^2 / 0.5 < 2. FLIP velocity and
/// position use the true v*_I (S_Ip dt f_I/m_I stays bounded), so momentum is untouched.
inline constexpr double kLightNodeMassFraction = 0.5;

/// Grid update (eq. 24): v_I = p_I/m_I, v*_I = v_I + dt (f_I/m_I + g); the face conditions as a
/// mirror (grid/boundary.cpp) on v_I (ghost layer) and v*_I (face and ghost layers); the FLIP
/// increment v*_I - v_I; the faces' impulse sum_I m_I (dv_I - dv_I^free) over constrained nodes;
/// for USL the gradient velocity v^L_I (kLightNodeMassFraction). Also the external (gravity)
/// impulse and work.
struct GridUpdate {
  BoundaryLoad boundary;
  Vec3 external_impulse = Vec3::Zero();
  double external_work = 0.0;
};
GridUpdate grid_update(Grid& G, double dt, const Vec3& gravity, bool usl_gradient);

/// What grid-to-particles measured on the end-of-step particle velocities (report eq. 13).
struct ParticleTotals {
  double kinetic_energy = 0.0;
  Vec3 momentum = Vec3::Zero();
  double max_speed = 0.0;  ///< max_p |v_p| [m/s]
  /// Kinetic energy the faces' velocity projection took from the particles this step:
  /// -sum_p m_p delta_p . (v_p^n + v_p^{n+1})/2, delta_p = sum_I S_Ip (P v_I - v_I), P the
  /// projection on the face layer (docs/mpm.md#ledger) [J].
  double boundary_dissipation = 0.0;
};

/// Grid to particles: FLIP velocity v_p += sum_I S_Ip (v*_I - v_I) (eq. 23), position
/// x_p += dt sum_I S_Ip v*_I (eq. 25), and with `usl_gradient` L_p = sum_I v^L_I (x) grad S_Ip
/// (eq. 26, evaluated as sum_I (v^L_I - v_p) (x) grad S_Ip over nodes with mass: equal, as
/// sum_I grad S_Ip = 0, and a massless node no longer fakes a velocity jump).
template <class Shape>
ParticleTotals grid_to_particles(Particles& P, const Grid& G, const Stencils<Shape>& S, double dt,
                                 bool usl_gradient, std::optional<Failure>& failure);

/// MUSL (Sulsky et al. 1995; Nairn 2003): re-map the updated particle momentum with the same
/// weights, v^{n+1}_I = sum_p S_Ip m_p v_p^{n+1} / m_I, mirror it at the faces (a projection:
/// particles do not see it), and L_p = sum_I v^{n+1}_I (x) grad S_Ip.
template <class Shape>
void remap_and_gradient(Particles& P, Grid& G, const Stencils<Shape>& S);

/// Constitutive update by the library for every particle: F_{n+1} from L (models/kinematics),
/// sigma_{n+1} by ElasticPlastic::update (objective, with the library's rotation), V = V0 det F.
/// Returns the strain-energy increment of report eq. 14, sum_p 1/2 (sigma_n + sigma_{n+1}) : D
/// V_{n+1} dt, and the largest c_p + |v_p| for the next time step.
struct StressTotals {
  double strain_energy_increment = 0.0;
  double max_signal_speed = 0.0;  ///< max_p (c_p + |v_p|) [m/s]
};
StressTotals update_stress(Particles& P, const std::vector<const ElasticPlastic*>& models,
                           double dt, FIntegration f_integration, std::optional<Failure>& failure);

/// Stable step: multiplier * min_d dx_d / max_p (c_p + |v_p|) (reference_code_notes.md sec. 16,
/// with the speed magnitude instead of per-axis components: slightly more conservative).
double stable_time_step(const Vec3& dx, double max_signal_speed, double multiplier);
/// max_p (c_p + |v_p|) from the stored wave speeds (first step).
double max_signal_speed(const Particles& P);

}  // namespace impact::mpm
