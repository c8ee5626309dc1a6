// Named paths: a leg entry with a "type" expands into explicit legs (JSON in, JSON out), so the
// expansion is visible in the resolved path written beside every run. Each type and its keys are
// listed in docs/pointdriver.md; strain means logarithmic strain, rate means its time derivative
// (the velocity-gradient component), both signed (negative = compression).
//
//   uniaxial_strain        L = diag(rate, 0, 0), all other components fixed
//   uniaxial_stress        L_xx = rate, sigma_yy = sigma_zz = 0
//   equibiaxial_stress     L_xx = L_yy = rate, sigma_zz = 0
//   pure_shear             L_xy = L_yx = gamma_rate / 2, all other components fixed
//   simple_shear           F_xy = gamma at the end, F otherwise the identity (constant L)
//   hydrostatic            L = rate I (all components fixed)
//   triaxial               confinement sigma_xx = sigma_yy = sigma_zz -> -pressure, then
//                          L_xx = rate with sigma_yy = sigma_zz = -pressure
//   load_unload_reverse    uniaxial stress: load to strain, unload to sigma_xx = 0, reverse
//   strain_rate_jump       uniaxial stress, one leg per (rate, strain increment)
//   temperature_jump       uniaxial stress, one leg per (temperature, strain increment)
//   constant_triaxiality   sigma = diag(s, k s, k s) with k from the triaxiality eta, L_xx = rate
//
// Every type accepts "steps" or "max_strain_increment", "first_step" (log-spaced steps),
// "thermal", "temperature" and "rotation" ({"axis": [x, y, z], "angle": rad}, spread over its
// legs in proportion to their duration).
#pragma once

#include "models/core/input.hpp"

namespace impact::pointdriver {

/// The names accepted as a leg's "type".
const std::vector<std::string>& named_path_types();

/// Expands one named leg into explicit legs. Problems (unknown type, missing or out-of-range
/// keys) are added to `reader`'s problem list with their key paths. `raw` is the leg's JSON.
Json expand_named_leg(JsonReader& reader, const Json& raw);

}  // namespace impact::pointdriver
