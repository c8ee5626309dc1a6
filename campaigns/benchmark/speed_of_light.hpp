// The speed-of-light step (issue 57): the leanest 27-node fp64 MPM step this project can write, to
// measure how far the full step is from it. One body, one velocity field, uGIMP (the solver's own
// gimp_stencil), USL (no re-map), a dense grid, no contact, no walls, no ledger, no failure
// checks, particles in cell order; a small-strain hypoelastic J2 solid with a radial return
// (perfect plasticity, the Jaumann rotation left out). What it keeps: the three transfers
// (P2G of mass, momentum and internal force; the grid update; G2P of the velocity increment, the
// position and the velocity gradient) and a constitutive update a real one cannot beat.
#pragma once

#include <chrono>
#include <cmath>
#include <vector>

#include "mpm/shape/gimp.hpp"

namespace impact::mpm::speed_of_light {

struct Result {
  long particles = 0;
  int steps = 0;
  double seconds = 0.0;
  double plastic_share = 0.0;  ///< of the particle-steps that returned to the yield surface
  double particle_steps_per_second() const { return particles * double(steps) / seconds; }
};

/// A cube of `cells_per_side`^3 cells holding a body of (cells_per_side - 8)^3 cells at 2^3
/// particles per cell (6061-T6-like: rho 2700, E 69 GPa, nu 0.33, yield 276 MPa), starting on the
/// yield surface in uniaxial compression along x and squeezed along x (stretched along y) at
/// 2e4 1/s, so that the points yield; `steps` steps of 1 ns after one warm-up step, on one
/// thread.
inline Result run(int cells_per_side, int steps) {
  const int n = cells_per_side, nodes = n + 3;  // one ghost layer below, two above
  const double h = 1e-3, dt = 1e-9, rho = 2700.0, E = 69e9, nu = 0.33, yield = 276e6;
  const double G = E / (2 * (1 + nu)), K = E / (3 * (1 - 2 * nu));
  const auto node = [&](int i, int j, int k) {
    return (i + 1) + nodes * ((j + 1) + nodes * (k + 1));
  };
  std::vector<Vec3> x, v;
  std::vector<Mat3> stress, L;
  std::vector<double> volume;
  for (int i = 4; i < n - 4; ++i)
    for (int j = 4; j < n - 4; ++j)
      for (int k = 4; k < n - 4; ++k)
        for (int a = 0; a < 8; ++a) {
          const Vec3 p = h * Vec3(i + 0.25 + 0.5 * (a & 1), j + 0.25 + 0.5 * ((a >> 1) & 1),
                                  k + 0.25 + 0.5 * ((a >> 2) & 1));
          x.push_back(p);
          const Vec3 c = p - Vec3::Constant(0.5 * n * h);
          v.push_back(2e4 * Vec3(-c(0), c(1), 0.0));
          stress.push_back(Vec3(-yield, 0.0, 0.0).asDiagonal().toDenseMatrix());
          L.push_back(Mat3::Zero());
          volume.push_back(h * h * h / 8);
        }
  const std::size_t np = x.size();
  const double mass = rho * h * h * h / 8;
  const int nn = nodes * nodes * nodes;
  std::vector<double> m(nn);
  std::vector<Vec3> p(nn), f(nn), dv(nn), vs(nn);
  std::vector<Stencil<3>> S(np);
  const Vec3 inv = Vec3::Constant(1.0 / h), l = Vec3::Constant(0.25);
  const std::array<int, 3> cells{n, n, n};
  long plastic = 0;
  // body(I, S_I, grad S_I) over the 27 nodes of a stencil, the weights' products hoisted per row.
  const auto each_node = [&](const Stencil<3>& s, auto&& body) {
    for (int c = 0; c < 3; ++c)
      for (int b = 0; b < 3; ++b) {
        const double wyz = s.w[1][b] * s.w[2][c];
        const double dyz = s.dw[1][b] * s.w[2][c], ydz = s.w[1][b] * s.dw[2][c];
        const int row = node(s.base[0], s.base[1] + b, s.base[2] + c);
        for (int a = 0; a < 3; ++a)
          body(row + a, s.w[0][a] * wyz, Vec3(s.dw[0][a] * wyz, s.w[0][a] * dyz, s.w[0][a] * ydz));
      }
  };
  const auto step = [&] {
    std::fill(m.begin(), m.end(), 0.0);
    std::fill(p.begin(), p.end(), Vec3::Zero());
    std::fill(f.begin(), f.end(), Vec3::Zero());
    for (std::size_t q = 0; q < np; ++q) {  // P2G; the stencil is kept for G2P, as the solver does
      const Stencil<3>& s = S[q] = gimp_stencil(x[q] * (1.0 / h), inv, l, cells);
      const Mat3 Vs = volume[q] * stress[q];
      const Vec3 mv = mass * v[q];
      each_node(s, [&](int I, double w, const Vec3& g) {
        m[I] += w * mass;
        p[I] += w * mv;
        f[I] -= Vs * g;
      });
    }
    for (int I = 0; I < nn; ++I) {  // the grid update
      if (m[I] <= 0.0) continue;
      dv[I] = dt * f[I] / m[I];
      vs[I] = p[I] / m[I] + dv[I];
    }
    for (std::size_t q = 0; q < np; ++q) {  // G2P, then the J2 update
      const Stencil<3>& s = S[q];
      Vec3 dvq = Vec3::Zero(), vq = Vec3::Zero();
      Mat3 Lq = Mat3::Zero();
      each_node(s, [&](int I, double w, const Vec3& g) {
        dvq += w * dv[I];
        vq += w * vs[I];
        Lq += vs[I] * g.transpose();
      });
      v[q] += dvq;
      x[q] += dt * vq;
      L[q] = Lq;
      const Mat3 D = 0.5 * (Lq + Lq.transpose());
      const double tr = D.trace();
      Mat3 trial =
          stress[q] + dt * (K * tr * Mat3::Identity() + 2 * G * (D - tr / 3 * Mat3::Identity()));
      const double mean = trial.trace() / 3;
      const Mat3 dev = trial - mean * Mat3::Identity();
      const double q_vm = std::sqrt(1.5 * (dev.array() * dev.array()).sum());
      if (q_vm > yield) {  // radial return to the von Mises surface
        trial = mean * Mat3::Identity() + (yield / q_vm) * dev;
        ++plastic;
      }
      stress[q] = trial;
      volume[q] *= 1.0 + dt * tr;
    }
  };
  step();  // warm-up
  plastic = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) step();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Result r;
  r.particles = long(np);
  r.steps = steps;
  r.seconds = seconds;
  r.plastic_share = double(plastic) / (double(np) * steps);
  return r;
}

}  // namespace impact::mpm::speed_of_light
