// Becker's loss-of-ellipticity check (report eq. 11): the acoustic tensor of isotropic elasticity,
// indicator 1 for an elastic tangent, and the critical hardening slope H_crit at which the
// indicator changes sign, found by bisection on H with the library and with an independent
// brute-force sweep of normals over the sphere (the J2 tangent built here with explicit index
// loops), for uniaxial tension, plane strain (pure shear) and a general triaxial state; both agree
// with Rudnicki & Rice's (1975) closed form. Also: where the critical normal lies, that the
// reported normal is unit with the reported ratio, and that the full-sphere search finds an
// out-of-plane minimum that Becker's plane misses.
#include "models/stability/becker.hpp"

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "models/stability/elastic_plastic_tangent.hpp"

using namespace impact;

namespace {

constexpr double kK = 66.4e9, kMu = 26e9;  // 6061-T6, report Table 1
constexpr double kPi = std::numbers::pi;
const double kNu = (3.0 * kK - 2.0 * kMu) / (2.0 * (3.0 * kK + kMu));  // 0.3268

// ---- Independent reference: tensors as C[i][j][k][l] built with explicit loops. -----------------
struct Tensor {
  double c[3][3][3][3];
};

Tensor elastic_loops() {
  const double lambda = kK - 2.0 * kMu / 3.0;
  Tensor t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          t.c[i][j][k][l] =
              lambda * (i == j) * (k == l) + kMu * ((i == k) * (j == l) + (i == l) * (j == k));
  return t;
}

// N_ij N_kl with N = (3/2) s / sigma_eq, from the stress components.
Tensor flow_dyad_loops(const Mat3& stress) {
  double s[3][3], ss = 0.0;
  const double mean = (stress(0, 0) + stress(1, 1) + stress(2, 2)) / 3.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      s[i][j] = stress(i, j) - (i == j) * mean;
      ss += s[i][j] * s[i][j];
    }
  const double q = std::sqrt(1.5 * ss);
  Tensor t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) t.c[i][j][k][l] = 2.25 * s[i][j] * s[k][l] / (q * q);
  return t;
}

void acoustic_array(const Tensor& t, const double n[3], double a[3][3]) {
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) {
      a[j][k] = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int l = 0; l < 3; ++l) a[j][k] += n[i] * t.c[i][j][k][l] * n[l];
    }
}

Mat3 acoustic_loops(const Tensor& t, const Vec3& n) {
  const double v[3] = {n(0), n(1), n(2)};
  double a[3][3];
  acoustic_array(t, v, a);
  Mat3 m;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) m(j, k) = a[j][k];
  return m;
}

// Cofactor determinant on plain arrays: the sweeps below take millions of them and must stay fast
// in unoptimized sanitizer builds too.
double det3(const double a[3][3]) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// Brute-force min over normals of det A / det A^e for a tangent C = C^e - c B (B = N (x) N for the
// J2 tangent, c = 4 mu^2 / (3 mu + H)). A is linear in C, so A(n) = A^e(n) - c A^B(n) with both
// parts from the explicit loops above, stored per normal. Level 1: the hemisphere on a 1-degree
// (theta, phi) grid. Level 2: a +-1.2 degree window around the level-1 minimum on a 0.01-degree
// grid (angle error <= 1e-4 rad, H error ~ mu 1e-8). Windows are cached by their centre, so each
// further evaluation costs one determinant per normal.
class BruteForce {
 public:
  BruteForce(const Tensor& elastic, const Tensor& b) : ce_(elastic), b_(b) {
    constexpr double deg = kPi / 180.0;
    for (int i = 0; i <= 90; ++i)
      for (int j = 0; j < (i == 0 ? 1 : 360); ++j) coarse_.push_back(sample(i * deg, j * deg));
  }

  double min_ratio(double c) {
    std::size_t best = 0;
    double best_value = ratio(coarse_[0], c);
    for (std::size_t m = 1; m < coarse_.size(); ++m) {
      const double v = ratio(coarse_[m], c);
      if (v < best_value) {
        best_value = v;
        best = m;
      }
    }
    for (const Sample& s : window(best)) best_value = std::min(best_value, ratio(s, c));
    return best_value;
  }

