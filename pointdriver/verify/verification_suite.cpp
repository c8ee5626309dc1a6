#include "pointdriver/verify/verification_suite.hpp"

#include <filesystem>
#include <limits>

#include "pointdriver/verify/cases/cases.hpp"
#include "support/shipped_file.hpp"

namespace impact::pointdriver {

namespace fs = std::filesystem;

const std::vector<VerificationCase>& verification_cases() {
  using namespace verify;
  static const std::vector<VerificationCase> cases = {
      {"elastic_uniaxial", "elastic uniaxial strain and stress: moduli and Poisson contraction",
       elastic_uniaxial},
      {"perfectly_plastic_uniaxial_strain",
       "elastic-perfectly-plastic uniaxial strain: yield point and plateau",
       perfectly_plastic_uniaxial_strain},
      {"johnson_cook_uniaxial_stress", "JC flow curves at 4 rates x 3 temperatures (isothermal)",
       johnson_cook_uniaxial_stress},
      {"adiabatic_compression_4000",
       "adiabatic compression at 4000 /s: heating (eq. 8) and the Drucker check",
       adiabatic_compression},
      {"simple_shear_gamma5", "simple shear to gamma = 5: Green-Naghdi vs Dienes, Jaumann",
       simple_shear},
      {"rotation_on_uniaxial_strain", "rigid rotation superposed on uniaxial strain (objectivity)",
       rotation_on_uniaxial_strain},
      {"mie_gruneisen_uniaxial_strain", "Mie-Gruneisen uniaxial strain vs the Hugoniot",
       mie_gruneisen_uniaxial_strain},
      {"johnson_cook_damage_triaxiality", "JC damage: failure at eps_f (eq. 7) at 4 triaxialities",
       johnson_cook_damage},
      {"becker_drucker_indicators", "Becker and Drucker indicators vs an independent evaluation",
       stability_indicators},
      {"neo_hookean_large_strain",
       "neo-Hookean uniaxial stress (stretch 2, 1/2) and simple shear (gamma 2) vs closed forms",
       neo_hookean},
      {"mixed_control", "mixed control: stress-controlled components within tolerance",
       mixed_control},
  };
  return cases;
}

SuiteContext default_suite_context(const std::string& out_dir) {
  SuiteContext c;
  c.out_dir = out_dir;
  const fs::path material = shipped_file("data/materials/al6061_t6.json");
  c.material_file = fs::absolute(material).string();
  const fs::path hugoniot = shipped_file("data/experiments/al6061_t6_hugoniot/hugoniot.csv");
  c.hugoniot_file = fs::exists(hugoniot) ? fs::absolute(hugoniot).string() : "";
  return c;
}

std::vector<Check> run_case(const VerificationCase& c, const SuiteContext& context) {
  try {
    return c.run(context);
  } catch (const std::exception& e) {
    return {{c.name, std::string("case ran to the end (error: ") + e.what() + ")", 1.0, 0.0,
             std::numeric_limits<double>::quiet_NaN(), 0.0, false}};
  }
}

}  // namespace impact::pointdriver
