// Constitutive update of every particle by the library (models/material/elastic_plastic.hpp):
// F_{n+1} = (I + L dt) F_n (or exp(L dt) F_n), sigma_{n+1} as ElasticPlastic::update gives it,
// in blocks whose radial returns share the vector lanes (UpdateBatch) (objective,
// Green-Naghdi or Jaumann as the material says), V_{n+1} = V_0 det F_{n+1}. The strain-energy
// increment is report eq. 14 with the mid-step stress: 1/2 (sigma_n + sigma_{n+1}) : D V_{n+1} dt.
// Artificial bulk viscosity (report eq. 12) is computed here from the same D, stored per particle
// and added to the next step's internal force as -q I; its dissipation q (-tr D) V dt is booked
// and retained as heat (docs/report_code.md sec. 13: the 2004 code neither booked its work
// nor let it shorten the time step).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "models/kinematics/deformation_gradient.hpp"
#include "models/material/update_batch.hpp"
#include "models/thermal/adiabatic_heating.hpp"
#include "mpm/step/step.hpp"
#include "mpm/threads/chunk_shares.hpp"
#include "mpm/threads/chunk_sums.hpp"
#include "mpm/threads/threads.hpp"

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

// Why an update cannot be used (the cold path: only on a fault); `molten`: the point is melted (at
// the start or the end of the step: its remedy differs).
std::string describe_fault(const Mat3& L, const Mat3& F1, const StepReport& r, bool injected,
                           bool molten = false) {
  std::ostringstream m;
  m.precision(9);
  if (!F1.allFinite()) {
    m << "deformation gradient F_{n+1} not finite (L = [" << L.row(0) << "; " << L.row(1) << "; "
      << L.row(2) << "] 1/s)";
    return m.str();
  }
  m << to_string(r.status);
  if (r.status == UpdateStatus::negative_jacobian || r.status == UpdateStatus::eos_out_of_range ||
      r.status == UpdateStatus::non_finite_wave_speed)
    m << " (det F_{n+1} = " << F1.determinant() << ")";
  if (r.status == UpdateStatus::return_mapping_not_converged)
    m << " (" << r.return_iterations << " iterations)";
  // A molten point has no shear strength; stretched beyond its equation of state's range it has
  // no sound speed either. The documented remedy lets it fail in tension instead (docs/models.md,
  // 4340 MTS at 1100 m/s).
  if (molten && (r.status == UpdateStatus::non_finite_wave_speed ||
                 r.status == UpdateStatus::eos_out_of_range))
    m << "; the point is molten and stretched beyond its equation of state: an erosion that drops "
         "tension (\"physics\": {\"erosion\": \"AllowNoTension\"}) lets it fail instead "
         "(docs/models.md)";
  if (injected) m << " (injected: --inject-fault nan)";
  return m.str();
}

// Completes a batched update's checks; false when it cannot be used: the model's own status
// (negative Jacobian, radial return not converged, non-finite stress, EOS out of range), or a
// non-finite stress or wave speed it did not flag. `inject_nan`: the stress it returned is
// replaced by NaN first (mpm run --inject-fault nan).
bool checked(PointState& s1, StepReport& r, bool inject_nan) {
  if (inject_nan) s1.stress.setConstant(std::numeric_limits<double>::quiet_NaN());
  if (r.status == UpdateStatus::ok && !s1.stress.allFinite())
    r.status = UpdateStatus::non_finite_stress;
  if (r.status == UpdateStatus::ok && !std::isfinite(r.wave_speed))
    r.status = UpdateStatus::non_finite_wave_speed;
  return r.status == UpdateStatus::ok;
}

// The mean edge of the cell holding x on a graded grid, over the mesh's axes (eq. 12's l where the
// cells differ: the resolution the shock is spread over there).
double local_mean_spacing(const GridSpec& g, const Vec3& x) {
  const std::array<int, 3> c = g.cell_of(x);
  return g.planar() ? 0.5 * (g.cell_size(0, c[0]) + g.cell_size(1, c[1]))
                    : (g.cell_size(0, c[0]) + g.cell_size(1, c[1]) + g.cell_size(2, c[2])) / 3.0;
}

}  // namespace

