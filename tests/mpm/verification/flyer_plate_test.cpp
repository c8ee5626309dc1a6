// Symmetric flyer-plate impact, 6061-T6 on 6061-T6 at 500 m/s, Mie-Gruneisen EOS, uniaxial strain
// (data/scenes/verification/flyer_plate.json). In the frame of
// the impact plane a 20 mm flyer at +250 m/s meets a 40 mm target at -250 m/s at x = 0, t = 0; a
// column 320 x 1 x 1 cells (dx = 0.2 mm, 2 particles per cell along x, 600 particles), lateral
// faces symmetric (mirrors), x faces free, one material and one velocity field (the plates stick
// in compression), uGIMP + MUSL. Run to t = 6 us (423 steps).
// Reference (computed here from the material, not typed in): u_p = (v_flyer - v_target)/2 =
// 250 m/s, U_s = C0 + S u_p = 5720.75 m/s, p_H = rho0 U_s u_p = 3.8615 GPa, rho_H = rho0 U_s /
// (U_s - u_p); asserted first that the EOS's own Hugoniot p_H(rho_H) equals rho0 U_s u_p (1e-12).
// Strength: the scene makes the alloy hydrodynamic (Johnson-Cook A = 0.1 MPa, B = C = 0, so the
// deviator is capped at 0.1 MPa = 2.6e-5 p_H and sigma = -p I): the tabulated Hugoniot is the
// hydrodynamic one, and with strength no single stress of the shocked state equals it. At the
// same u_p (exact by symmetry whatever the strength) the elastic-plastic state sits on
// -sigma_xx = p + 2/3 Y with -sigma_xx ~ rho0 U u_p, which puts the mean stress at about
// p_H - 2/3 Y p_H'/(p_H' + p_H/eta) = p_H - 0.35 Y (-3.2 % of p_H with Y = 348 MPa) and -sigma_xx
// at about p_H + 0.31 Y (+2.8 %): the "pressure vs p_H" comparison is off by as much as the 3 %
// tolerance. So the assertions use the hydrodynamic variant; the alloy's own strength (A, B, C
// restored) is run and reported: mean stress -2.7 % and -sigma_xx +2.9 % with AV (1.5 (-sigma_xx
// - p) = 325 MPa vs A + B ep^n = 348 MPa), -1.3 % / +2.0 % without (the ringing unloads the
// deviator to 193 MPa); the elastic precursor is at 0.18 p_H (HEL with K = rho0 C0^2).
// Measurement: target particles in layers of equal initial x, X (the column is laterally uniform).
// Plateau window at t = 6 us: X from 25 cells behind the impact face (5 mm: skips the start-up
// layers) to 50 cells behind the Hugoniot front U_s t (24.3 mm: skips the steepest ringing, whose
// peak is 1.76 p_H without AV), 193 layers. Nothing else has arrived there: the release from the
// flyer's back face reaches the impact face at h_f/U_s + h_f (1 - u_p/U_s)/c_H = 6.80 us (c_H =
// 5787 m/s, the shocked bulk sound speed; 6.32 us at the elastic 6765 m/s of the strength runs),
// the shock reaches the target's back face at h_t/U_s = 6.99 us (the strength runs' precursor at
// 6.18 us). Asserted, without and with artificial viscosity (C_L = 0.2, C_0 = 2.0):
//   - mean pressure -tr(sigma)/3 over the window = p_H within 3 % (measured +0.20 % / -0.11 %);
//   - mean particle velocity jump v - v_target over the window = u_p within 3 % (measured
//     +0.09 % / -0.02 %);
//   - shock speed = U_s within 2 % (measured +0.24 % / -0.18 %): the X of the p_H/2 crossing
//     (scanning from the undisturbed end) at t = 3 and 6 us; in initial coordinates the front
//     runs at U_s relative to the unshocked target;
//   - viscous_work = 0 without AV, > 0 with it; with AV the cell-mean pressure std over the window
//     < 2 % of p_H (measured 0.62 %; 4.1 % without AV).
// Reported (BOOST_TEST_MESSAGE), post-shock oscillation over the window relative to p_H: per layer
// max - min 0.31 / 0.071, std 0.052 / 0.021 (no AV / AV); cell means (the two particles of a cell
// averaged) max - min 0.24 / 0.026, std 0.041 / 0.0062. With AV the per-layer scatter is almost
// all an odd-even mode, neighbouring particles at +-2.5 % of p_H: a stress alternating from
// particle to particle exerts no net force on any node (uGIMP with l = dx/4 and particles dx/2
// apart: the gradient weights at each node cancel in pairs whatever the particles' offset from
// the grid; nearly so after the 4 % compression), so nothing relaxes it once the front leaves it.
// Also reported: front width (10 -> 90 % of p_H) 0.83 / 1.51 mm; the internal energy in the window
// 3.2 / 3.9 % below e_H = u_p^2/2 (rho0 Gamma0 (e - e_H) = -0.14 / -0.17 % of p_H); the ledger's
// energy_error at 6 us -2.5 % / -0.31 %, viscous_work 5.5 % of E0.
// Resolution (scene patched, not part of the test), 160 / 320 / 640 / 1280 cells: mean pressure
// +0.22 / +0.20 / +0.20 / +0.37 % (no AV), -0.19 / -0.11 / -0.09 / -0.08 % (AV); shock speed
// -0.31 / +0.24 / +0.81 / +1.10 % (no AV: the ringing spikes near the front move the p_H/2
// crossing), -0.08 / -0.18 / -0.12 / -0.10 % (AV). The no-AV ringing does not converge (per-layer
// max - min 0.17 / 0.31 / 0.53 / 0.96, the window reaching closer to the front as dx shrinks);
// the AV odd-even mode stays at +-2.5 % at every resolution. One OpenMP thread: 600 particles,
// ~0.25 s per run; with the default two threads on the shared machine a run took 1-22 s.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <variant>

