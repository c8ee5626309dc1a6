// Verification case: Becker and Drucker indicators against an independent evaluation.
#include "models/stability/becker.hpp"
#include "models/stability/drucker.hpp"
#include "models/stability/elastic_plastic_tangent.hpp"
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

namespace {

using Mat9 = Eigen::Matrix<double, 9, 9>;

/// C^e_ijkl = (K - 2mu/3) d_ij d_kl + mu (d_ik d_jl + d_il d_jk), written out again.
Mat9 own_elastic(double K, double mu) {
  Mat9 c = Mat9::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          c(3 * i + j, 3 * k + l) = (K - 2.0 * mu / 3.0) * (i == j) * (k == l) +
                                    mu * ((i == k) * (j == l) + (i == l) * (j == k));
  return c;
}

/// C^ep = C^e - (2mu)^2 N (x) N / (3mu + H), N = 3 s / (2 sigma_eq) (Hill 1958).
Mat9 own_tangent(double K, double mu, const Mat3& stress, double H) {
  const Mat3 s = stress - stress.trace() / 3.0 * Mat3::Identity();
  const double q = von_mises_of(stress);
  const Mat3 N = 1.5 * s / q;
  Eigen::Matrix<double, 9, 1> v;
  for (int k = 0; k < 9; ++k) v(k) = N(k / 3, k % 3);
  return own_elastic(K, mu) - 4.0 * mu * mu / (3.0 * mu + H) * v * v.transpose();
}

double det_acoustic(const Mat9& C, const Vec3& n) {
  Mat3 A = Mat3::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) A(j, k) += n(i) * C(3 * i + j, 3 * k + l) * n(l);
  return A.determinant();
}

/// min over the unit sphere of det A^ep(n) / det A^e(n): a 2-degree grid of the hemisphere, then
/// a compass search in the two angles down to 1e-10 rad around the best grid points.
double own_becker(const Mat9& Cep, const Mat9& Ce) {
  const auto f = [&](double th, double ph) {
    const Vec3 n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    return det_acoustic(Cep, n) / det_acoustic(Ce, n);
  };
  const double deg = std::numbers::pi / 180.0;
  struct Start {
    double v, th, ph;
  };
  std::vector<Start> grid;
  for (int a = 0; a <= 90; ++a)
    for (int b = 0; b < 180; ++b)
      grid.push_back({f(2 * a * deg, 2 * b * deg), 2 * a * deg, 2 * b * deg});
  std::sort(grid.begin(), grid.end(), [](const Start& x, const Start& y) { return x.v < y.v; });
  double best = grid.front().v;
  for (std::size_t s = 0; s < std::min<std::size_t>(8, grid.size()); ++s) {
    double th = grid[s].th, ph = grid[s].ph, v = grid[s].v;
    for (double h = 2 * deg; h > 1e-10; h *= 0.5) {
      for (bool moved = true; moved;) {
        moved = false;
        const std::array<std::pair<double, double>, 4> moves = {
            {{h, 0.0}, {-h, 0.0}, {0.0, h}, {0.0, -h}}};
        for (const auto& [dt, dp] : moves) {
          const double w = f(th + dt, ph + dp);
          if (w < v) {
            v = w, th += dt, ph += dp, moved = true;
          }
        }
      }
    }
    best = std::min(best, v);
  }
  return best;
}

}  // namespace

std::vector<Check> stability_indicators(const SuiteContext& ctx) {
  Recorder rec("becker_drucker_indicators");
  const Material m = load_material(ctx.material_file);
  const double K = m.model.params().bulk_modulus, mu = m.model.params().shear_modulus;
  const double nu = cf::poisson_ratio(K, mu);
  const double H_rr = -(1.0 + nu) * mu / 2.0;  // Rudnicki & Rice (1975), uniaxial tension
  Mat3 general;
  general << 250e6, 80e6, 30e6, 80e6, -50e6, 20e6, 30e6, 20e6, 100e6;
  struct State {
    std::string label;
    Mat3 stress;
    double H;
  };
  const Mat3 tension = Vec3(300e6, 0, 0).asDiagonal();
  const Mat3 plane = Vec3(200e6, -200e6, 0.0).asDiagonal();
  const std::vector<State> states = {
      {"uniaxial tension, H = 0.5 GPa", tension, 0.5e9},
      {"uniaxial tension, H = H_crit = -(1+nu) mu/2", tension, H_rr},
      {"uniaxial tension, H = 1.2 H_crit", tension, 1.2 * H_rr},
      {"sigma = diag(200, -200, 0) MPa (s_II = 0), H = -0.1 GPa", plane, -0.1e9},
      {"general stress (off-diagonal), H = -5 GPa", general, -5e9},
  };
  for (const State& s : states) {
    const double own = own_becker(own_tangent(K, mu, s.stress, s.H), own_elastic(K, mu));
    const double model =
        becker_check(elastic_plastic_tangent(K, mu, s.stress, s.H), isotropic_elasticity(K, mu),
                     s.stress, NormalSearch::principal_plane)
            .indicator;
    const double j2 = becker_check_j2(K, mu, s.stress, s.H).indicator;
    rec.compare("Becker, " + s.label + ": becker_check (principal plane) vs own sphere search", own,
                model, 1e-7, 1.0);
    rec.compare("Becker, " + s.label + ": becker_check_j2 vs own sphere search", own, j2, 1e-7,
                1.0);
    if (s.H == H_rr) {
      rec.compare("Becker, " + s.label + ": own search gives 0 at Rudnicki-Rice H_crit", 0.0, own,
                  1e-9, 1.0);
    }
  }
  // Drucker: sigma_dot : D^p with sigma_dot = C^ep : D and D^p = eps_dot_p N of the same loading.
  Mat3 D;
  D << 1000.0, 150.0, 0.0, 150.0, -400.0, 50.0, 0.0, 50.0, -450.0;
  for (const State& s : {states[0], states[2], states[4]}) {
    const Mat9 Cep = own_tangent(K, mu, s.stress, s.H);
    const Mat3 dev = s.stress - s.stress.trace() / 3.0 * Mat3::Identity();
    const Mat3 N = 1.5 * dev / von_mises_of(s.stress);
    const double ep_rate = 2.0 * mu * (N.array() * D.array()).sum() / (3.0 * mu + s.H);
    const Mat3 Dp = ep_rate * N;
    Eigen::Matrix<double, 9, 1> d;
    for (int k = 0; k < 9; ++k) d(k) = D(k / 3, k % 3);
    const Eigen::Matrix<double, 9, 1> sdot = Cep * d;
    double own = 0.0;
    for (int k = 0; k < 9; ++k) own += sdot(k) * Dp(k / 3, k % 3);
    const double model =
        drucker_check(elastic_plastic_tangent(K, mu, s.stress, s.H), D, Dp).indicator;
    rec.compare("Drucker, " + s.label + ": drucker_check vs own C^ep:D : D^p", own, model, 1e-10);
    rec.compare("Drucker, " + s.label + ": own C^ep:D : D^p = H eps_dot_p^2 (sign of H)",
                s.H * ep_rate * ep_rate, own, 1e-8);
  }
  return rec.take();
}

}  // namespace impact::pointdriver::verify
