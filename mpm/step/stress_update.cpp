// Constitutive update of every particle by the library (models/material/elastic_plastic.hpp):
// F_{n+1} = (I + L dt) F_n (or exp(L dt) F_n), sigma_{n+1} from ElasticPlastic::update (objective,
// Green-Naghdi or Jaumann as the material says), V_{n+1} = V_0 det F_{n+1}. The strain-energy
// increment is report eq. 14 with the mid-step stress: 1/2 (sigma_n + sigma_{n+1}) : D V_{n+1} dt.
#include <string>

#include "models/kinematics/deformation_gradient.hpp"
#include "mpm/step/parallel.hpp"

namespace impact::mpm {

StressTotals update_stress(Particles& P, const std::vector<const ElasticPlastic*>& models,
                           double dt, FIntegration f_integration, std::optional<Failure>& failure) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  const int nt = std::min(omp_get_max_threads(), kMaxThreads);
  StressTotals partial[kMaxThreads];
  std::optional<Failure> failures[kMaxThreads];
#pragma omp parallel num_threads(nt)
  {
    StressTotals sum;
    std::optional<Failure> fail;
#pragma omp for schedule(static)
    for (std::ptrdiff_t p = 0; p < n; ++p) {
      const PointState& s0 = P.state[p];
      const Mat3& L = P.L[p];
      const Mat3 F1 = advance_deformation_gradient(s0.F, L, dt, f_integration);
      PointState s1;
      const StepReport r = models[P.material[p]]->update(s0, L, F1, dt, s1);
      if (r.status != UpdateStatus::ok) {
        // Keep the old state so the final snapshot shows the last good values.
        if (!fail) fail = Failure{std::size_t(p), "stress", std::string(to_string(r.status))};
        continue;
      }
      const double V1 = P.volume0[p] * F1.determinant();
      sum.strain_energy_increment += 0.5 * ddot(s0.stress + s1.stress, sym(L)) * V1 * dt;
      P.state[p] = s1;
      P.volume[p] = V1;
      P.wave_speed[p] = r.wave_speed;
      sum.max_signal_speed = std::max(sum.max_signal_speed, r.wave_speed + P.v[p].norm());
    }
    partial[omp_get_thread_num()] = sum;
    failures[omp_get_thread_num()] = fail;
  }
  StressTotals total;
  for (int t = 0; t < nt; ++t) {  // thread order: deterministic
    total.strain_energy_increment += partial[t].strain_energy_increment;
    total.max_signal_speed = std::max(total.max_signal_speed, partial[t].max_signal_speed);
    merge_failure(failure, failures[t]);
  }
  return total;
}

}  // namespace impact::mpm
