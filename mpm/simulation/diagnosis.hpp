// How the Simulation names what went wrong (docs/mpm.md#failure-handling): the particle, its
// state and the field, for a failed update, a particle outside the grid, a collapsed time step or
// energy that grows.
#pragma once

#include <optional>
#include <string>

#include "mpm/ledger/ledger.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/step/step.hpp"

namespace impact::mpm {

/// The energy-growth check: the fastest particle with the ledger's figures when kinetic + strain
/// energy grew beyond time.max_energy_growth times the energy that entered; else nullopt.
/// `energy_unit`: the ledger's energy unit (J, or J/m on a plane-strain grid).
std::optional<Failure> energy_growth(const Ledger& ledger, const Particles& P, const TimeSpec& t,
                                     const std::string& energy_unit);

}  // namespace impact::mpm
