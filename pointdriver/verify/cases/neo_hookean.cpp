// Verification case: the compressible neo-Hookean solid (data/materials/neo_hookean_soft.json) at
// large strain, driven by the point driver's mixed control: uniaxial stress to a stretch of 2 and
// of 1/2 (the lateral stretch found by the driver against the root of sigma_yy = 0), and simple
// shear to gamma = 2, against closed forms written from the stored energy alone
// (closed_forms.hpp). The stress work the driver integrates, int J sigma : D dt, must equal the
// stored energy W(F) of the end state: a hyperelastic law does no net work round a path.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"
#include "support/shipped_file.hpp"

namespace impact::pointdriver::verify {

namespace {

// W(F) per unit reference volume, from its definition (not the library's).
double stored_energy(const Mat3& F, double mu, double lambda) {
  const double lnJ = std::log(F.determinant());
  return 0.5 * mu * ((F.transpose() * F).trace() - 3.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
}

Json neo_hookean_path(const Json& leg) {
  Json doc = Json::object();
  doc["material"] =
      Json{{"file", fs::absolute(shipped_file("data/materials/neo_hookean_soft.json")).string()}};
  doc["temperature"] = 294.0;
  doc["thermal"] = "isothermal";
  doc["failure_policy"] = "stop";
  doc["legs"] = Json::array({leg});
  return doc;
}

}  // namespace

std::vector<Check> neo_hookean(const SuiteContext&) {
  Recorder rec("neo_hookean_large_strain");
  for (const double stretch : {2.0, 0.5}) {
    const std::string name = "uniaxial stress to a stretch of " + num(stretch);
    const Run r = run(neo_hookean_path(Json{{"type", "uniaxial_stress"},
                                            {"strain", std::log(stretch)},
                                            {"strain_rate", stretch > 1.0 ? 100.0 : -100.0},
                                            {"steps", 200}}),
                      "neo-Hookean " + name);
    const double mu = r.params().shear_modulus;
    const double lambda = r.params().bulk_modulus - 2.0 / 3.0 * mu;
    const double scale = std::abs(cf::neo_hookean_uniaxial_stress(mu, lambda, stretch).axial);
    Worst axial, lateral_y, lateral_z;
    for (const Row& row : r.rows) {
      if (row.step == 0) continue;
      const cf::UniaxialStretch c = cf::neo_hookean_uniaxial_stress(mu, lambda, row.F(0, 0));
      axial.update(c.axial, row.state.stress(0, 0), scale);
      lateral_y.update(c.lateral, row.F(1, 1), c.lateral);
      lateral_z.update(c.lateral, row.F(2, 2), c.lateral);
    }
    const Row& end = r.rows.back();
    rec.worst(name + ": sigma_xx = mu (s^2 - t^2) / (s t^2) (error / max |sigma_xx|)", axial, 1e-9);
    rec.worst(name + ": lateral stretch t, root of mu (t^2 - 1) + lambda ln(s t^2) = 0", lateral_y,
              1e-9);
    rec.worst(name + ": lateral stretch along z = along y", lateral_z, 1e-9);
    const double W = stored_energy(end.F, mu, lambda);
    // The driver's trapezoid of J sigma : D over 200 steps: second order in the step.
    rec.compare(name + ": stress work of the path = stored energy W(F) (relative)", W,
                end.stress_work, 1e-4);
  }
  {
    const Run r =
        run(neo_hookean_path(Json{
                {"type", "simple_shear"}, {"gamma", 2.0}, {"gamma_rate", 1000.0}, {"steps", 200}}),
            "neo-Hookean simple shear");
    const double mu = r.params().shear_modulus;
    const double lambda = r.params().bulk_modulus - 2.0 / 3.0 * mu;
    const double scale = mu * 4.0;  // mu gamma^2 at the end
    Worst xy, xx, yy, zz;
    for (const Row& row : r.rows) {
      if (row.step == 0) continue;
      const cf::ShearStress c = cf::neo_hookean_simple_shear(mu, row.F(0, 1));
      xy.update(c.xy, row.state.stress(0, 1), scale);
      xx.update(c.xx, row.state.stress(0, 0), scale);
      yy.update(c.yy, row.state.stress(1, 1), scale);
      zz.update(0.0, row.state.stress(2, 2), scale);
    }
    rec.worst("simple shear to gamma = 2: sigma_xy = mu gamma (error / mu gamma_end^2)", xy, 1e-12);
    rec.worst("simple shear to gamma = 2: sigma_xx = mu gamma^2", xx, 1e-12);
    rec.worst("simple shear to gamma = 2: sigma_yy = 0", yy, 1e-12);
    rec.worst("simple shear to gamma = 2: sigma_zz = 0", zz, 1e-12);
    rec.compare("simple shear to gamma = 2: stress work = W(F) = mu gamma^2 / 2 (relative)",
                stored_energy(r.rows.back().F, mu, lambda), r.rows.back().stress_work, 1e-4);
  }
  return rec.take();
}

}  // namespace impact::pointdriver::verify
