// output.plastic_work: the history column plastic_work [J], sum over steps and particles of
// sigma_eq,n+1 (ep_n+1 - ep_n) V_n+1 (mpm/step/step.hpp, StressTotals::plastic_work).
// Independent reference: an elastic-perfectly-plastic block (Johnson-Cook with B = 0, C = 0 and no
// heating, so the flow stress is A at every rate and strain) in homogeneous uniaxial-strain
// compression (the verification scene; v_x = -rate x). The radial return puts every plastic
// point's stress on the yield surface, sigma_eq = A, so each step's plastic work must be
// A sum_p (ep_n+1 - ep_n) V_n+1, computed here from the particle arrays (1e-9 relative: the
// return's round-off on sigma_eq). The plastic strains it multiplies follow the closed form of
// uniaxial strain where the release from the free x+ end has not arrived: sigma_eq = 2 mu eps
// until yield, then ep = (2/3)(eps - A/(2 mu)), eps = -ln(1 - rate t) the log strain (measured
// worst 4.7e-4 relative: asserted 5e-3). Also: the column is not a term of energy_error and changes
// nothing else (every other column identical with it off), and it stays below the strain energy.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "../verification_helpers.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

constexpr double kA = 324e6;  // Pa

Scene perfectly_plastic(bool plastic_work) {
  const Json jc = {
      {"type", "johnson_cook"}, {"A", kA}, {"B", 0.0}, {"n", 0.42}, {"C", 0.0}, {"m", 1.34}};
  const Json patch = {
      {"materials",
       {{"jc_al",
         {{"overrides",
           {{"constitutive_model",
             {{"flow_stress", jc}, {"adiabatic_heating", {{"enabled", false}}}}}}}}}}},
      {"output", {{"plastic_work", plastic_work}}}};
  return test::verification_scene("uniaxial_compression.json", patch);
}

constexpr double kRate = 3000.0;  // 1/s: 1.8 % strain in 6 us, yield near 0.6 %

void compress(Simulation& sim) {
  constexpr double rate = kRate;
  Particles& P = sim.particles();
  for (std::size_t p = 0; p < P.size(); ++p) P.v[p] = Vec3(-rate * P.x[p](0), 0, 0);
  sim.restart_ledger();
}

int column(const Ledger& ledger, const std::string& name) {
  const auto& names = ledger.sink_names();
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_plastic_work)

BOOST_AUTO_TEST_CASE(plastic_work_of_a_perfectly_plastic_block_is_A_times_the_plastic_volume) {
  const Scene scene = perfectly_plastic(true);
  Simulation on(scene), off(perfectly_plastic(false));
  compress(on);
  compress(off);
  const std::vector<Vec3> X = on.particles().x;
  const int k = column(on.ledger(), "plastic_work");
  BOOST_TEST_REQUIRE(k >= 0);
  BOOST_TEST(column(off.ledger(), "plastic_work") == -1);  // opt-in: no column when off
  const Particles& P = on.particles();
  double expected = 0.0, worst = 0.0;
  long plastic_steps = 0;
  while (!on.finished()) {
    std::vector<double> ep0(P.size());
    for (std::size_t p = 0; p < P.size(); ++p) ep0[p] = P.state[p].plastic_strain;
    const double before = on.ledger().state().sinks[std::size_t(k)];
    on.step();
    off.step();
    double step = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p)
      step += kA * (P.state[p].plastic_strain - ep0[p]) * P.volume[p];
    const double booked = on.ledger().state().sinks[std::size_t(k)] - before;
    if (step > 0.0) {
      ++plastic_steps;
      worst = std::max(worst, std::abs(booked / step - 1.0));
    } else {
      BOOST_TEST(booked == 0.0);
    }
    expected += step;
    // The column changes nothing else: the other columns of the two runs are the same bits.
    const LedgerRow a = on.ledger().row(), b = off.ledger().row();
    BOOST_TEST_REQUIRE(a.strain_energy == b.strain_energy);
    BOOST_TEST_REQUIRE(a.kinetic_energy == b.kinetic_energy);
    BOOST_TEST_REQUIRE(a.energy_error == b.energy_error);
  }
  const double total = on.ledger().state().sinks[std::size_t(k)];
  BOOST_TEST_MESSAGE("plastic work " << total << " J in " << plastic_steps
                                     << " plastic steps; worst step deviation " << worst
                                     << "; strain energy " << on.ledger().row().strain_energy
                                     << " J");
  BOOST_TEST(plastic_steps > 10);
  BOOST_TEST(worst < 1e-9);
  BOOST_TEST(std::abs(total / expected - 1.0) < 1e-9);
  BOOST_TEST(total > 0.0);
  BOOST_TEST(total < on.ledger().row().strain_energy);  // the rest is stored elastic energy

  const double mu = scene.materials[0].material.model.params().shear_modulus;
  const double eps = -std::log(1.0 - kRate * on.time());
  const double ep = 2.0 / 3.0 * (eps - kA / (2.0 * mu));
  const double reach = 1.05 * test::longitudinal_wave_speed(scene) * on.time() +
                       6.0 * on.grid().spacing()(0);  // the release front and its precursor
  double worst_ep = 0.0;
  std::size_t interior = 0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (X[p](0) > 0.1 - reach) continue;
    ++interior;
    worst_ep = std::max(worst_ep, std::abs(P.state[p].plastic_strain / ep - 1.0));
  }
  BOOST_TEST_MESSAGE("closed-form ep " << ep << " at log strain " << eps << "; " << interior
                                       << " interior particles, worst " << worst_ep);
  BOOST_TEST(interior > 100u);
  BOOST_TEST(worst_ep < 5e-3);
}

BOOST_AUTO_TEST_SUITE_END()