// Long on purpose (about 140 lines): one parallel region whose threads share the chunk counter,
// the batch per thread and the per-thread totals; split, those would cross function boundaries.
StressTotals update_stress(Particles& P, const StressUpdateSettings& settings, double dt,
                           std::optional<Failure>& failure) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  const int nt = std::min(omp_get_max_threads(), kMaxThreads);
  const ArtificialViscositySpec* av = settings.viscosity;
  const double l = settings.mean_spacing;
  const GridSpec* const graded = settings.graded_grid;
  const bool convert = !settings.companion_field.empty();
  const bool fail_particle = settings.fail_particle && P.fault.size() == P.size();
  const bool outflow = P.removed.size() == P.size() && !P.removed.empty();
  const std::uint8_t* const rigid =
      settings.rigid_field.empty() ? nullptr : settings.rigid_field.data();
  // Particles go through the model in blocks of one batch: their radial returns run together on
  // the vector lanes (models/material/update_batch.hpp), with the same bits as one at a time.
  constexpr std::ptrdiff_t kBlock = UpdateBatch::capacity;
  const std::ptrdiff_t blocks = (n + kBlock - 1) / kBlock;
  // The threads balance chunks of kChunkBlocks blocks (mpm/threads/chunk_shares.hpp); the energy
  // sums are taken per chunk and then in chunk order, the same bits on any thread count.
  constexpr std::ptrdiff_t kChunkBlocks = 64;
  struct EnergySums {
    double strain = 0.0, viscous = 0.0, eroded = 0.0, plastic = 0.0;  // [J]
  };
  ChunkSums<EnergySums> chunk_sums(blocks, kChunkBlocks);
  ChunkShares shares(chunk_sums.chunks(), nt);
  StressTotals partial[kMaxThreads];
  std::optional<Failure> failures[kMaxThreads];
