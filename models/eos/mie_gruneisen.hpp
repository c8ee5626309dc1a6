// Mie-Gruneisen equation of state referenced to the linear U_s-u_p Hugoniot (report eq. 3,
// corrected; Uintah MPM user guide, Mie-Gruneisen section; Meyers, "Dynamic Behavior of Materials",
// Wiley 1994, ch. 4). With eta = 1 - rho0/rho (compression positive) and p compression positive:
//   p(rho, e) = rho0 C0^2 eta (1 - Gamma0 eta/2) / (1 - S eta)^2 + rho0 Gamma0 e,
// e = specific internal energy above the reference state (rho0, p = 0, e = 0) [J/kg], and
// rho Gamma = rho0 Gamma0 (the usual constant-rho-Gamma assumption). On the Hugoniot (from the jump
// conditions with U_s = C0 + S u_p):
//   p_H = rho0 C0^2 eta / (1 - S eta)^2,   e_H = p_H eta / (2 rho0),
// and p(rho, e_H) = p_H identically. The report's eq. (3), written with zeta = rho/rho0 - 1, is the
// same cold term; its "+ Gamma0 Cp T" is misplaced inside the denominator, lacks the factor rho0
// (J/kg added to Pa), and uses the absolute temperature. The 2004 code had the units error and also
// returned p = 0 at rho = rho0 whatever T (docs/report_code.md sec. 0 item 4). We use
// rho0 Gamma0 e.
//
// Choices:
//  - Tension (eta < 0) uses the same formula (as Uintah does): a smooth extrapolation of the
//    Hugoniot fit, with p -> -rho0 C0^2 Gamma0/(2 S^2) as rho -> 0 (S > 0). No spall cut-off;
//    tensile failure belongs to failure/ (TEPLA) and damage/.
//  - Compression limit: p -> +inf as eta -> 1/S; beyond it the formula turns back down, which is
//    unphysical. mie_gruneisen_admissible() says whether rho is inside (0 < rho, S eta < 1).
//    Outside, the pressure and the bulk modulus return +inf (the limit value, never a silent NaN
//    nor a plausible wrong number) and mie_gruneisen_update() sets admissible = false; the caller
//    must report the state as out of range.
//  - Energy (MieGruneisenEnergy):
//      evolved (default): de = -p dv + dq (v = 1/rho; dq = heat per unit mass from plastic work).
//        Since p is linear in e, the step with the cold pressure held at its mean is a linear ODE
//        solved exactly (mie_gruneisen_update); it is second order and reversible to round-off
//        (the same mean both ways), and agrees with the trapezoid of p to (rho0 Gamma0 dv)^2 / 12.
//      cp_temperature: the report's approximation E = Cp T (eq. 15), measured from the point's
//        initial state: e = Cp (T - T_0), advanced as e += Cp (T_{n+1} - T_n). The literal
//        absolute form would put rho0 Gamma0 Cp T (= 2700 * 1.99 * 896 * 294 = 1.4 GPa for
//        6061-T6 at 294 K) of pressure into material at rest. This mode ignores the compression
//        work -p dv; the report blames this approximation for the energy growth it saw with
//        Mie-Gruneisen (report sec. 5.12, Case 13, Fig. 13).
//  - Reference state: e is the specific internal energy above the point's initial state (at rest,
//    stress-free, at its initial temperature T_0 and density rho0), so e = 0 at t = 0 whatever
//    T_0 (docs/theory.md sec. 2, "internal energy and temperature").
#pragma once

#include "models/core/catalogue.hpp"
#include "models/core/input.hpp"
#include "models/eos/eos_step.hpp"

namespace impact {

enum class MieGruneisenEnergy {
  evolved,         ///< e from de = -p dv + dq (energy-consistent; default)
  cp_temperature,  ///< e = Cp (T - T_room), the report's eq. (15) measured from the reference state
};

struct MieGruneisenParams {
  double C0 = 0.0;       ///< bulk sound speed, intercept of U_s = C0 + S u_p [m/s]
  double Gamma0 = 0.0;   ///< Gruneisen coefficient at the reference state [-]
  double S_alpha = 0.0;  ///< slope S of U_s = C0 + S u_p [-]
  MieGruneisenEnergy energy = MieGruneisenEnergy::evolved;

