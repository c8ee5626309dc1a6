// What every equation of state shares: the material constants and the one-step inputs it reads,
// and the step it returns. Each EOS of the catalogue (models/eos/equation_of_state.hpp) defines
//   eos_step(params, EosMaterial, EosStepInput) -> EosStep          (step 4 of elastic_plastic.hpp)
//   eos_bulk_modulus(params, EosMaterial, density, internal_energy)  (the wave speed, time step)
// beside its pressure law; the elastic-plastic step reaches them by visiting the variant.
#pragma once

namespace impact {

/// The material's constants an EOS may read.
struct EosMaterial {
  double density = 0.0;        ///< reference density rho0 [kg/m^3]
  double bulk_modulus = 0.0;   ///< K [Pa]
  double shear_modulus = 0.0;  ///< mu0 [Pa]
  double specific_heat = 0.0;  ///< cp [J/(kg K)]
};

/// One step from the start-of-step state to the new density (and the temperature after heating).
struct EosStepInput {
  double pressure = 0.0;         ///< p_n [Pa], compression positive
  double density = 0.0;          ///< rho_n [kg/m^3]
  double internal_energy = 0.0;  ///< e_n [J/kg]
  double temperature = 0.0;      ///< T_n [K]
  double new_density = 0.0;      ///< rho_{n+1} [kg/m^3]
  double new_temperature = 0.0;  ///< T_{n+1} after the step's heating [K]
  double trace_D = 0.0;          ///< tr(D) in the working frame [1/s]
  double dt = 0.0;               ///< [s]
  double heat_per_mass = 0.0;    ///< plastic heat retained this step [J/kg]
};

struct EosStep {
  double pressure = 0.0;         ///< p_{n+1} [Pa]
  double internal_energy = 0.0;  ///< e_{n+1} [J/kg]
  /// False when the new density is outside the EOS's range: the step reports eos_out_of_range.
  bool in_range = true;
};

}  // namespace impact
