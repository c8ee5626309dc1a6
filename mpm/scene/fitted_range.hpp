// A material used outside the strain rates and temperatures its parameters were fitted on (the
// material file's `fitted_range`, docs/models.md): one warning per material when a scene starts,
// so that a user who runs a quasi-statically fitted law at 1000 m/s is told before trusting the
// answer. The strain rate of an impact is not known before it is run: the check uses the nominal
// rate of each object, its largest speed relative to another object it approaches over its
// extent along that relative velocity, or its speed toward a face that holds it (a wall, a mirror,
// a fixed face) over its extent along the face's normal: v / L (a Taylor rod at 1100 m/s, 25 mm
// long: 4.4e4 /s). The temperatures are the objects' initial ones. Costs nothing per step.
#pragma once

#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// The nominal strain rate of object `o` [1/s] (above): 0 for a body at rest with nothing moving
/// relative to it.
double nominal_strain_rate(const Scene& scene, std::size_t o);

/// One warning per material that states a fitted_range and is used outside it, naming the file,
/// the range and the object's nominal rate or temperature ("FILE: /materials/NAME/file: ...").
std::vector<std::string> fitted_range_warnings(const Scene& scene);

}  // namespace impact::mpm