  static constexpr std::string_view kType = "mie_gruneisen";
  static constexpr std::string_view kMeaning =
      "Mie-Gruneisen parameters";  ///< of its block, in messages
  static constexpr LawParameter<MieGruneisenParams> kParameters[] = {
      {"C0", "m/s", &MieGruneisenParams::C0},
      {"Gamma0", "-", &MieGruneisenParams::Gamma0},
      {"S_alpha", "-", &MieGruneisenParams::S_alpha}};
};

/// True when rho > 0 and 1 - S eta > 0 (eta = 1 - rho0/rho), where the EOS is defined.
bool mie_gruneisen_admissible(const MieGruneisenParams& p, double rho0, double rho);

/// p(rho, e) [Pa], compression positive; rho0, rho [kg/m^3], e [J/kg]. +inf if not admissible.
double mie_gruneisen_pressure(const MieGruneisenParams& p, double rho0, double rho, double e);

struct HugoniotPoint {
  double pressure = 0.0;         ///< p_H [Pa]
  double internal_energy = 0.0;  ///< e_H [J/kg] above the reference state
};

/// The Hugoniot state at density rho (from the reference state at rest). +inf if not admissible.
HugoniotPoint mie_gruneisen_hugoniot(const MieGruneisenParams& p, double rho0, double rho);

/// Isentropic bulk modulus rho c^2 = rho dp/drho|_s = rho dp/drho|_e + (p/rho) dp/de [Pa]
/// (along an isentrope de = -p dv = p drho/rho^2). In closed form, with A = rho0 C0^2:
///   rho c^2 = (1 - eta) [A (1 + (S - Gamma0) eta)/(1 - S eta)^3 + Gamma0 p(rho, e)],
/// which is rho0 C0^2 at the reference state. For the stable time step and artificial viscosity.
/// +inf if not admissible; it can fall below zero only in extreme tension with large negative p.
double mie_gruneisen_bulk_modulus(const MieGruneisenParams& p, double rho0, double rho, double e);

struct MieGruneisenStep {
  double pressure = 0.0;         ///< p_{n+1} [Pa]
  double internal_energy = 0.0;  ///< e_{n+1} [J/kg]
  bool admissible = true;        ///< false beyond the compression limit (pressure = +inf)
};

/// One step from (rho_old, p_old, e_old) to rho_new.
///   evolved:        de = -p dv + dq with p = p_c + rho0 Gamma0 e, the cold (e = 0) part p_c held
///                   at its step mean (p_c(rho_old) + p_c(rho_new))/2, integrated exactly in e:
///                   e1 = e0 + dq - (p_c_mean + k e0 + k dq/2) dv (1 - exp(-k dv)) / (k dv),
///                   k = rho0 Gamma0, p1 = p(rho_new, e1). To x^2 (x = k dv) it is the trapezoidal
///                   e1 = e0 - (p0 + p1)/2 dv + dq, whose 1 / (1 + x/2) has a pole at x = -2: a
///                   few per cent compression of a point expanded 30-fold. p_old should be
///                   p(rho_old, e_old).
///   cp_temperature: e1 = e_old + Cp (T_new - T_old), p1 = p(rho_new, e1); p_old and dq unused
///                   (the plastic heat is already in T_new).
/// heat_per_mass [J/kg], specific_heat [J/(kg K)], temperatures [K]. Not admissible (pressure +inf,
/// energy e_old) beyond the compression limit, or where exp(-rho0 Gamma0 dv) leaves the doubles
/// (a point expanded a thousandfold halved in one step).
MieGruneisenStep mie_gruneisen_update(const MieGruneisenParams& p, double rho0, double rho_old,
                                      double rho_new, double p_old, double e_old,
                                      double heat_per_mass, double specific_heat,
                                      double temperature_old, double temperature_new);

/// The catalogue's step (models/eos/eos_step.hpp): out of range beyond the compression limit
/// (S eta >= 1), else mie_gruneisen_update from the start-of-step state.
inline EosStep eos_step(const MieGruneisenParams& p, const EosMaterial& m, const EosStepInput& in) {
  const double eta = 1.0 - m.density / in.new_density;
  if (!(p.S_alpha * eta < 1.0)) return {in.pressure, in.internal_energy, false};
  const MieGruneisenStep step = mie_gruneisen_update(
      p, m.density, in.density, in.new_density, in.pressure, in.internal_energy, in.heat_per_mass,
      m.specific_heat, in.temperature, in.new_temperature);
  return {step.pressure, step.internal_energy, step.admissible};
}
/// The isentropic bulk modulus at (density, internal_energy): mie_gruneisen_bulk_modulus.
inline double eos_bulk_modulus(const MieGruneisenParams& p, const EosMaterial& m, double density,
                               double internal_energy) {
  return mie_gruneisen_bulk_modulus(p, m.density, density, internal_energy);
}

/// Reads {"C0" (m/s, > 0), "Gamma0" (>= 0), "S_alpha" ([0, 10]), "energy": "evolved" (default) |
/// "cp_temperature"}; "type" is read by the caller.
MieGruneisenParams read_mie_gruneisen(JsonReader& r);
/// The catalogue's reader (models/eos/equation_of_state.hpp): read_mie_gruneisen.
inline MieGruneisenParams read_model(JsonReader& r, const MieGruneisenParams*) {
  return read_mie_gruneisen(r);
}
/// {"C0", "Gamma0", "S_alpha", "energy"}: the block read_mie_gruneisen reads back.
Json to_json(const MieGruneisenParams& p);

}  // namespace impact
