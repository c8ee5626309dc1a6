#include "models/eos/mie_gruneisen.hpp"

#include <limits>
#include <string>

namespace impact {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

/// Cold (e = 0) part rho0 C0^2 eta (1 - Gamma0 eta/2)/(1 - S eta)^2; requires admissibility.
double cold_pressure(const MieGruneisenParams& p, double rho0, double eta) {
  const double denominator = 1.0 - p.S_alpha * eta;
  return rho0 * p.C0 * p.C0 * eta * (1.0 - 0.5 * p.Gamma0 * eta) / (denominator * denominator);
}

}  // namespace

bool mie_gruneisen_admissible(const MieGruneisenParams& p, double rho0, double rho) {
  if (!(rho > 0.0)) return false;
  const double eta = 1.0 - rho0 / rho;
  return p.S_alpha * eta < 1.0;
}

double mie_gruneisen_pressure(const MieGruneisenParams& p, double rho0, double rho, double e) {
  if (!mie_gruneisen_admissible(p, rho0, rho)) return infinity;
  const double eta = 1.0 - rho0 / rho;
  return cold_pressure(p, rho0, eta) + rho0 * p.Gamma0 * e;
}

HugoniotPoint mie_gruneisen_hugoniot(const MieGruneisenParams& p, double rho0, double rho) {
  if (!mie_gruneisen_admissible(p, rho0, rho)) return {infinity, infinity};
  const double eta = 1.0 - rho0 / rho;
  const double denominator = 1.0 - p.S_alpha * eta;
  HugoniotPoint h;
  h.pressure = rho0 * p.C0 * p.C0 * eta / (denominator * denominator);
  h.internal_energy = h.pressure * eta / (2.0 * rho0);  // Rayleigh-line work from rest
  return h;
}

double mie_gruneisen_bulk_modulus(const MieGruneisenParams& p, double rho0, double rho, double e) {
  if (!mie_gruneisen_admissible(p, rho0, rho)) return infinity;
  const double eta = 1.0 - rho0 / rho;
  const double denominator = 1.0 - p.S_alpha * eta;
  // rho dp/drho|_e = (rho0/rho) dp_c/deta = (1 - eta) A (1 + (S - Gamma0) eta)/(1 - S eta)^3;
  // (p/rho) dp/de = (p/rho) rho0 Gamma0 = (1 - eta) Gamma0 p.
  const double d_cold = rho0 * p.C0 * p.C0 * (1.0 + (p.S_alpha - p.Gamma0) * eta) /
                        (denominator * denominator * denominator);
  const double pressure = cold_pressure(p, rho0, eta) + rho0 * p.Gamma0 * e;
  return (1.0 - eta) * (d_cold + p.Gamma0 * pressure);
}

MieGruneisenStep mie_gruneisen_update(const MieGruneisenParams& p, double rho0, double rho_old,
                                      double rho_new, double p_old, double e_old,
                                      double heat_per_mass, double specific_heat,
                                      double temperature_old, double temperature_new) {
  MieGruneisenStep step;
  if (!mie_gruneisen_admissible(p, rho0, rho_new)) return {infinity, e_old, false};
  const double cold = cold_pressure(p, rho0, 1.0 - rho0 / rho_new);
  const double stiffness = rho0 * p.Gamma0;  // dp/de at fixed rho
  if (p.energy == MieGruneisenEnergy::cp_temperature) {
    step.internal_energy = e_old + specific_heat * (temperature_new - temperature_old);
  } else {
    // de/dv = -(p_c + k e), k = rho0 Gamma0, with the cold pressure p_c held at its mean over the
    // step, integrated exactly: e1 = e0 + dq - (p_c_mean + k e0 + k dq/2) dv phi(k dv),
    // phi(x) = (1 - exp(-x)) / x. The trapezoidal rule's phi = 1 / (1 + x/2) agrees to x^2 but
    // has a pole at x = -2: a 4 % compression of a point expanded 31-fold (k dv = -2.1; steel,
    // rho0 Gamma0 = 1.3e4 kg/m^3) made the pressure infinite and stopped a valid run. The start
    // pressure is the point's own p_old (after erosion, the eroded one), as the trapezoid had it:
    // the work is done by the stress the point carries.
    const double dv = 1.0 / rho_new - 1.0 / rho_old;
    const double x = stiffness * dv;
    const double phi = x == 0.0 ? 1.0 : -std::expm1(-x) / x;
    const double cold_mean = 0.5 * (p_old - stiffness * e_old + cold);
    step.internal_energy =
        e_old + heat_per_mass -
        (cold_mean + stiffness * e_old + 0.5 * stiffness * heat_per_mass) * dv * phi;
    // exp(-x) beyond the doubles (x < -709: a point expanded a thousandfold halved in one step):
    // out of range, reported, never an infinite energy taken as a state.
    if (!std::isfinite(step.internal_energy)) return {infinity, e_old, false};
  }
  step.pressure = cold + stiffness * step.internal_energy;
  return step;
}

MieGruneisenParams read_mie_gruneisen(JsonReader& r) {
  MieGruneisenParams p;
  r.ignore("type");
  p.C0 = r.quantity("C0", Quantity::sound_speed, Range::positive(),
                    "Mie-Gruneisen bulk sound speed C0 [m/s]");
  p.Gamma0 =
      r.number("Gamma0", Range::non_negative(), "Mie-Gruneisen Gruneisen coefficient Gamma0 [-]");
  // Physically S ~ 1-2 for metals; [0, 10] only rejects typos and sign errors.
  p.S_alpha = r.number("S_alpha", Range::closed(0.0, 10.0),
                       "Mie-Gruneisen Hugoniot slope S in U_s = C0 + S u_p [-]");
  const std::string energy = r.choice(
      "energy", {"evolved", "cp_temperature"},
      "internal energy: evolved from -p dv + heat, or the report's Cp (T - T_room)", "evolved");
  p.energy =
      energy == "cp_temperature" ? MieGruneisenEnergy::cp_temperature : MieGruneisenEnergy::evolved;
  r.reject_unknown_keys();
  return p;
}

Json to_json(const MieGruneisenParams& p) {
  Json j = parameters_to_json(p);
  j.erase("type");  // the block's type is its key (models/eos/equation_of_state.hpp)
  j["energy"] = p.energy == MieGruneisenEnergy::evolved ? "evolved" : "cp_temperature";
  return j;
}

}  // namespace impact
