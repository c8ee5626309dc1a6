// Verification case: Johnson-Cook uniaxial stress at four rates and three temperatures.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

std::vector<Check> johnson_cook_uniaxial_stress(const SuiteContext& ctx) {
  Recorder rec("johnson_cook_uniaxial_stress");
  const std::vector<double> rates = {1e-3, 1.0, 1e3, 1e5};
  const std::vector<double> temperatures = {294.0, 500.0, 800.0};
  const int steps = 1000;
  const double strain = 0.2;
  std::vector<std::string> header = {"log_strain_xx [-]"};
  std::vector<std::vector<double>> driver_cols, jc_cols;
  Worst own_flow, own_strain;
  for (double T : temperatures) {
    for (double rate : rates) {
      const std::string label = "rate " + num(rate) + " /s, T " + num(T) + " K";
      const Run r = run(path_document(ctx, Json::object(),
                                      Json{{"type", "uniaxial_stress"},
                                           {"strain", strain},
                                           {"strain_rate", rate},
                                           {"steps", steps}},
                                      T),
                        "JC uniaxial stress " + label);
      const auto& p = r.params();
      const double E = cf::young_modulus(p.bulk_modulus, p.shear_modulus);
      // The suite's material is Johnson-Cook (the patch above keeps it so); by name, through the
      // law (models/flow_stress/flow_stress_law.hpp).
      const auto jc_parameter = [&](const char* name) { return parameter(p.flow_stress, name); };
      const cf::JohnsonCook jc{jc_parameter("A"),  jc_parameter("B"),
                               jc_parameter("n"),  jc_parameter("C"),
                               jc_parameter("m"),  jc_parameter("reference_strain_rate"),
                               p.room_temperature, p.melt_temperature};
      Worst flow;
      std::vector<double> dcol, jcol;
      double ep_prev = 0.0, t_prev = 0.0, ep_max = 0.0;
      for (const Row& row : r.rows) {
        const double sxx = row.state.stress(0, 0);
        // Independent estimate of the plastic strain (hypoelastic uniaxial stress: the elastic
        // part of the axial log strain is sigma_xx / E) and of its rate (backward difference).
        const double ep = axial_log_strain(row) - sxx / E;
        const double ep_rate = row.step > 0 ? (ep - ep_prev) / (row.time - t_prev) : 0.0;
        const double reference = cf::johnson_cook_flow_stress(jc, ep, ep_rate, T);
        if (ep > 2e-3) flow.update(reference, sxx, reference);
        if (row.state.plastic_strain > 0.0) {
          const double own = cf::johnson_cook_flow_stress(jc, row.state.plastic_strain,
                                                          row.state.plastic_strain_rate, T);
          own_flow.update(own, sxx, own);
        }
        ep_max = std::max(ep_max, row.state.plastic_strain);
        ep_prev = ep;
        t_prev = row.time;
        dcol.push_back(sxx);
        jcol.push_back(row.step > 0 && ep > 0.0 ? reference : nan);
      }
      for (const Row& row : r.rows) {
        own_strain.update(axial_log_strain(row) - row.state.stress(0, 0) / E,
                          row.state.plastic_strain, ep_max);
      }
      rec.worst(label +
                    ": sigma_xx = JC(eps_p, rate, T) with eps_p = eps_xx - sigma_xx/E, rate = " +
                    "its backward difference (rows with eps_p > 2e-3)",
                flow, 1e-3);
      header.push_back("driver_" + num(rate) + "_per_s_" + num(T) + "K [Pa]");
      header.push_back("johnson_cook_" + num(rate) + "_per_s_" + num(T) + "K [Pa]");
      driver_cols.push_back(dcol);
      jc_cols.push_back(jcol);
    }
  }
  rec.worst(
      "all 12 runs: independent eps_xx - sigma_xx/E equals the driver's plastic strain "
      "(relative to the run's final eps_p)",
      own_strain, 1e-8);
  rec.worst("all 12 runs: sigma_xx = JC(driver's own eps_p and plastic rate, T) (tighter)",
            own_flow, 1e-9);
  FigureCsv fig(ctx, "johnson_cook_flow_curves.csv", header);
  for (int i = 0; i <= steps; ++i) {
    std::vector<double> v = {strain * i / steps};
    for (std::size_t c = 0; c < driver_cols.size(); ++c) {
      v.push_back(driver_cols[c][static_cast<std::size_t>(i)]);
      v.push_back(jc_cols[c][static_cast<std::size_t>(i)]);
    }
    fig.row(v);
  }
  fig.close();
  return rec.take();
}

}  // namespace impact::pointdriver::verify