 private:
  struct Sample {
    double theta, phi;
    double ae[3][3], ab[3][3], det_ae;
  };
  Sample sample(double theta, double phi) const {
    const double n[3] = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         std::cos(theta)};
    Sample s{theta, phi, {}, {}, 0.0};
    acoustic_array(ce_, n, s.ae);
    acoustic_array(b_, n, s.ab);
    s.det_ae = det3(s.ae);
    return s;
  }
  static double ratio(const Sample& s, double c) {
    double a[3][3];
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) a[j][k] = s.ae[j][k] - c * s.ab[j][k];
    return det3(a) / s.det_ae;
  }
  const std::vector<Sample>& window(std::size_t centre) {
    auto it = windows_.find(centre);
    if (it != windows_.end()) return it->second;
    const double theta0 = coarse_[centre].theta, phi0 = coarse_[centre].phi;
    constexpr double step = 0.01 * kPi / 180.0;
    std::vector<Sample> w;
    for (int a = -120; a <= 120; ++a)
      for (int b = -120; b <= 120; ++b) w.push_back(sample(theta0 + a * step, phi0 + b * step));
    return windows_.emplace(centre, std::move(w)).first->second;
  }

  Tensor ce_, b_;
  std::vector<Sample> coarse_;
  std::map<std::size_t, std::vector<Sample>> windows_;
};

double plastic_factor(double H) {
  return 4.0 * kMu * kMu / (3.0 * kMu + H);
}

