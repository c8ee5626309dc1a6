// The material format's keys as the material reader asks for them (models/core/input_keys.hpp):
// read_material reads sample materials that switch on every optional block and put every
// catalogued model (flow stress, shear modulus, damage) in its slot, and records each key's
// type, range, default and meaning. `material_check --keys` prints them;
// tests/models/material/material_keys_test.cpp checks docs/models.md's tables against them.
#pragma once

#include <string_view>

#include "models/core/input_keys.hpp"

namespace impact {

/// The slots whose models share key names with different meanings and ranges (`n` of
/// Johnson-Cook and of Steinberg-Cochran-Guinan): a key of the model `type` in slot
/// /constitutive_model/SLOT is recorded as /constitutive_model/SLOT[type]/KEY, written
/// constitutive_model.SLOT[type].KEY. The slot's own `type` key is recorded as read.
inline constexpr std::string_view kMaterialSlots[] = {"flow_stress", "shear_modulus", "damage"};

/// Every key of the material format, in the order the reader reads them. Throws InputError if a
/// sample material is refused (the samples are then out of date with the reader), and
/// std::logic_error if a model of a catalogue has no sample (one added without one).
InputKeyRecorder material_keys();

}  // namespace impact
