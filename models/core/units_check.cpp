#include "models/core/units_check.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace impact {

namespace {

// Plausible SI magnitudes, chosen wide enough that every material, scene and path of this
// project's scope (metals, polymers, ceramics, foams for densities; impact-scale scenes) reads
// without a warning, and narrow enough that the common slips land outside.
const QuantityUnits kDensity{"density", "kg/m^3", 100.0, 25000.0, 5000.0, {{"g/cm^3", 1e3}}, true};
const QuantityUnits kModulus{
    "elastic modulus", "Pa", 1e8, 1.5e12, 5e10, {{"GPa", 1e9}, {"MPa", 1e6}}, true};
const QuantityUnits kStress{"stress", "Pa", 1e5, 1e11, 3e8, {{"MPa", 1e6}, {"GPa", 1e9}}};
const QuantityUnits kTemperature{"temperature", "K", 50.0, 5000.0, 300.0, {{"degC", 1.0, 273.15}}};
const QuantityUnits kSpecificHeat{"specific heat", "J/(kg K)",         100.0, 2e4,
                                  900.0,           {{"J/(g K)", 1e3}}, true};
const QuantityUnits kSoundSpeed{"sound speed", "m/s", 500.0, 2e4, 5000.0, {{"km/s", 1e3}}, true};
const QuantityUnits kSpeed{"speed", "m/s", 0.0, 2e4, 1000.0, {{"mm/s", 1e-3}}};
const QuantityUnits kLength{"length", "m", 1e-6, 10.0, 0.05, {{"mm", 1e-3}}, true};

bool plausible(const QuantityUnits& u, double si) {
  const double a = std::abs(si);
  return a >= u.low && a <= u.high;
}

std::string format(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

const QuantityUnits& quantity_units(Quantity q) {
  switch (q) {
    case Quantity::density:
      return kDensity;
    case Quantity::elastic_modulus:
      return kModulus;
    case Quantity::stress:
      return kStress;
    case Quantity::temperature:
      return kTemperature;
    case Quantity::specific_heat:
      return kSpecificHeat;
    case Quantity::sound_speed:
      return kSoundSpeed;
    case Quantity::speed:
      return kSpeed;
    case Quantity::length:
      return kLength;
  }
  return kDensity;
}

std::optional<UnitGuess> likely_unit(Quantity q, double value) {
  const QuantityUnits& u = quantity_units(q);
  if (!std::isfinite(value) || value == 0.0 || plausible(u, value)) return std::nullopt;
  if (u.positive_only && value < 0.0) return std::nullopt;  // a sign error, not a unit slip
  std::optional<UnitGuess> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const UnitAlternative& alt : u.alternatives) {
    const double si = value * alt.factor + alt.offset;
    if (!plausible(u, si) || si == 0.0) continue;
    const double distance = std::abs(std::log(std::abs(si) / u.typical));
    if (distance < best_distance) {
      best_distance = distance;
      best = UnitGuess{alt.unit, si};
    }
  }
  return best;
}

std::optional<std::string> unit_hint(Quantity q, double value) {
  const auto guess = likely_unit(q, value);
  if (!guess) return std::nullopt;
  const QuantityUnits& u = quantity_units(q);
  return format(value) + " looks like " + guess->unit + " (" + format(value) + " " + guess->unit +
         " = " + format(guess->value_in_si) + " " + u.si_unit + "); SI expects " + u.si_unit;
}

}  // namespace impact