// The H at which `unstable(H)` switches from true (below) to false (above), by bisection on
// [-2.5 mu, 0.5 mu]: 32 halvings leave a bracket of 3 mu / 2^32 ~ 18 Pa, far below tolerance.
double critical_H(const std::function<bool(double)>& unstable) {
  double lo = -2.5 * kMu, hi = 0.5 * kMu;
  BOOST_REQUIRE(unstable(lo));
  BOOST_REQUIRE(!unstable(hi));
  for (int it = 0; it < 32; ++it) {
    const double mid = 0.5 * (lo + hi);
    (unstable(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Rudnicki & Rice (1975), critical hardening for associated Mises flow (beta = mu_RR = 0) without
// geometric terms: h_crit / G = -(1 + nu) N^2 / 2 with N = s_II / tau, tau = sqrt(s:s / 2), and h
// the slope of tau against the plastic shear strain gamma_p; sigma_eq = sqrt(3) tau and eps_p =
// gamma_p / sqrt(3) give H = 3 h.
double rudnicki_rice_H_crit(const Mat3& stress) {
  const Mat3 s = deviator(stress);
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(s);
  const double tau = std::sqrt(0.5 * ddot(s, s));
  const double n_rr = eig.eigenvalues()(1) / tau;
  return -1.5 * (1.0 + kNu) * kMu * n_rr * n_rr;
}

Mat3 rotation() {  // an arbitrary rotation, so that no state is aligned with the lab axes
  return Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
}

Mat3 rotated_diagonal(double a, double b, double c) {
  const Mat3 R = rotation();
  return R * Vec3(a, b, c).asDiagonal() * R.transpose();
}

// The three states of the H_crit comparison.
struct State {
  const char* name;
  Mat3 stress;
};
std::vector<State> states() {
  return {{"uniaxial tension", rotated_diagonal(300e6, 0.0, 0.0)},
          {"plane strain (pure shear + pressure)", rotated_diagonal(100e6, -73.2e6, -246.4e6)},
          {"general triaxial", rotated_diagonal(400e6, 100e6, -150e6)}};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stability_becker)

BOOST_AUTO_TEST_CASE(acoustic_tensor_of_isotropic_elasticity_is_mu_I_plus_K_plus_mu_over_3_nn) {
  // n_i C_ijkl n_l = lambda n_j n_k + mu (delta_jk + n_j n_k) = mu I + (K + mu/3) n (x) n.
  const Tensor4 ce = isotropic_elasticity(kK, kMu);
  for (const Vec3& v : {Vec3(1, 0, 0), Vec3(0.3, -0.7, 0.2), Vec3(-1, 1, 1)}) {
    const Vec3 n = v.normalized();
    const Mat3 expected = kMu * Mat3::Identity() + (kK + kMu / 3.0) * n * n.transpose();
    BOOST_TEST((acoustic_tensor(ce, n) - expected).cwiseAbs().maxCoeff() < 1e-12 * kK);
    // And the library's contraction equals the explicit loops for a general tangent.
    const Tensor4 c = elastic_plastic_tangent(kK, kMu, rotated_diagonal(3e8, 1e8, -2e8), -1e9);
    Tensor t;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) t.c[i][j][k][l] = c(3 * i + j, 3 * k + l);
    BOOST_TEST((acoustic_tensor(c, n) - acoustic_loops(t, n)).cwiseAbs().maxCoeff() < 1e-12 * kK);
  }
}

BOOST_AUTO_TEST_CASE(elastic_tangent_gives_indicator_one_for_every_normal_and_both_searches) {
  const Tensor4 ce = isotropic_elasticity(kK, kMu);
  for (const State& s : states())
    for (NormalSearch search : {NormalSearch::principal_plane, NormalSearch::full_sphere}) {
      const BeckerResult r = becker_check(ce, ce, s.stress, search);
      BOOST_TEST(std::abs(r.indicator - 1.0) < 1e-12);
      BOOST_TEST(!r.unstable);
      BOOST_TEST(std::abs(r.normal.norm() - 1.0) < 1e-12);
    }
}

BOOST_AUTO_TEST_CASE(indicator_changes_sign_at_the_brute_force_and_rudnicki_rice_H_crit) {
  // Tolerances: 1e-3 of |H_crit| where it is not zero (the brief's), and 1e-6 mu = 26 kPa for plane
  // strain, whose H_crit is 0 (s_II = 0); both far below any Johnson-Cook slope.
  const Tensor4 ce = isotropic_elasticity(kK, kMu);
  for (const State& s : states()) {
    BruteForce brute(elastic_loops(), flow_dyad_loops(s.stress));
    const double h_brute =
        critical_H([&](double H) { return brute.min_ratio(plastic_factor(H)) <= 0.0; });
    const double h_rr = rudnicki_rice_H_crit(s.stress);
    const double tol = std::max(1e-3 * std::abs(h_brute), 1e-6 * kMu);
    BOOST_TEST_MESSAGE(s.name << ": H_crit brute force " << h_brute << " Pa, R&R " << h_rr
                              << " Pa, |diff| / max(|H_crit|, mu) = "
                              << std::abs(h_brute - h_rr) / std::max(std::abs(h_rr), kMu));
    BOOST_TEST(std::abs(h_brute - h_rr) < tol, s.name << ": brute force vs Rudnicki-Rice");
    for (NormalSearch search : {NormalSearch::full_sphere, NormalSearch::principal_plane}) {
      const double h_lib = critical_H([&](double H) {
        return becker_check(elastic_plastic_tangent(kK, kMu, s.stress, H), ce, s.stress, search)
            .unstable;
      });
      BOOST_TEST_MESSAGE(
          "  library " << (search == NormalSearch::full_sphere ? "full_sphere" : "principal_plane")
                       << ": " << h_lib << " Pa, |diff| / max(|H_crit|, mu) = "
                       << std::abs(h_lib - h_brute) / std::max(std::abs(h_brute), kMu));
      BOOST_TEST(std::abs(h_lib - h_brute) < tol, s.name);
    }
  }
  // The closed forms themselves: -(1 + nu) mu / 2 in uniaxial tension, 0 in plane strain.
  BOOST_TEST(rudnicki_rice_H_crit(states()[0].stress) == -0.5 * (1.0 + kNu) * kMu,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(rudnicki_rice_H_crit(states()[1].stress)) < 1e-9 * kMu);
}

BOOST_AUTO_TEST_CASE(critical_normal_lies_where_rudnicki_rice_put_it) {
  // The argmin does not depend on H (ratio = 1 - c(H) g(n)); take H = -0.8 mu.
  // Uniaxial: maximizing g over x = (n . e_axis)^2 gives x = (3K + 2 mu)/(6K + 2 mu) = (2 - nu)/3,
  // a cone at 41.8 degrees to the tension axis, whatever the transverse direction (Becker's plane
  // is any plane through the axis there). Plane strain: 45 degrees in the max-min plane. General:
  // perpendicular to the intermediate principal direction. Tolerance 1e-6 (searches refine the
  // angle to ~1e-9 rad).
  const Tensor4 ce = isotropic_elasticity(kK, kMu);
  const Mat3 R = rotation();
  const Vec3 e_max = R.col(0), e_mid = R.col(1), e_min = R.col(2);
  const std::vector<State> st = states();
  for (NormalSearch search : {NormalSearch::principal_plane, NormalSearch::full_sphere}) {
    auto normal = [&](const Mat3& stress) {
      return becker_check(elastic_plastic_tangent(kK, kMu, stress, -0.8 * kMu), ce, stress, search)
          .normal;
    };
    const Vec3 n0 = normal(st[0].stress);
    BOOST_TEST(std::abs(std::pow(n0.dot(e_max), 2) - (2.0 - kNu) / 3.0) < 1e-6);
    const Vec3 n1 = normal(st[1].stress);
    BOOST_TEST(std::abs(std::abs(n1.dot(e_max)) - std::sqrt(0.5)) < 1e-6);
    BOOST_TEST(std::abs(std::abs(n1.dot(e_min)) - std::sqrt(0.5)) < 1e-6);
    BOOST_TEST(std::abs(n1.dot(e_mid)) < 1e-6);
    BOOST_TEST(std::abs(normal(st[2].stress).dot(e_mid)) < 1e-6);
  }
  BOOST_TEST((2.0 - kNu) / 3.0 == (3.0 * kK + 2.0 * kMu) / (6.0 * kK + 2.0 * kMu),
             boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(reported_normal_is_unit_and_its_ratio_is_the_indicator) {
  // Ratio recomputed with the explicit-loop tensors of this file; absolute 1e-12 (the ratio is
  // O(1)).
  const Tensor ce_loops = elastic_loops();
  for (const State& s : states()) {
    const Tensor nn = flow_dyad_loops(s.stress);
    for (double H : {-0.3 * kMu, 1e8})
      for (NormalSearch search : {NormalSearch::principal_plane, NormalSearch::full_sphere}) {
        const BeckerResult r = becker_check(elastic_plastic_tangent(kK, kMu, s.stress, H),
                                            isotropic_elasticity(kK, kMu), s.stress, search);
        BOOST_TEST(std::abs(r.normal.norm() - 1.0) < 1e-14);
        const double c = plastic_factor(H);
        const Mat3 ae = acoustic_loops(ce_loops, r.normal);
        const double ratio =
            (ae - c * acoustic_loops(nn, r.normal)).determinant() / ae.determinant();
        BOOST_TEST(std::abs(ratio - r.indicator) < 1e-12);
        BOOST_TEST(r.unstable == (r.indicator <= 0.0));
      }
  }
}

BOOST_AUTO_TEST_CASE(full_sphere_finds_an_out_of_plane_minimum_that_beckers_plane_misses) {
  // A non-J2 tangent C^e - c M (x) M with M a deviator not coaxial with the stress: its critical
  // normal is not in the max-min principal plane of the stress. full_sphere must reach the
  // brute-force minimum (1-degree grid, then a 0.01-degree window: value error ~ 1e-7) and lie
  // clearly below what Becker's plane finds.
  const Mat3 stress = rotated_diagonal(400e6, 100e6, -150e6);
  Mat3 m;
  m << 0.1, 0.6, 0.0, 0.6, -0.3, 0.5, 0.0, 0.5, 0.2;
  m = deviator(m);
  const Tensor4 ce = isotropic_elasticity(kK, kMu);
  const Eigen::Matrix<double, 9, 1> mv = flatten(m);
  const Tensor4 c = ce - 0.8 * kMu / ddot(m, m) * mv * mv.transpose();
  Tensor mm{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) mm.c[i][j][k][l] = m(i, j) * m(k, l);
  const double best = BruteForce(elastic_loops(), mm).min_ratio(0.8 * kMu / ddot(m, m));
  const BeckerResult full = becker_check(c, ce, stress, NormalSearch::full_sphere);
  const BeckerResult plane = becker_check(c, ce, stress, NormalSearch::principal_plane);
  BOOST_TEST_MESSAGE("brute " << best << ", full_sphere " << full.indicator << ", principal_plane "
                              << plane.indicator);
  BOOST_TEST(std::abs(full.indicator - best) < 1e-6);
  BOOST_TEST(full.indicator <= best + 1e-12);  // never above the sampled minimum
  BOOST_TEST(plane.indicator > full.indicator + 0.01);
}

BOOST_AUTO_TEST_CASE(non_finite_input_gives_a_nan_indicator_that_is_not_unstable) {
  Tensor4 c = isotropic_elasticity(kK, kMu);
  c(0, 0) = std::nan("");
  const BeckerResult r =
      becker_check(c, isotropic_elasticity(kK, kMu), states()[0].stress, NormalSearch::full_sphere);
  BOOST_TEST(std::isnan(r.indicator));
  BOOST_TEST(!r.unstable);
}

BOOST_AUTO_TEST_CASE(j2_closed_form_equals_the_numerical_plane_search) {
  // The closed form (matrix determinant lemma, quadratic in cos^2 t) against the 36-sample sweep
  // plus Brent refinement on the assembled 9x9 tangent, for rotated triaxial stresses and
  // hardening from stiff to far past the critical softening: same indicator to 1e-7 and the
  // same band normal up to the mirror symmetry of the plane.
  const Tensor4 Ce = isotropic_elasticity(kK, kMu);
  const double Hs[] = {5e9, 3e8, 0.0, -2e9, -1e10, -3e10};
  const Vec3 principal[] = {Vec3(400e6, -50e6, -120e6), Vec3(300e6, 0.0, 0.0),
                            Vec3(-350e6, 20e6, 80e6), Vec3(200e6, 100e6, -300e6)};
  for (int k = 0; k < 4; ++k) {
    const Mat3 Q = Eigen::AngleAxisd(0.3 + k, Vec3(1.0, 2.0, -0.5 * k).normalized()).matrix();
    const Mat3 stress = Q * Mat3(principal[k].asDiagonal()) * Q.transpose() -
                        1e8 * Mat3::Identity();  // a mean stress must not matter
    for (const double H : Hs) {
      const BeckerResult numeric = becker_check(elastic_plastic_tangent(kK, kMu, stress, H), Ce,
                                                stress, NormalSearch::principal_plane);
      const BeckerResult closed = becker_check_j2(kK, kMu, stress, H);
      BOOST_TEST_CONTEXT("stress state " << k << ", H = " << H) {
        BOOST_TEST(closed.indicator == numeric.indicator, boost::test_tools::tolerance(1e-7));
        BOOST_TEST(closed.unstable == numeric.unstable);
        BOOST_TEST(closed.normal.norm() == 1.0, boost::test_tools::tolerance(1e-9));
        // Normals at +-t about e_max are mirror images with the same indicator: compare the
        // components along e_max and e_min. Uniaxial (k = 1) has a cone: any member is right.
        const Eigen::SelfAdjointEigenSolver<Mat3> eig(stress);
        if (k != 1 && closed.indicator < 0.999) {
          for (int c : {0, 2}) {
            const Vec3 e = eig.eigenvectors().col(c);
            BOOST_TEST(std::abs(closed.normal.dot(e)) == std::abs(numeric.normal.dot(e)),
                       boost::test_tools::tolerance(1e-5));
          }
        }
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(j2_closed_form_of_a_deviator_free_state_is_elastic) {
  const BeckerResult r = becker_check_j2(kK, kMu, -2e9 * Mat3::Identity(), -1e10);
  BOOST_TEST(r.indicator == 1.0);
  BOOST_TEST(!r.unstable);
}

BOOST_AUTO_TEST_SUITE_END()
