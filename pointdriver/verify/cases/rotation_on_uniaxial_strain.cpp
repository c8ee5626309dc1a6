// Verification case: Rigid rotation superposed on uniaxial strain.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

std::vector<Check> rotation_on_uniaxial_strain(const SuiteContext& ctx) {
  Recorder rec("rotation_on_uniaxial_strain");
  const Json base = {
      {"type", "uniaxial_strain"}, {"strain", -0.05}, {"strain_rate", -1000.0}, {"steps", 500}};
  const Run ref = run(path_document(ctx, Json::object(), base), "uniaxial strain, no rotation");
  const double duration = ref.rows.back().time;
  struct Spin {
    std::string label;
    Vec3 axis;
    double angle;
  };
  const std::vector<Spin> spins = {
      {"quarter turn about z", Vec3(0, 0, 1), std::numbers::pi / 2},
      {"full turn about (1, 2, 3)", Vec3(1, 2, 3).normalized(), 2 * std::numbers::pi}};
  for (const Spin& s : spins) {
    Json leg = base;
    leg["rotation"] = {{"axis", {s.axis.x(), s.axis.y(), s.axis.z()}}, {"angle", s.angle}};
    const Run rot = run(path_document(ctx, Json::object(), leg), "uniaxial strain, " + s.label);
    Worst lab, unrotated, pressure, mises, ep;
    const std::size_t n = std::min(ref.rows.size(), rot.rows.size());
    double scale = 0.0;
    for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, max_abs(ref.rows[i].state.stress));
    for (std::size_t i = 1; i < n; ++i) {
      const Row& r0 = ref.rows[i];
      const Row& r1 = rot.rows[i];
      // The rotation written independently: Q(t) = exp(angle t / T [axis]x).
      const Mat3 Q = Eigen::AngleAxisd(s.angle * r1.time / duration, s.axis).toRotationMatrix();
      const Mat3 expected_lab = Q * r0.state.stress * Q.transpose();
      const Mat3 d_lab = r1.state.stress - expected_lab;
      const Mat3 d_unrot = r1.stress_path - r0.state.stress;
      lab.update(0.0, max_abs(d_lab), scale);
      unrotated.update(0.0, max_abs(d_unrot), scale);
      const double p0 = -r0.state.stress.trace() / 3, p1 = -r1.state.stress.trace() / 3;
      pressure.update(p0, p1, std::abs(p0));
      mises.update(von_mises_of(r0.state.stress), von_mises_of(r1.state.stress),
                   std::max(von_mises_of(r0.state.stress), 1.0));
      ep.update(r0.state.plastic_strain, r1.state.plastic_strain,
                std::max(ref.rows.back().state.plastic_strain, 1e-30));
    }
    const std::string l = s.label + ": ";
    rec.worst(l + "lab stress = Q sigma_norotation Q^T (max component error / max |sigma|)", lab,
              1e-10);
    rec.worst(l + "unrotated stress Q^T sigma Q = sigma_norotation (/ max |sigma|)", unrotated,
              1e-10);
    rec.worst(l + "pressure unchanged", pressure, 1e-10);
    rec.worst(l + "von Mises stress unchanged", mises, 1e-10);
    rec.worst(l + "plastic strain unchanged (/ final eps_p)", ep, 1e-10);
    const Mat3 Q_end = Eigen::AngleAxisd(s.angle, s.axis).toRotationMatrix();
    rec.add(l + "final superposed rotation Q = exp(angle [axis]x) (max component error)", 0.0,
            (rot.rows.back().Q - Q_end).cwiseAbs().maxCoeff(),
            (rot.rows.back().Q - Q_end).cwiseAbs().maxCoeff(), 1e-12);
  }
  return rec.take();
}

}  // namespace impact::pointdriver::verify
