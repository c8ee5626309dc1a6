// Verification case: Elastic uniaxial strain and uniaxial stress.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

std::vector<Check> elastic_uniaxial(const SuiteContext& ctx) {
  Recorder rec("elastic_uniaxial");
  const Run strain = run(path_document(ctx, elastic_patch(),
                                       Json{{"type", "uniaxial_strain"},
                                            {"strain", -0.01},
                                            {"strain_rate", -100.0},
                                            {"steps", 100}}),
                         "elastic uniaxial strain");
  const auto& p = strain.params();
  const double K = p.bulk_modulus, mu = p.shear_modulus;
  const double M = cf::constrained_modulus(K, mu), E = cf::young_modulus(K, mu);
  const double nu = cf::poisson_ratio(K, mu);
  Worst sxx, syy;
  for (const Row& r : strain.rows) {
    if (r.step == 0) continue;
    const double e = axial_log_strain(r);
    sxx.update(M * e, r.state.stress(0, 0), std::abs(M * e));
    syy.update((K - 2.0 * mu / 3.0) * e, r.state.stress(1, 1), std::abs((K - 2.0 * mu / 3.0) * e));
  }
  rec.worst("uniaxial strain to -0.01: sigma_xx = (K + 4mu/3) eps_xx", sxx, 1e-10);
  rec.worst("uniaxial strain to -0.01: sigma_yy = (K - 2mu/3) eps_xx", syy, 1e-10);

  const Run stress = run(path_document(ctx, elastic_patch(),
                                       Json{{"type", "uniaxial_stress"},
                                            {"strain", 0.01},
                                            {"strain_rate", 100.0},
                                            {"steps", 100}}),
                         "elastic uniaxial stress");
  Worst poisson_y, poisson_z, young;
  for (const Row& r : stress.rows) {
    if (r.step == 0) continue;
    const double exx = axial_log_strain(r, 0);
    poisson_y.update(nu, -axial_log_strain(r, 1) / exx, nu);
    poisson_z.update(nu, -axial_log_strain(r, 2) / exx, nu);
    young.update(E * exx, r.state.stress(0, 0), std::abs(E * exx));
  }
  rec.worst("uniaxial stress to 0.01: -eps_yy/eps_xx = nu = (3K-2mu)/(2(3K+mu))", poisson_y, 1e-10);
  rec.worst("uniaxial stress to 0.01: -eps_zz/eps_xx = nu", poisson_z, 1e-10);
  rec.worst("uniaxial stress to 0.01: sigma_xx = E eps_xx, E = 9K mu/(3K+mu)", young, 1e-10);
  return rec.take();
}

}  // namespace impact::pointdriver::verify
