// The units of the extensive totals a run books (energies, masses, momenta, impulses, volumes):
// a 3D or an axisymmetric run books whole bodies (an axisymmetric ring is the revolved body,
// scene/grid_geometry.hpp); a plane-strain run books a slice of unit thickness along z, so its
// totals are per metre of thickness and say so in every label (history.csv, summary.json,
// `mpm check`; docs/mpm.md#ledger). Intensive quantities (velocity, stress, strain, temperature,
// energy_error) keep their units.
#pragma once

#include <string>

namespace impact::mpm {

struct ExtensiveUnits {
  std::string energy = "J";
  std::string mass = "kg";
  std::string momentum = "kg m/s";
  std::string impulse = "N s";
  std::string volume = "m^3";

  /// Per metre of thickness (plane strain) or of the whole body.
  static ExtensiveUnits of(bool per_metre_of_thickness) {
    if (!per_metre_of_thickness) return {};
    return {"J/m", "kg/m", "(kg m/s)/m", "(N s)/m", "m^3/m"};
  }
};

}  // namespace impact::mpm