#pragma omp parallel num_threads(nt)
  {
    StressTotals sum;
    std::optional<Failure> fail;
    UpdateBatch batch;
    PointState next[kBlock];
    Mat3 F1s[kBlock];
    int lane_of[kBlock];
    // A particle whose update cannot be used keeps its start-of-step state (the last good values).
    const auto fault = [&](std::ptrdiff_t p, std::string why) {
      Failure f{std::size_t(p), "stress", std::move(why), std::nullopt};
      if (!fail_particle) {
        if (fails_first(P, f.particle, fail)) fail = std::move(f);
        return;
      }
      f.state = P.state[p];
      P.fault[p] = 1;
      P.state[p].stress.setZero();
      P.state[p].failed = true;
      if (av != nullptr) P.q[p] = 0.0;
      sum.faulted.push_back(std::move(f));
      sum.max_signal_speed = std::max(sum.max_signal_speed, P.wave_speed[p] + P.v[p].norm());
    };
    // A contiguous share per thread, the tail balanced by stealing chunks. Chunks of 4 blocks
    // dealt round the threads (42f7956, for the plastic points of an impact, which are neighbours
    // in the arrays) cost 10-15 % of the whole step on 2 threads on the 2-core VM of issue 57: the
    // transfers after the stress update read the particles the other thread had just written.
    // One thread runs the same order either way.
    for (std::ptrdiff_t chunk; (chunk = shares.next(omp_get_thread_num())) >= 0;) {
      EnergySums& energy = chunk_sums[chunk];
      const std::ptrdiff_t chunk_end = chunk_sums.end(chunk);
      for (std::ptrdiff_t block = chunk_sums.begin(chunk); block < chunk_end; ++block) {
        const std::ptrdiff_t p0 = block * kBlock, p1 = std::min(n, p0 + kBlock);
        batch.clear();
        for (std::ptrdiff_t p = p0; p < p1; ++p) {
          const std::ptrdiff_t i = p - p0;
          lane_of[i] = -1;
          if (outflow && P.removed[p]) {  // left the grid: out of the simulation, nothing to carry
            P.v[p].setZero();
            P.mass[p] = 0.0;
            P.volume[p] = 0.0;
            P.state[p].stress.setZero();
            P.wave_speed[p] = 0.0;
            if (!P.q.empty()) P.q[p] = 0.0;
            continue;
          }
          if (in_rigid_field(rigid, P, std::size_t(p))) {  // a rigid object: moves, never strains
            sum.max_signal_speed = std::max(sum.max_signal_speed, P.v[p].norm());
            continue;
          }
          if (fail_particle && P.fault[p] != 0) {  // flagged earlier: zero stress, no update
            sum.max_signal_speed = std::max(sum.max_signal_speed, P.wave_speed[p] + P.v[p].norm());
            continue;
          }
          F1s[i] = advance_deformation_gradient(P.state[p].F, P.L[p], dt, settings.f_integration);
          if (!F1s[i].allFinite()) {  // not passed to the model
            fault(p, describe_fault(P.L[p], F1s[i], StepReport{}, false));
            continue;
          }
          lane_of[i] =
              batch.add(*settings.models[P.material[p]], P.state[p], P.L[p], F1s[i], next[i]);
        }
        batch.run(dt);
        for (std::ptrdiff_t p = p0; p < p1; ++p) {
          const std::ptrdiff_t i = p - p0;
          if (lane_of[i] < 0) continue;
          const PointState& s0 = P.state[p];
          const Mat3& L = P.L[p];
          const Mat3& F1 = F1s[i];
          PointState& s1 = next[i];
          StepReport r = batch.finish(lane_of[i], dt, s1);
          const bool inject = p == settings.inject_nan_stress;
          if (!checked(s1, r, inject)) {
            fault(p, describe_fault(L, F1, r, inject, s0.melted || s1.melted));
            continue;
          }
          const ElasticPlastic& model = *settings.models[P.material[p]];
          const double V1 = P.volume0[p] * F1.determinant();
          // Report eq. 14, the stress power at mid-step; a hyperelastic point's stored energy is
          // W(F), and its change is booked exactly: the quadrature drifts from it at first order in
          // dt (a soft block ringing on a wall for 1 s booked 0.8 J/m less than sum V0 W(F),
          // going negative while compressed; docs/mpm.md#ledger).
          energy.strain +=
              model.hyperelastic()
                  ? P.volume0[p] * (model.stored_energy(F1) - model.stored_energy(s0.F))
                  : 0.5 * ddot(s0.stress + s1.stress, sym(L)) * V1 * dt;
          energy.eroded += r.eroded_energy * V1;
          if (settings.plastic_work)  // with the stress the point carries: none once eroded to zero
            energy.plastic += von_mises(s1.stress) * (s1.plastic_strain - s0.plastic_strain) * V1;
          double signal = r.wave_speed;
          if (av != nullptr) {
            const double trD = L.trace();
            const double rho = P.mass[p] / V1;
            const double K = model.params().bulk_modulus;
            const double lp = graded ? local_mean_spacing(*graded, P.x[p]) : l;
            const double q1 = bulk_viscosity(*av, rho, K, trD, lp);
            // The viscous dissipation of this step's compression: q(D) (-tr D) V dt >= 0, q > 0
            // only where tr D < 0 (the force applies q one step later; the lag is part of the
            // residual).
            const double work = q1 * (-trD) * V1 * dt;
            energy.viscous += work;
            P.q[p] = q1;
            // The shock's entropy: heat retained by the point when heating is on (e and T, which
            // the Mie-Gruneisen pressure and the flow stress read; models/thermal/
            // adiabatic_heating.hpp). The 2004 code dropped it (docs/report_code.md sec. 13).
            retain_heat(s1, work / P.mass[p], model.params().heating.enabled,
                        model.params().specific_heat);
            if (trD < 0.0) {
              const double Q = av->linear * std::sqrt(K / rho) + av->quadratic * lp * std::abs(trD);
              signal = Q + std::sqrt(Q * Q + r.wave_speed * r.wave_speed);
            }
          }
          if (r.failure != FailureCause::none) {
            ++sum.failed;
            if (convert && P.field[p] != settings.companion_field[P.material[p]]) {
              // Same mass, velocity, stress and history: only the velocity field changes, at the
              // time level the failure happened (the 2004 code re-inserted the particle with its
              // time-n position and velocity, a one-step lag: docs/report_code.md sec. 12).
              P.field[p] = settings.companion_field[P.material[p]];
              ++sum.converted;
            }
          }
          P.state[p] = s1;
          P.volume[p] = V1;
          P.wave_speed[p] = signal;
          sum.max_signal_speed = std::max(sum.max_signal_speed, signal + P.v[p].norm());
        }
      }
    }
    partial[omp_get_thread_num()] = sum;
    failures[omp_get_thread_num()] = fail;
  }
  StressTotals total;
  chunk_sums.add_in_order([&](const EnergySums& e) {
    total.strain_energy_increment += e.strain;
    total.viscous_work += e.viscous;
    total.eroded_energy += e.eroded;
    total.plastic_work += e.plastic;
  });
  for (int t = 0; t < nt; ++t) {  // the counts, the largest speed and the faults
    merge_into(total, partial[t]);
    for (Failure& f : partial[t].faulted) total.faulted.push_back(std::move(f));
    merge_failure(failure, failures[t],
                  [&](const Failure& a, const Failure& b) { return fails_first(P, a, b); });
  }
  // Ascending seed indices, whichever thread updated which chunk and whatever the storage order.
  std::stable_sort(total.faulted.begin(), total.faulted.end(),
                   [&](const Failure& a, const Failure& b) { return fails_first(P, a, b); });
  return total;
}

}  // namespace impact::mpm
