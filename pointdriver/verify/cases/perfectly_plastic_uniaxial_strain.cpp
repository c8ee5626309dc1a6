// Verification case: Elastic-perfectly-plastic uniaxial strain: yield point and plateau.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

std::vector<Check> perfectly_plastic_uniaxial_strain(const SuiteContext& ctx) {
  Recorder rec("perfectly_plastic_uniaxial_strain");
  const Json patch = model_patch(Json{{"flow_stress", Json{{"B", 0.0}, {"C", 0.0}}}});
  const Run r = run(path_document(ctx, patch,
                                  Json{{"type", "uniaxial_strain"},
                                       {"strain", -0.02},
                                       {"strain_rate", -1.0},
                                       {"steps", 2000}}),
                    "perfectly plastic uniaxial strain");
  const auto& p = r.params();
  const double K = p.bulk_modulus, mu = p.shear_modulus, Y = parameter(p.flow_stress, "A");
  const cf::UniaxialStrainYield y = cf::uniaxial_strain_yield(K, mu, Y);
  const double M = cf::constrained_modulus(K, mu);

  Worst elastic_slope, plateau;
  int last_elastic = -1;
  for (std::size_t i = 1; i < r.rows.size(); ++i) {
    const Row& row = r.rows[i];
    const double e = axial_log_strain(row);
    if (row.state.plastic_strain == 0.0) {
      elastic_slope.update(M, row.state.stress(0, 0) / e, M);
      last_elastic = static_cast<int>(i);
    } else {
      plateau.update(Y, std::abs(row.state.stress(0, 0) - row.state.stress(1, 1)), Y);
    }
  }
  rec.worst("elastic part: sigma_xx / eps_xx = K + 4mu/3", elastic_slope, 1e-10);
  rec.worst("plastic part: |sigma_xx - sigma_yy| = A (plateau)", plateau, 1e-10);

  // The yield point where the elastic line (through the last elastic row) meets the plastic line
  // (through the last two rows); both are straight, so the intersection is exact.
  const std::size_t n = r.rows.size();
  if (last_elastic > 0 && n >= 3 && static_cast<std::size_t>(last_elastic) + 2 < n) {
    const Row& re = r.rows[static_cast<std::size_t>(last_elastic)];
    const double ke = re.state.stress(0, 0) / axial_log_strain(re);
    const double e1 = axial_log_strain(r.rows[n - 2]), e2 = axial_log_strain(r.rows[n - 1]);
    const double s1 = r.rows[n - 2].state.stress(0, 0), s2 = r.rows[n - 1].state.stress(0, 0);
    const double kp = (s2 - s1) / (e2 - e1), c = s2 - kp * e2;
    const double ey = c / (ke - kp);
    rec.compare("yield point: eps_xx = -A/(2mu) where the elastic and plastic lines meet",
                -y.strain, ey, 1e-9);
    rec.compare("yield point: sigma_xx = -(K + 4mu/3) A/(2mu) (Hugoniot elastic limit)",
                -y.axial_stress, ke * ey, 1e-9);
    rec.compare("plastic part: d sigma_xx / d eps_xx = K", K, kp, 1e-9);
    const double e_last = axial_log_strain(re),
                 e_next = axial_log_strain(r.rows[static_cast<std::size_t>(last_elastic) + 1]);
    // The first plastic step must bracket the closed-form yield strain.
    const bool bracketed = e_next <= -y.strain && -y.strain <= e_last;
    rec.add(
        "first plastic step brackets eps_y = -A/(2mu) (got: eps_xx of the first plastic step; "
        "error 0 when bracketed)",
        -y.strain, e_next, bracketed ? 0.0 : 1.0, 0.0, bracketed);
  } else {
    rec.add("yield point found on the path", 1, 0, nan, 0);
  }
  return rec.take();
}

}  // namespace impact::pointdriver::verify
