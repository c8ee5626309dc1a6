// The verification cases, one file each (pointdriver/verify/cases/<name>.cpp); the catalogue in
// verification_suite.cpp names them.
#pragma once

#include <vector>

#include "pointdriver/verify/verification_suite.hpp"

namespace impact::pointdriver::verify {

/// Elastic uniaxial strain and uniaxial stress.
std::vector<Check> elastic_uniaxial(const SuiteContext& ctx);
/// Elastic-perfectly-plastic uniaxial strain: yield point and plateau.
std::vector<Check> perfectly_plastic_uniaxial_strain(const SuiteContext& ctx);
/// Johnson-Cook uniaxial stress at four rates and three temperatures.
std::vector<Check> johnson_cook_uniaxial_stress(const SuiteContext& ctx);
/// Adiabatic uniaxial compression at 4000 /s: heating and the Drucker check.
std::vector<Check> adiabatic_compression(const SuiteContext& ctx);
/// Simple shear to gamma = 5: Green-Naghdi against Dienes (1979); Jaumann oscillates.
std::vector<Check> simple_shear(const SuiteContext& ctx);
/// Rigid rotation superposed on uniaxial strain.
std::vector<Check> rotation_on_uniaxial_strain(const SuiteContext& ctx);
/// Mie-Gruneisen uniaxial-strain compression against the Hugoniot.
std::vector<Check> mie_gruneisen_uniaxial_strain(const SuiteContext& ctx);
/// Johnson-Cook damage at constant triaxiality.
std::vector<Check> johnson_cook_damage(const SuiteContext& ctx);
/// Becker and Drucker indicators against an independent evaluation.
std::vector<Check> stability_indicators(const SuiteContext& ctx);
/// The compressible neo-Hookean solid in uniaxial stress and simple shear at large strain.
std::vector<Check> neo_hookean(const SuiteContext& ctx);
/// Mixed control: stress-controlled components within the solver tolerance at every step.
std::vector<Check> mixed_control(const SuiteContext& ctx);

}  // namespace impact::pointdriver::verify
