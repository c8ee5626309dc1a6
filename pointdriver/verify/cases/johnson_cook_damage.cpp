// Verification case: Johnson-Cook damage at constant triaxiality.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

std::vector<Check> johnson_cook_damage(const SuiteContext& ctx) {
  Recorder rec("johnson_cook_damage_triaxiality");
  const Material m = load_material(ctx.material_file);
  const auto& dp = std::get<JohnsonCookDamageParams>(m.model.params().damage);
  const cf::JohnsonCookDamage jd{dp.D1,
                                 dp.D2,
                                 dp.D3,
                                 dp.D4,
                                 dp.D5,
                                 dp.reference_strain_rate,
                                 m.model.params().room_temperature,
                                 m.model.params().melt_temperature};
  // Erosion KeepStress: failure detection on (TEPLA), and the failed point keeps its stress, so
  // the step on which it fails can still meet the stress ratios. (With the file's AllowNoTension
  // the tensile cases cannot be solved on that step: the eroded stress is a pure deviator, which
  // no velocity gradient brings to the prescribed ratios; see docs/verification.md.)
  const Json patch = model_patch(Json{{"erosion", Json{{"algorithm", "KeepStress"}}}});
  for (double eta : {-1.0 / 3.0, 0.0, 1.0 / 3.0, 2.0 / 3.0}) {
    const std::string l = "triaxiality " + num(eta) + ": ";
    const double eps_f = cf::johnson_cook_fracture_strain(jd, eta, 1.0, 294.0);
    const double sign = eta >= 0.0 ? 1.0 : -1.0;
    Run r;
    try {
      r = run(path_document(ctx, patch,
                            Json{{"type", "constant_triaxiality"},
                                 {"triaxiality", eta},
                                 {"strain", sign * 1.3 * eps_f},
                                 {"strain_rate", sign * 1.0},
                                 {"max_strain_increment", 2e-4}}),
              "constant triaxiality " + num(eta));
    } catch (const std::exception& e) {
      rec.add(l + "path solved to failure (error: " + e.what() + ")", 1.0, 0.0, nan, 0.0);
      continue;
    }
    Worst held;
    for (const Row& row : r.rows) {
      if (row.state.plastic_strain > 0.0) {
        const Mat3& s = row.state.stress;
        held.update(eta, s.trace() / 3.0 / von_mises_of(s), 1.0);
      }
    }
    rec.worst(l + "sigma_m / sigma_eq held (absolute error)", held, 1e-6);
    const Row& last = r.rows.back();
    rec.add(l + "fails by TEPLA with D >= 1 (got: D at failure)", 1.0, last.state.damage, 0.0, 0.0,
            r.result.failure == FailureCause::tepla && last.state.damage >= 1.0);
    rec.compare(l + "plastic strain at failure = eps_f = D1 + D2 exp(D3 eta) (eq. 7, T* = 0)",
                eps_f, last.state.plastic_strain, 5e-3);
  }
  return rec.take();
}

}  // namespace impact::pointdriver::verify