#include "../verification_helpers.hpp"
#include "models/eos/mie_gruneisen.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Hugoniot {
  double u_p = 0.0, U_s = 0.0, p = 0.0, rho = 0.0;
};

/// Jump conditions of the symmetric impact, from the material and the two plate velocities
/// (Rankine-Hugoniot): u_p = (v_flyer - v_target)/2, U_s = C0 + S u_p,
/// p_H = rho0 U_s u_p, rho_H = rho0 U_s / (U_s - u_p).
Hugoniot symmetric_impact(const Scene& scene, double v_flyer, double v_target) {
  const auto& params = scene.materials.front().material.model.params();
  const auto& mg = std::get<MieGruneisenParams>(params.equation_of_state);
  Hugoniot h;
  h.u_p = 0.5 * (v_flyer - v_target);
  h.U_s = mg.C0 + mg.S_alpha * h.u_p;
  h.p = params.density * h.U_s * h.u_p;
  h.rho = params.density * h.U_s / (h.U_s - h.u_p);
  return h;
}

int object_index(const Scene& scene, const std::string& name) {
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    if (scene.objects[o].name == name) return static_cast<int>(o);
  }
  throw std::runtime_error("flyer_plate.json has no object " + name);
}

/// Target particles in layers of equal initial x (the sub-cell centres), ascending; the column
/// is laterally uniform, so a layer is one x-position of the 1-D problem.
struct Layers {
  std::vector<double> X;                          ///< initial x [m]
  std::vector<int> cell;                          ///< grid cell along x at t = 0
  std::vector<std::vector<std::size_t>> members;  ///< particle indices
};

Layers target_layers(const Particles& P, int target, const GridSpec& grid) {
  std::map<long, std::vector<std::size_t>> by_x;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.object[p] == target) by_x[std::lround(P.x[p](0) * 1e7)].push_back(p);  // 0.1 um bins
  }
  Layers l;
  for (auto& [key, members] : by_x) {
    l.X.push_back(P.x[members.front()](0));
    l.cell.push_back(
        static_cast<int>(std::floor((l.X.back() - grid.lower(0)) / grid.spacing()(0))));
    l.members.push_back(std::move(members));
  }
  return l;
}

/// Per layer: pressure -tr(sigma)/3 of the constitutive stress (without the viscous q), the
/// longitudinal stress -sigma_xx, velocity v_x, q, internal energy and plastic strain.
struct Profile {
  std::vector<double> p, sxx, v, q, e, ep;
};

