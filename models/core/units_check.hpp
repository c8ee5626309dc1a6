// Units plausibility: every input is SI, and a value far outside the usual SI range of its
// quantity that lands inside it after a common unit factor (g/cm^3 -> x1000, GPa -> x1e9,
// MPa -> x1e6, degC -> +273.15, mm -> x1e-3, ...) was probably typed in that unit. The loaders
// turn such a finding into a warning (the run proceeds: a foam's density of 2.7 kg/m^3 is real)
// or, when the value is also outside the physically possible range, append it to the error.
// docs/reliability.md lists the quantities, their ranges and the warn-or-refuse decisions.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impact {

/// The physical quantities whose units are checked.
enum class Quantity {
  density,          ///< kg/m^3
  elastic_modulus,  ///< Pa (shear, bulk, Young's)
  stress,           ///< Pa (yield and hardening stresses, stress targets, stress tolerances)
  temperature,      ///< K
  specific_heat,    ///< J/(kg K)
  sound_speed,      ///< m/s (bulk sound speed of an EOS)
  speed,            ///< m/s (an initial velocity component)
  length,           ///< m (the extent of a scene's grid)
};

/// A unit the value may have been typed in: si = value * factor + offset.
struct UnitAlternative {
  const char* unit;
  double factor = 1.0;
  double offset = 0.0;
};

/// The plausible SI magnitude of a quantity (compared with |value|) and the slips looked for.
struct QuantityUnits {
  const char* name;     ///< e.g. "density"
  const char* si_unit;  ///< e.g. "kg/m^3"
  double low;           ///< plausible |value| in SI: [low, high]; 0 = no lower limit
  double high;          ///< plausible |value| in SI
  double typical;       ///< chooses between alternatives that both fit (closest in log)
  std::vector<UnitAlternative> alternatives;
  /// A negative value is no unit slip but a wrong sign (a density of -2.7 is not in g/cm^3):
  /// density, moduli, specific heat, sound speed, length. Stress and speed have a sign, and a
  /// negative temperature may be in degC.
  bool positive_only = false;
};

/// The table of quantities (docs/reliability.md reproduces it).
const QuantityUnits& quantity_units(Quantity q);

/// The likely unit of an implausible value.
struct UnitGuess {
  std::string unit;    ///< e.g. "GPa"
  double value_in_si;  ///< the value converted from that unit to SI
};

/// nullopt when |value| is plausible, zero or not finite, negative for a positive-only quantity,
/// or when no alternative explains it.
std::optional<UnitGuess> likely_unit(Quantity q, double value);

/// "26 looks like GPa (26 GPa = 2.6e+10 Pa); SI expects Pa", or nullopt (see likely_unit).
std::optional<std::string> unit_hint(Quantity q, double value);

}  // namespace impact
