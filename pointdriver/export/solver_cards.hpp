// A Johnson-Cook or a Swift x Cowper-Symonds material as the cards users paste into other codes
// (docs/fitting.md, "Cards for other codes"), in a consistent unit system:
//   Johnson-Cook:
//     LS-DYNA: *MAT_JOHNSON_COOK (MAT_015: elasticity, A, B, n, C, m, T_melt, T_room, the
//              reference rate, cp, D1..D5) with *EOS_LINEAR_POLYNOMIAL (C1 = K, the project's
//              default_hypo pressure) or *EOS_GRUNEISEN (C0, S, Gamma0: the Mie-Gruneisen EOS);
//     Abaqus:  *DENSITY, *ELASTIC, *PLASTIC, HARDENING=JOHNSON COOK (A, B, n, m, T_melt, T_room),
//              *RATE DEPENDENT, TYPE=JOHNSON COOK (C, reference rate), *SPECIFIC HEAT and
//              *INELASTIC HEAT FRACTION (Taylor-Quinney chi); the pressure is Abaqus's linear
//              elasticity's (an *EOS is left to the user).
//   Swift x Cowper-Symonds (cowper_symonds):
//     LS-DYNA: *MAT_POWER_LAW_PLASTICITY (MAT_018: k = K, N = n, SRC = D, SRP = q, SIGY giving the
//              strain to yield eps0 exactly, VP = 1: the plastic strain rate), no EOS card;
//     Abaqus:  *PLASTIC with Swift's curve tabulated (swift_table) and *RATE DEPENDENT,
//              TYPE=POWER LAW (D, q: Cowper-Symonds' form).
// Values are converted from SI by the system's units of length, mass and time; temperatures stay
// in kelvin. Other laws have no such cards: std::invalid_argument naming the law.
#pragma once

#include <array>
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

/// The LS-DYNA keyword cards of `material` (*MAT_JOHNSON_COOK and its *EOS, or
/// *MAT_POWER_LAW_PLASTICITY), part of a .k file; std::invalid_argument for another law, or for
/// a Swift eps0 the unit system cannot write exactly (SIGY below 0.02 read as a strain).
std::string ls_dyna_cards(const Material& material, const UnitSystem& units, int id = 1);
/// The Abaqus *MATERIAL block of `material`; std::invalid_argument for another law.
std::string abaqus_cards(const Material& material, const UnitSystem& units);

/// The largest ratio of eps0 + ep between neighbouring rows of the Abaqus Swift table: linear
/// interpolation of x^n over [x, 1.15 x] is within 6.1e-4 of it for every n in (0, 1).
inline constexpr double kSwiftTableRatio = 1.15;
/// The last plastic strain of the table (Abaqus holds the stress constant beyond it).
inline constexpr double kSwiftTableEnd = 5.0;
/// Swift's yield K (eps0 + ep)^n [Pa] against plastic strain ep: ep = 0, then eps0 + ep growing
/// by kSwiftTableRatio to kSwiftTableEnd; n = 0: one row (K, 0).
std::vector<std::array<double, 2>> swift_table(const CowperSymondsParams& law);

}  // namespace impact::pointdriver