Profile profile(const Particles& P, const Layers& layers) {
  Profile m;
  for (const auto& members : layers.members) {
    double p = 0.0, sxx = 0.0, v = 0.0, q = 0.0, e = 0.0, ep = 0.0;
    for (std::size_t i : members) {
      e += P.state[i].internal_energy;
      ep += P.state[i].plastic_strain;
      p -= P.state[i].stress.trace() / 3.0;
      sxx -= P.state[i].stress(0, 0);
      v += P.v[i](0);
      q += P.q.empty() ? 0.0 : P.q[i];
    }
    const double n = static_cast<double>(members.size());
    m.p.push_back(p / n);
    m.sxx.push_back(sxx / n);
    m.v.push_back(v / n);
    m.q.push_back(q / n);
    m.e.push_back(e / n);
    m.ep.push_back(ep / n);
  }
  return m;
}

/// Initial x where the layer pressure first rises through `level`, scanning from the undisturbed
/// far end (linear between layers); -1 if it never does.
double crossing(const Layers& layers, const std::vector<double>& p, double level) {
  for (std::size_t k = layers.X.size() - 1; k > 0; --k) {
    if (p[k - 1] >= level && p[k] < level) {
      return layers.X[k - 1] +
             (layers.X[k] - layers.X[k - 1]) * (p[k - 1] - level) / (p[k - 1] - p[k]);
    }
  }
  return -1.0;
}

struct Stats {
  double mean = 0.0, lo = 1e300, hi = -1e300, stddev = 0.0;
  int n = 0;
};

Stats stats(const std::vector<double>& values) {
  Stats s;
  for (double v : values) {
    s.mean += v;
    s.lo = std::min(s.lo, v);
    s.hi = std::max(s.hi, v);
  }
  s.n = static_cast<int>(values.size());
  s.mean /= s.n;
  for (double v : values) s.stddev += (v - s.mean) * (v - s.mean);
  s.stddev = std::sqrt(s.stddev / s.n);
  return s;
}

struct Measured {
  Hugoniot h;
  double eos_p_at_rho_h = 0.0;  ///< the EOS's own Hugoniot pressure at rho_H
  double rho0_gamma0 = 0.0;     ///< dp/de at fixed density [kg/m^3]
  double window_lo = 0.0, window_hi = 0.0;
  Stats p, sxx, u, p_cell, q, e, ep;  ///< over the window; u = v - v_target; p_cell: cell means
  double peak = 0.0;                  ///< max layer pressure between the window start and the front
  double face_velocity = 0.0;         ///< v - v_target of the target layer at the impact face [m/s]
  double yield_at_ep = 0.0;           ///< A + B ep^n at the window's mean plastic strain [Pa]
  double front1 = 0.0, front2 = 0.0, t1 = 0.0, t2 = 0.0, shock_speed = 0.0;
  double width = 0.0;  ///< front width, 10 -> 90 % of p_H, at t2 [m]
  double energy_error = 0.0, viscous_work = 0.0, initial_energy = 0.0;
  long steps = 0;
  double seconds = 0.0;
};

