#include "mpm/ledger/ledger.hpp"

#include <algorithm>
#include <stdexcept>

namespace impact::mpm {

int Ledger::add_sink_column(std::string name, bool in_balance, bool unchecked) {
  sink_names_.push_back(std::move(name));
  s_.sinks.push_back(0.0);
  in_balance_.push_back(in_balance);
  unchecked_.push_back(unchecked);
  return static_cast<int>(s_.sinks.size()) - 1;
}

void Ledger::start(double time, double kinetic_energy, const Vec3& momentum, double drive,
                   double stored) {
  s_.time = time;
  s_.kinetic = kinetic_energy;
  // The initial strain energy is zero: stress-free start.
  s_.initial_energy = kinetic_energy + stored;
  s_.peak_input = std::max(s_.initial_energy, drive);
  s_.momentum = booked(momentum);
  s_.p0 = s_.momentum;
}

void Ledger::record_step(double time, double kinetic_energy, const Vec3& momentum,
                         double strain_energy_increment, const Vec3& boundary_impulse,
                         const Vec3& external_impulse, double external_work) {
  s_.time = time;
  s_.kinetic = kinetic_energy;
  s_.momentum = booked(momentum);
  s_.strain += strain_energy_increment;
  s_.boundary_impulse += booked(boundary_impulse);
  s_.external_impulse += booked(external_impulse);
  s_.external_work += external_work;
  s_.peak_input = std::max(s_.peak_input, s_.initial_energy + s_.external_work);
}

LedgerRow Ledger::row() const {
  LedgerRow r;
  r.time = s_.time;
  r.kinetic_energy = s_.kinetic;
  r.strain_energy = s_.strain;
  r.total_energy = s_.kinetic + s_.strain;
  r.momentum = s_.momentum;
  r.boundary_impulse = s_.boundary_impulse;
  r.sinks = s_.sinks;
  r.outflow_mass = s_.outflow_mass;
  r.outflow_momentum = s_.outflow_momentum;
  r.outflow_kinetic_energy = s_.outflow_kinetic;
  r.external_impulse = s_.external_impulse;
  r.external_work = s_.external_work;
  const double scale = s_.peak_input > 0.0 ? s_.peak_input : 1.0;  // E_in (ledger.hpp)
  r.energy_error = energy_excess() / scale;
  return r;
}

double Ledger::energy_excess() const {
  double sunk = 0.0;
  for (std::size_t i = 0; i < s_.sinks.size(); ++i)
    if (in_balance_[i]) sunk += s_.sinks[i];
  return (s_.kinetic + s_.strain) + sunk + s_.outflow_kinetic - s_.initial_energy -
         s_.external_work;
}

double Ledger::growth_excess() const {
  double excess = energy_excess();
  for (std::size_t i = 0; i < s_.sinks.size(); ++i)
    if (unchecked_[i]) excess -= s_.sinks[i];
  return excess;
}

std::vector<std::pair<std::string, double>> Ledger::checked_sinks() const {
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t i = 0; i < s_.sinks.size(); ++i)
    if (in_balance_[i] && !unchecked_[i]) out.emplace_back(sink_names_[i], s_.sinks[i]);
  return out;
}

std::vector<std::string> Ledger::columns() const {
  const auto in = [](const std::string& unit) { return " [" + unit + "]"; };
  const std::string J = in(units_.energy), p = in(units_.momentum), I = in(units_.impulse);
  std::vector<std::string> c = {"time [s]",
                                "kinetic_energy" + J,
                                "strain_energy" + J,
                                "total_energy" + J,
                                "momentum_x" + p,
                                "momentum_y" + p,
                                "momentum_z" + p,
                                "boundary_impulse_x" + I,
                                "boundary_impulse_y" + I,
                                "boundary_impulse_z" + I};
  for (const std::string& s : sink_names_) c.push_back(s + J);
  if (with_outflow_) {
    c.insert(c.end(),
             {"outflow_mass" + in(units_.mass), "outflow_momentum_x" + p, "outflow_momentum_y" + p,
              "outflow_momentum_z" + p, "outflow_kinetic_energy" + J});
  }
  if (with_external_) {
    c.insert(c.end(), {"external_impulse_x" + I, "external_impulse_y" + I, "external_impulse_z" + I,
                       "external_work" + J});
  }
  c.push_back("energy_error [-]");
  return c;
}

std::vector<double> Ledger::values(const LedgerRow& r) const {
  std::vector<double> v = {r.time,
                           r.kinetic_energy,
                           r.strain_energy,
                           r.total_energy,
                           r.momentum(0),
                           r.momentum(1),
                           r.momentum(2),
                           r.boundary_impulse(0),
                           r.boundary_impulse(1),
                           r.boundary_impulse(2)};
  v.insert(v.end(), r.sinks.begin(), r.sinks.end());
  if (with_outflow_) {
    v.insert(v.end(), {r.outflow_mass, r.outflow_momentum(0), r.outflow_momentum(1),
                       r.outflow_momentum(2), r.outflow_kinetic_energy});
  }
  if (with_external_) {
    v.insert(v.end(), {r.external_impulse(0), r.external_impulse(1), r.external_impulse(2),
                       r.external_work});
  }
  v.push_back(r.energy_error);
  return v;
}

void Ledger::restore(const State& s) {
  if (s.sinks.size() != s_.sinks.size()) {
    throw std::invalid_argument("ledger: " + std::to_string(s.sinks.size()) + " sink columns for " +
                                std::to_string(s_.sinks.size()));
  }
  s_ = s;
}

}  // namespace impact::mpm
