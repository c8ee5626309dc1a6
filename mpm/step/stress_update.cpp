// Constitutive update of every particle by the library (models/material/elastic_plastic.hpp):
// F_{n+1} = (I + L dt) F_n (or exp(L dt) F_n), sigma_{n+1} from ElasticPlastic::update (objective,
// Green-Naghdi or Jaumann as the material says), V_{n+1} = V_0 det F_{n+1}. The strain-energy
// increment is report eq. 14 with the mid-step stress: 1/2 (sigma_n + sigma_{n+1}) : D V_{n+1} dt.
// Artificial bulk viscosity (report eq. 12) is computed here from the same D, stored per particle
// and added to the next step's internal force as -q I (reference_code_notes.md sec. 13: the 2004
// code neither booked its work nor let it shorten the time step).
#include <cmath>
#include <string>

#include "models/kinematics/deformation_gradient.hpp"
#include "mpm/step/parallel.hpp"

namespace impact::mpm {

namespace {

// Report eq. 12: q = rho (C_L a |tr D| l + C_0 (tr D l)^2) in compression (tr D < 0), else 0;
// a = sqrt(K / rho) the bulk sound speed from the input bulk modulus.
double bulk_viscosity(const ArtificialViscositySpec& av, double rho, double bulk_modulus,
                      double trD, double l) {
  if (!(trD < 0.0)) return 0.0;
  const double a = std::sqrt(bulk_modulus / rho);
  return rho * (av.linear * a * std::abs(trD) * l + av.quadratic * trD * trD * l * l);
}

}  // namespace

StressTotals update_stress(Particles& P, const StressUpdateSettings& settings, double dt,
                           std::optional<Failure>& failure) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  const int nt = std::min(omp_get_max_threads(), kMaxThreads);
  const ArtificialViscositySpec* av = settings.viscosity;
  const double l = settings.mean_spacing;
  const bool convert = !settings.companion_field.empty();
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
      const Mat3 F1 = advance_deformation_gradient(s0.F, L, dt, settings.f_integration);
      const ElasticPlastic& model = *settings.models[P.material[p]];
      PointState s1;
      const StepReport r = model.update(s0, L, F1, dt, s1);
      if (r.status != UpdateStatus::ok) {
        // Keep the old state so the final snapshot shows the last good values.
        if (!fail) fail = Failure{std::size_t(p), "stress", std::string(to_string(r.status))};
        continue;
      }
      const double V1 = P.volume0[p] * F1.determinant();
      sum.strain_energy_increment += 0.5 * ddot(s0.stress + s1.stress, sym(L)) * V1 * dt;
      sum.eroded_energy += r.eroded_energy * V1;
      double signal = r.wave_speed;
      if (av != nullptr) {
        const double trD = L.trace();
        const double rho = P.mass[p] / V1;
        const double K = model.params().bulk_modulus;
        const double q1 = bulk_viscosity(*av, rho, K, trD, l);
        const double work = 0.5 * (P.q[p] + q1) * (-trD) * V1 * dt;
        sum.viscous_work += work;
        P.q[p] = q1;
        // The viscous work is the shock's entropy: it becomes internal energy (which the
        // Mie-Gruneisen pressure reads) and, with adiabatic heating on, temperature. The 2004
        // code dropped it (reference_code_notes.md sec. 13).
        s1.internal_energy += work / P.mass[p];
        if (model.params().heating.enabled)
          s1.temperature += work / (P.mass[p] * model.params().specific_heat);
        if (trD < 0.0) {
          const double Q = av->linear * std::sqrt(K / rho) + av->quadratic * l * std::abs(trD);
          signal = Q + std::sqrt(Q * Q + r.wave_speed * r.wave_speed);
        }
      }
      if (r.failure != FailureCause::none) {
        ++sum.failed;
        if (convert && P.field[p] != settings.companion_field[P.material[p]]) {
          // Same mass, velocity, stress and history: only the velocity field changes, at the
          // time level the failure happened (the 2004 code re-inserted the particle with its
          // time-n position and velocity, a one-step lag: reference_code_notes.md sec. 12).
          P.field[p] = settings.companion_field[P.material[p]];
          ++sum.converted;
        }
      }
      P.state[p] = s1;
      P.volume[p] = V1;
      P.wave_speed[p] = signal;
      sum.max_signal_speed = std::max(sum.max_signal_speed, signal + P.v[p].norm());
    }
    partial[omp_get_thread_num()] = sum;
    failures[omp_get_thread_num()] = fail;
  }
  StressTotals total;
  for (int t = 0; t < nt; ++t) {  // thread order: deterministic
    total.strain_energy_increment += partial[t].strain_energy_increment;
    total.viscous_work += partial[t].viscous_work;
    total.eroded_energy += partial[t].eroded_energy;
    total.max_signal_speed = std::max(total.max_signal_speed, partial[t].max_signal_speed);
    total.failed += partial[t].failed;
    total.converted += partial[t].converted;
    merge_failure(failure, failures[t]);
  }
  return total;
}

}  // namespace impact::mpm
