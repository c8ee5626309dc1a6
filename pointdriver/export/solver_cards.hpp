// A Johnson-Cook material as the cards users paste into other codes (docs/fitting.md, "Cards for
// other codes"), in a consistent unit system:
//   LS-DYNA: *MAT_JOHNSON_COOK (MAT_015: elasticity, A, B, n, C, m, T_melt, T_room, the reference
//            rate, cp, D1..D5) with *EOS_LINEAR_POLYNOMIAL (C1 = K, the project's default_hypo
//            pressure) or *EOS_GRUNEISEN (C0, S, Gamma0: the Mie-Gruneisen EOS);
//   Abaqus:  *DENSITY, *ELASTIC, *PLASTIC, HARDENING=JOHNSON COOK (A, B, n, m, T_melt, T_room),
//            *RATE DEPENDENT, TYPE=JOHNSON COOK (C, reference rate), *SPECIFIC HEAT and
//            *INELASTIC HEAT FRACTION (Taylor-Quinney chi); the pressure is Abaqus's linear
//            elasticity's (an *EOS is left to the user).
// Values are converted from SI by the system's units of length, mass and time; temperatures stay
// in kelvin. Only Johnson-Cook has these cards (both codes' built-in Johnson-Cook hardening).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "models/material/material.hpp"

namespace impact::pointdriver {

/// A consistent unit system: the size of its units of length, mass and time in SI.
struct UnitSystem {
  std::string name;     ///< e.g. "mm-ms-kg"
  std::string stress;   ///< the stress unit it implies, e.g. "GPa"
  double length = 1.0;  ///< [m]
  double mass = 1.0;    ///< [kg]
  double time = 1.0;    ///< [s]
  double stress_scale() const { return mass / (length * time * time); }  ///< [Pa]
};

/// "SI" (m, kg, s: Pa), "mm-s-tonne" (mm, t, s: MPa), "mm-ms-kg" (mm, kg, ms: GPa), "mm-ms-g"
/// (mm, g, ms: MPa); std::invalid_argument naming the systems for another name.
const UnitSystem& unit_system(std::string_view name);
std::vector<std::string> unit_system_names();

/// The LS-DYNA keyword cards (*MAT_JOHNSON_COOK and its *EOS) of `material`, part of a .k file;
/// std::invalid_argument when its law is not Johnson-Cook.
std::string ls_dyna_cards(const Material& material, const UnitSystem& units, int id = 1);
/// The Abaqus *MATERIAL block of `material`; std::invalid_argument as above.
std::string abaqus_cards(const Material& material, const UnitSystem& units);

}  // namespace impact::pointdriver