Measured impact_run(const Json& patch) {
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = test::verification_scene("flyer_plate.json", patch);
  Simulation sim(scene, 1);  // 600 particles: one thread (no barrier waits on a loaded machine)
  const int flyer = object_index(scene, "flyer"), target = object_index(scene, "target");
  const double v_target = scene.objects[target].velocity(0);
  const auto& params = scene.materials.front().material.model.params();
  Measured r;
  r.h = symmetric_impact(scene, scene.objects[flyer].velocity(0), v_target);
  r.eos_p_at_rho_h = mie_gruneisen_hugoniot(std::get<MieGruneisenParams>(params.equation_of_state),
                                            params.density, r.h.rho)
                         .pressure;
  r.rho0_gamma0 = params.density * std::get<MieGruneisenParams>(params.equation_of_state).Gamma0;
  const Particles& P = sim.particles();
  const Layers layers = target_layers(P, target, scene.grid);
  const double dx = scene.grid.spacing()(0);
  while (!sim.finished()) {
    sim.step();
    if (r.t1 == 0.0 && sim.time() >= 0.5 * scene.time.max_time) {
      r.t1 = sim.time();
      r.front1 = crossing(layers, profile(P, layers).p, 0.5 * r.h.p);
    }
  }
  r.t2 = sim.time();
  const Profile m = profile(P, layers);
  r.front2 = crossing(layers, m.p, 0.5 * r.h.p);
  r.shock_speed = (r.front2 - r.front1) / (r.t2 - r.t1);
  r.width = crossing(layers, m.p, 0.1 * r.h.p) - crossing(layers, m.p, 0.9 * r.h.p);
  // The plateau window (initial x): from 25 cells behind the impact face (x = 0 in the scene) to
  // 50 cells behind the Hugoniot front position U_s t.
  const double face = layers.X.front() - 0.5 * dx / scene.objects[target].particles_per_cell[0];
  r.window_lo = face + 25.0 * dx;
  r.window_hi = face + r.h.U_s * r.t2 - 50.0 * dx;
  std::vector<double> p, sxx, u, q, e, ep;
  std::map<int, std::pair<double, int>> cells;
  for (std::size_t k = 0; k < layers.X.size(); ++k) {
    if (layers.X[k] >= r.window_lo && layers.X[k] < r.front2) r.peak = std::max(r.peak, m.p[k]);
    if (layers.X[k] < r.window_lo || layers.X[k] > r.window_hi) continue;
    p.push_back(m.p[k]);
    sxx.push_back(m.sxx[k]);
    u.push_back(m.v[k] - v_target);
    q.push_back(m.q[k]);
    e.push_back(m.e[k]);
    ep.push_back(m.ep[k]);
    cells[layers.cell[k]].first += m.p[k];
    cells[layers.cell[k]].second += 1;
  }
  std::vector<double> p_cell;
  for (const auto& [c, sum] : cells) p_cell.push_back(sum.first / sum.second);
  r.p = stats(p);
  r.sxx = stats(sxx);
  r.u = stats(u);
  r.q = stats(q);
  r.e = stats(e);
  r.ep = stats(ep);
  r.face_velocity = m.v.front() - v_target;
  r.p_cell = stats(p_cell);
  const LedgerRow row = sim.ledger().row();
  r.energy_error = row.energy_error;
  r.initial_energy = sim.ledger().initial_energy();
  for (std::size_t i = 0; i < sim.ledger().sink_names().size(); ++i) {
    if (sim.ledger().sink_names()[i] == "viscous_work") r.viscous_work = row.sinks[i];
  }
  const auto& jc = std::get<JohnsonCookParams>(params.flow_stress);
  r.yield_at_ep = jc.A + jc.B * std::pow(r.ep.mean, jc.n);
  r.steps = sim.steps();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void report(const char* label, const Measured& r) {
  const double pH = r.h.p;
  const double e_H = 0.5 * r.h.u_p * r.h.u_p;
  BOOST_TEST_MESSAGE(label << ": Hugoniot u_p " << r.h.u_p << " m/s, U_s " << r.h.U_s
                           << " m/s, p_H " << pH << " Pa, rho_H " << r.h.rho
                           << " kg/m^3 (EOS p_H(rho_H) " << r.eos_p_at_rho_h << " Pa); " << r.steps
                           << " steps, " << r.seconds << " s");
  BOOST_TEST_MESSAGE(label << ": window x0 = " << r.window_lo * 1e3 << "-" << r.window_hi * 1e3
                           << " mm (" << r.p.n << " layers): pressure " << r.p.mean << " Pa ("
                           << (r.p.mean / pH - 1) * 100 << " %), -sigma_xx " << r.sxx.mean
                           << " Pa (" << (r.sxx.mean / pH - 1) * 100 << " %), particle velocity "
                           << r.u.mean << " m/s (" << (r.u.mean / r.h.u_p - 1) * 100
                           << " %), mean q " << r.q.mean / pH << " p_H");
  BOOST_TEST_MESSAGE(label << ": oscillation over the window (/ p_H): per layer [" << r.p.lo / pH
                           << ", " << r.p.hi / pH << "], max - min " << (r.p.hi - r.p.lo) / pH
                           << ", std " << r.p.stddev / pH << "; cell means max - min "
                           << (r.p_cell.hi - r.p_cell.lo) / pH << ", std " << r.p_cell.stddev / pH
                           << "; particle velocity [" << r.u.lo << ", " << r.u.hi
                           << "] m/s; peak pressure behind the front " << r.peak / pH);
  BOOST_TEST_MESSAGE(label << ": front (p_H/2) at x0 = " << r.front1 * 1e3
                           << " mm at t = " << r.t1 * 1e6 << " us, " << r.front2 * 1e3 << " mm at "
                           << r.t2 * 1e6 << " us: shock speed " << r.shock_speed << " m/s ("
                           << (r.shock_speed / r.h.U_s - 1) * 100 << " % vs U_s); front width "
                           << "(10 -> 90 % of p_H) " << r.width * 1e3 << " mm");
  BOOST_TEST_MESSAGE(label << ": internal energy " << r.e.mean << " J/kg vs e_H = u_p^2/2 = " << e_H
                           << " J/kg: rho0 Gamma0 (e - e_H) = "
                           << r.rho0_gamma0 * (r.e.mean - e_H) / pH
                           << " p_H; impact-face layer v - v_target " << r.face_velocity
                           << " m/s (FLIP keeps the initial jump the grid cannot see)");
  if (r.yield_at_ep > 1e6) {  // the strength runs: the deviator behind the shock
    BOOST_TEST_MESSAGE(label << ": plastic strain " << r.ep.mean
                             << "; 1.5 (-sigma_xx - p) = " << 1.5 * (r.sxx.mean - r.p.mean)
                             << " Pa vs A + B ep^n " << r.yield_at_ep << " Pa");
  }
  BOOST_TEST_MESSAGE(label << ": ledger at the end: energy_error " << r.energy_error
                           << ", viscous_work " << r.viscous_work << " J ("
                           << r.viscous_work / r.initial_energy * 100 << " % of E0 "
                           << r.initial_energy << " J)");
}

void check_hugoniot(const Measured& r) {
  BOOST_TEST(std::abs(r.eos_p_at_rho_h / r.h.p - 1.0) < 1e-12);
  BOOST_TEST(r.p.n >= 100);
  BOOST_TEST(std::abs(r.p.mean / r.h.p - 1.0) < 0.03);
  BOOST_TEST(std::abs(r.u.mean / r.h.u_p - 1.0) < 0.03);
  BOOST_TEST(std::abs(r.shock_speed / r.h.U_s - 1.0) < 0.02);
}

const Json kViscosity = {
    {"physics",
     {{"artificial_viscosity", {{"enabled", true}, {"linear", 0.2}, {"quadratic", 2.0}}}}}};

/// The alloy's own Johnson-Cook A, B, C (data/materials/al6061_t6.json) over the scene's
/// hydrodynamic override.
Json with_strength(const Json& patch) {
  Json p = patch;
  p["materials"]["al_mg"]["overrides"]["constitutive_model"]["flow_stress"] = {
      {"A", 324.0e6}, {"B", 114.0e6}, {"C", 0.002}};
  return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_flyer_plate)

BOOST_AUTO_TEST_CASE(hugoniot_state_without_artificial_viscosity) {
  const Measured r = impact_run(Json::object());
  report("no AV", r);
  check_hugoniot(r);
  BOOST_TEST(r.viscous_work == 0.0);
}

BOOST_AUTO_TEST_CASE(hugoniot_state_with_artificial_viscosity) {
  const Measured r = impact_run(kViscosity);
  report("AV 0.2/2.0", r);
  check_hugoniot(r);
  BOOST_TEST(r.viscous_work > 0.0);
  // The viscosity damps the ringing: cell-mean pressure std over the window (measured 0.6 %,
  // 4.1 % without AV).
  BOOST_TEST(r.p_cell.stddev / r.h.p < 0.02);
}

// Reported only: the alloy's strength restored. The mean stress and -sigma_xx straddle p_H (see
// the header); u_p = v/2 holds by symmetry whatever the strength, and is asserted.
BOOST_AUTO_TEST_CASE(with_strength_reported) {
  const Measured plain = impact_run(with_strength(Json::object()));
  report("strength, no AV", plain);
  BOOST_TEST(std::abs(plain.u.mean / plain.h.u_p - 1.0) < 0.03);
  const Measured viscous = impact_run(with_strength(kViscosity));
  report("strength, AV 0.2/2.0", viscous);
  BOOST_TEST(std::abs(viscous.u.mean / viscous.h.u_p - 1.0) < 0.03);
}

BOOST_AUTO_TEST_SUITE_END()
