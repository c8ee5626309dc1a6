// Verification case: Simple shear to gamma = 5: Green-Naghdi against Dienes (1979); Jaumann
// oscillates.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

std::vector<Check> simple_shear(const SuiteContext& ctx) {
  Recorder rec("simple_shear_gamma5");
  const double mu_file = 26e9;  // only for checking the closed form itself
  // The closed form against its own small-gamma series and against quadrature.
  for (double g : {0.05, 0.1}) {
    const cf::ShearStress d = cf::green_naghdi_simple_shear(mu_file, g);
    const cf::ShearStress s = cf::green_naghdi_simple_shear_series(mu_file, g);
    rec.compare("Dienes closed form vs its series (derived from the rate equation), gamma = " +
                    num(g) + ": sigma_xy",
                s.xy, d.xy, 1e-9);
    rec.compare("Dienes closed form vs its series, gamma = " + num(g) + ": sigma_xx", s.xx, d.xx,
                1e-9);
  }
  {
    const cf::ShearStress d = cf::green_naghdi_simple_shear(mu_file, 5.0);
    const cf::ShearStress q = cf::green_naghdi_simple_shear_quadrature(mu_file, 5.0, 20000);
    rec.compare(
        "Dienes closed form vs Simpson quadrature of the GN rate equation, gamma = 5: "
        "sigma_xy",
        q.xy, d.xy, 1e-10);
    rec.compare("Dienes closed form vs Simpson quadrature, gamma = 5: sigma_xx", q.xx, d.xx, 1e-10);
  }

  const int steps = 5000;
  const Json leg = {
      {"type", "simple_shear"}, {"gamma", 5.0}, {"gamma_rate", 1000.0}, {"steps", steps}};
  const Run gn = run(path_document(ctx, elastic_patch(), leg), "simple shear, Green-Naghdi");
  Json jaumann_patch = elastic_patch();
  jaumann_patch["constitutive_model"]["objective_rate"] = "jaumann";
  const Run ja = run(path_document(ctx, jaumann_patch, leg), "simple shear, Jaumann");
  const double mu = gn.params().shear_modulus;

  double gn_scale = 0.0;
  for (const Row& r : gn.rows) {
    const cf::ShearStress d = cf::green_naghdi_simple_shear(mu, r.F(0, 1));
    gn_scale = std::max({gn_scale, std::abs(d.xy), std::abs(d.xx)});
  }
  Worst gn_xy, gn_xx, gn_yy, ja_xy, ja_xx;
  double gn_min_xy = std::numeric_limits<double>::infinity();
  FigureCsv fig(ctx, "simple_shear.csv",
                {"gamma [-]", "green_naghdi_xy [Pa]", "jaumann_xy [Pa]", "dienes_xy [Pa]",
                 "mu_sin_gamma [Pa]", "green_naghdi_xx [Pa]", "jaumann_xx [Pa]", "dienes_xx [Pa]",
                 "mu_one_minus_cos_gamma [Pa]"});
  for (std::size_t i = 0; i < gn.rows.size() && i < ja.rows.size(); ++i) {
    const Row& g = gn.rows[i];
    const Row& j = ja.rows[i];
    const double gamma = g.F(0, 1);
    const cf::ShearStress d = cf::green_naghdi_simple_shear(mu, gamma);
    const cf::ShearStress z = cf::jaumann_simple_shear(mu, j.F(0, 1));
    if (i > 0) {
      gn_xy.update(d.xy, g.state.stress(0, 1), gn_scale);
      gn_xx.update(d.xx, g.state.stress(0, 0), gn_scale);
      gn_yy.update(d.yy, g.state.stress(1, 1), gn_scale);
      ja_xy.update(z.xy, j.state.stress(0, 1), mu);
      ja_xx.update(z.xx, j.state.stress(0, 0), mu);
      gn_min_xy = std::min(gn_min_xy, g.state.stress(0, 1));
    }
    if (i % 10 == 0) {
      fig.row({gamma, g.state.stress(0, 1), j.state.stress(0, 1), d.xy, z.xy, g.state.stress(0, 0),
               j.state.stress(0, 0), d.xx, z.xx});
    }
  }
  fig.close();
  const std::string n = std::to_string(steps) + " steps";
  rec.worst("Green-Naghdi, " + n + ": sigma_xy = Dienes (1979) (error / max |sigma|)", gn_xy, 1e-6);
  rec.worst("Green-Naghdi, " + n + ": sigma_xx = Dienes (error / max |sigma|)", gn_xx, 1e-6);
  rec.worst("Green-Naghdi, " + n + ": sigma_yy = -sigma_xx (error / max |sigma|)", gn_yy, 1e-6);
  rec.add("Green-Naghdi sigma_xy stays positive up to gamma = 5 (got: its minimum)", 0.0, gn_min_xy,
          0.0, 0.0, gn_min_xy > 0.0);
  // The Jaumann update (midpoint form: half a Hughes-Winget rotation, the increment, the other
  // half) is second order: its error is ~ mu dgamma^2 / 20 (measured 5.2e-8 mu for sigma_xy and
  // 9.7e-8 mu for sigma_xx at dgamma = 1e-3). The tolerance is 0.2 dgamma^2, and a second run
  // with half the steps must show the error growing fourfold.
  const double dgamma = 5.0 / steps;
  const double ja_tol = 0.2 * dgamma * dgamma;
  rec.worst("Jaumann, " + n +
                ": sigma_xy = mu sin gamma (error / mu; second order, tolerance 0.2 dgamma^2)",
            ja_xy, ja_tol);
  rec.worst(
      "Jaumann, " + n + ": sigma_xx = mu (1 - cos gamma) (error / mu; tolerance 0.2 dgamma^2)",
      ja_xx, ja_tol);
  {
    Json coarse = leg;
    coarse["steps"] = steps / 2;
    const Run jc = run(path_document(ctx, jaumann_patch, coarse), "simple shear, Jaumann, coarse");
    Worst coarse_xy;
    for (std::size_t i = 1; i < jc.rows.size(); ++i) {
      coarse_xy.update(mu * std::sin(jc.rows[i].F(0, 1)), jc.rows[i].state.stress(0, 1), mu);
    }
    rec.compare("Jaumann converges at second order: error(" + std::to_string(steps / 2) +
                    " steps) / error(" + std::to_string(steps) + " steps) = 4",
                4.0, coarse_xy.error / ja_xy.error, 0.05);
  }
  const double ja_end = ja.rows.back().state.stress(0, 1);
  rec.add("Jaumann sigma_xy has turned negative at gamma = 5 (mu sin 5 < 0: the oscillation)",
          mu * std::sin(5.0), ja_end, std::abs(ja_end - mu * std::sin(5.0)) / mu, ja_tol,
          ja_end < 0.0 && std::abs(ja_end - mu * std::sin(5.0)) <= ja_tol * mu);
  return rec.take();
}

}  // namespace impact::pointdriver::verify
