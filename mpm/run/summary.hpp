// summary.json of a run and the report of `mpm check`: per-object counts, mass and volumes, the
// memory estimate, the ledger's last row, failures by cause, the observables and the run's speed.
#pragma once

#include <string>

#include "mpm/output/gauge_extrema.hpp"
#include "mpm/output/observables.hpp"
#include "mpm/output/particle_paths.hpp"
#include "mpm/simulation/simulation.hpp"

namespace impact::mpm {

/// What `mpm check` prints after the resolved scene: per-object counts, mass, particle volume
/// against the exact geometric volume, estimated steps and memory, the scene fingerprint
/// (mpm/run/scene_fingerprint.hpp); with `ranks` > 1 also the split over that many MPI ranks
/// ("decomposition": plan_decomposition). `seeding`: where the seeded bodies' warnings go
/// (run/seeding_check.hpp), if given.
Json check_report(const Scene& scene, int threads, int ranks = 0,
                  std::vector<std::string>* seeding = nullptr);

/// summary.json at the end of a run of sim, whose particles are P (on several ranks, those this
/// rank holds: a collective call, every rank gets the whole summary): `status` (completed, failed,
/// interrupted) with its message, `wall` the step loop's wall time [s] over every run of a
/// restarted one; `paths`: null when the run has none; `gauges`: the gauges' extrema over the
/// history rows, added to "gauges" beside their particle counts.
Json run_summary(const Simulation& sim, const Particles& P, const std::string& status,
                 const std::string& message, double wall, const Observables& observables,
                 const GaugeExtrema& gauges, const ParticlePaths* paths);

}  // namespace impact::mpm
