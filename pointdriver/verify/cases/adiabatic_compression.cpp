// Verification case: Adiabatic uniaxial compression at 4000 /s: heating and the Drucker check.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

std::vector<Check> adiabatic_compression(const SuiteContext& ctx) {
  Recorder rec("adiabatic_compression_4000");
  const Json leg = {{"type", "uniaxial_stress"},
                    {"strain", -1.0},
                    {"strain_rate", -4000.0},
                    {"max_strain_increment", 2.5e-4}};
  // (a) failure detection off (erosion none): the whole softening curve.
  const Run a = run(path_document(ctx, model_patch(Json{{"erosion", Json{{"algorithm", "none"}}}}),
                                  leg, 294.0, "adiabatic", "continue"),
                    "adiabatic compression, no failure detection");
  // (b) the material file as it is (erosion AllowNoTension, drucker_becker), stop at failure.
  const Run b = run(path_document(ctx, Json::object(), leg, 294.0, "adiabatic", "stop"),
                    "adiabatic compression, stop at failure");
  const auto& p = a.params();
  const double chi = p.heating.taylor_quinney, cp = p.specific_heat,
               T0 = a.rows.front().state.temperature;

  // Temperature rise against chi * int sigma_eq d eps_p / (rho cp), trapezoidal over the rows.
  Worst heating;
  double work = 0.0;  // plastic work per unit mass [J/kg]
  double peak = -1.0, ep_peak = 0.0, dep_peak = 0.0;
  FigureCsv fig(
      ctx, "adiabatic_compression.csv",
      {"plastic_strain [-]", "von_mises [Pa]", "temperature [K]", "temperature_reference [K]"});
  for (std::size_t i = 1; i < a.rows.size(); ++i) {
    const Row& r0 = a.rows[i - 1];
    const Row& r1 = a.rows[i];
    const double q0 = von_mises_of(r0.state.stress) * r0.state.F.determinant() / p.density;
    const double q1 = von_mises_of(r1.state.stress) * r1.state.F.determinant() / p.density;
    const double dep = r1.state.plastic_strain - r0.state.plastic_strain;
    work += 0.5 * (q0 + q1) * dep;
    const double rise = cf::adiabatic_temperature_rise(chi, work, cp);
    if (r1.state.plastic_strain >= 0.05) heating.update(rise, r1.state.temperature - T0, rise);
    const double vm = von_mises_of(r1.state.stress);
    if (vm > peak) {
      peak = vm;
      ep_peak = r1.state.plastic_strain;
      dep_peak = dep;
    }
    if (i % 4 == 0) fig.row({r1.state.plastic_strain, vm, r1.state.temperature, T0 + rise});
  }
  fig.close();
  rec.worst(
      "T - T0 = chi int sigma_eq d eps_p / (rho cp), trapezoid over the rows (rows with eps_p >= "
      "0.05)",
      heating, 1e-3);

  // Drucker fires at the maximum of sigma_eq(eps_p).
  const Row& last = b.rows.back();
  const bool failed = b.result.failure != FailureCause::none;
  rec.add("run (b) fails by Drucker (failure cause 3 = drucker)",
          double(int(FailureCause::drucker)), double(int(b.result.failure)), failed ? 0.0 : 1.0,
          0.0, b.result.failure == FailureCause::drucker && last.drucker_indicator < 0.0);
  const double ep_fail = last.state.plastic_strain;
  const bool earlier_stable = [&] {
    for (std::size_t i = 0; i + 1 < b.rows.size(); ++i) {
      if (b.rows[i].drucker_checked && !(b.rows[i].drucker_indicator > 0.0)) return false;
    }
    return true;
  }();
  rec.add(
      "eps_p where Drucker fires = eps_p at max sigma_eq of the no-failure run (tolerance: 3 "
      "steps' plastic-strain increment; Drucker indicator > 0 before)",
      ep_peak, ep_fail, std::abs(ep_fail - ep_peak) / ep_peak, 3.0 * dep_peak / ep_peak,
      failed && earlier_stable && std::abs(ep_fail - ep_peak) <= 3.0 * dep_peak);
  return rec.take();
}

}  // namespace impact::pointdriver::verify
