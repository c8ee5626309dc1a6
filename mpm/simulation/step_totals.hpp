// What one step reports: its totals (for the ledger and for tests) and where its wall time went.
#pragma once

#include <utility>

#include "mpm/step/step.hpp"

namespace impact::mpm {

/// Wall time of each phase of the last step [s] (omp_get_wtime; for the benchmark's profile).
struct PhaseTimes {
  double particles_to_grid = 0, grid_update = 0, grid_to_particles = 0, remap = 0, stress = 0;

  /// Each phase with its name, in step order (for summaries).
  static constexpr std::pair<const char*, double PhaseTimes::*> kPhases[] = {
      {"particles_to_grid", &PhaseTimes::particles_to_grid},
      {"grid_update", &PhaseTimes::grid_update},
      {"grid_to_particles", &PhaseTimes::grid_to_particles},
      {"remap", &PhaseTimes::remap},
      {"stress", &PhaseTimes::stress}};
  PhaseTimes& operator+=(const PhaseTimes& o) {
    for (const auto& [name, phase] : kPhases) this->*phase += o.*phase;
    return *this;
  }
};

/// One step's totals, for the ledger and for tests.
struct StepTotals {
  GridUpdate grid;
  ParticleTotals particles;
  StressTotals stress;
  PhaseTimes seconds;
  /// Particles whose uGIMP box was narrowed to the cells about them this step (a graded grid's
  /// particle seeded in a coarse cell, among finer ones: shape/tartan.hpp); this rank's.
  long narrowed = 0;
};

}  // namespace impact::mpm
