// Verification case: Mixed control: stress-controlled components within the solver tolerance at
// every step.
#include "pointdriver/verify/case_support.hpp"
#include "pointdriver/verify/cases/cases.hpp"

namespace impact::pointdriver::verify {

std::vector<Check> mixed_control(const SuiteContext& ctx) {
  Recorder rec("mixed_control");
  struct Case {
    std::string label;
    Json leg;
    /// target of stress component c (0..5) at a row, or NaN if not stress-controlled
    std::function<double(const Row&, int)> target;
  };
  const double pc = 200e6, tc = 1e-4;
  const double txy = 150e6, t_off = 1e-4;
  const std::vector<Case> cases = {
      {"triaxial, 200 MPa confinement then axial compression",
       Json{{"type", "triaxial"},
            {"confining_pressure", pc},
            {"confinement_duration", tc},
            {"strain", -0.1},
            {"strain_rate", -1000.0},
            {"steps", 500}},
       [&](const Row& r, int c) {
         if (c >= 3) return 0.0;
         if (r.leg == 0) return -pc * r.time / tc;
         return c == 0 ? nan : -pc;
       }},
      {"equibiaxial stress to 0.1",
       Json{{"type", "equibiaxial_stress"},
            {"strain", 0.1},
            {"strain_rate", 1000.0},
            {"steps", 500}},
       [](const Row&, int c) { return c == 0 || c == 1 ? nan : 0.0; }},
      {"off-axis: L_xx = 1000 /s with sigma_xy ramped to 150 MPa, other stresses zero",
       Json{{"duration", t_off},
            {"steps", 500},
            {"velocity_gradient", {{"xx", 1000.0}}},
            {"stress", {{"xy", txy}, {"yy", 0.0}, {"zz", 0.0}}}},
       [&](const Row& r, int c) { return c == 0   ? nan
                                         : c == 3 ? txy * r.time / t_off
                                                  : 0.0; }},
  };
  for (const Case& c : cases) {
    const Run r = run(path_document(ctx, Json::object(), c.leg), "mixed control: " + c.label);
    const SolverSettings& st = r.path.solver;
    double worst = -1.0, worst_expected = nan, worst_got = nan;
    int count = 0;
    for (const Row& row : r.rows) {
      if (row.step == 0) continue;
      // The solver's own acceptance bound on a stress row (mixed_control.cpp).
      const double allowed =
          st.stress_tolerance + st.relative_stress_tolerance * max_abs(row.state.stress);
      for (int k = 0; k < 6; ++k) {
        const double target = c.target(row, k);
        if (std::isnan(target)) continue;
        const auto [i, j] = stress_index[static_cast<std::size_t>(k)];
        const double got = row.stress_path(i, j);
        const double e = std::abs(got - target) / allowed;
        if (e > worst) worst = e, worst_expected = target, worst_got = got;
        ++count;
      }
    }
    rec.add(c.label +
                ": stress-controlled components at every step (error in units of the solver "
                "tolerance 1e-3 Pa + 1e-10 max|sigma|) [worst of " +
                std::to_string(count) + "]",
            worst_expected, worst_got, count > 0 ? worst : nan, 1.0);
    rec.add(c.label + ": the path is plastic (got: final eps_p)", 0.0,
            r.rows.back().state.plastic_strain, 0.0, 0.0,
            r.rows.back().state.plastic_strain > 0.01);
  }
  return rec.take();
}

}  // namespace impact::pointdriver::verify
