#include "mpm/ledger/ledger.hpp"

#include <stdexcept>

namespace impact::mpm {

int Ledger::add_sink_column(std::string name, bool in_balance) {
  sink_names_.push_back(std::move(name));
  sinks_.push_back(0.0);
  in_balance_.push_back(in_balance);
  return static_cast<int>(sinks_.size()) - 1;
}

void Ledger::start(double time, double kinetic_energy, const Vec3& momentum) {
  time_ = time;
  kinetic_ = kinetic_energy;
  initial_energy_ = kinetic_energy;  // the initial strain energy is zero: stress-free start
  momentum_ = momentum;
  p0_ = momentum;
}

void Ledger::record_step(double time, double kinetic_energy, const Vec3& momentum,
                         double strain_energy_increment, const Vec3& boundary_impulse,
                         const Vec3& external_impulse, double external_work) {
  time_ = time;
  kinetic_ = kinetic_energy;
  momentum_ = momentum;
  strain_ += strain_energy_increment;
  boundary_impulse_ += boundary_impulse;
  external_impulse_ += external_impulse;
  external_work_ += external_work;
}

LedgerRow Ledger::row() const {
  LedgerRow r;
  r.time = time_;
  r.kinetic_energy = kinetic_;
  r.strain_energy = strain_;
  r.total_energy = kinetic_ + strain_;
  r.momentum = momentum_;
  r.boundary_impulse = boundary_impulse_;
  r.sinks = sinks_;
  r.outflow_mass = outflow_mass_;
  r.outflow_momentum = outflow_momentum_;
  r.outflow_kinetic_energy = outflow_kinetic_;
  r.external_impulse = external_impulse_;
  r.external_work = external_work_;
  const double scale = initial_energy_ > 0.0 ? initial_energy_ : 1.0;
  r.energy_error = energy_excess() / scale;
  return r;
}

double Ledger::energy_excess() const {
  double sunk = 0.0;
  for (std::size_t i = 0; i < sinks_.size(); ++i)
    if (in_balance_[i]) sunk += sinks_[i];
  return (kinetic_ + strain_) + sunk + outflow_kinetic_ - initial_energy_ - external_work_;
}

std::vector<std::string> Ledger::columns() const {
  std::vector<std::string> c = {"time [s]",
                                "kinetic_energy [J]",
                                "strain_energy [J]",
                                "total_energy [J]",
                                "momentum_x [kg m/s]",
                                "momentum_y [kg m/s]",
                                "momentum_z [kg m/s]",
                                "boundary_impulse_x [N s]",
                                "boundary_impulse_y [N s]",
                                "boundary_impulse_z [N s]"};
  for (const std::string& s : sink_names_) c.push_back(s + " [J]");
  if (with_outflow_) {
    c.insert(c.end(),
             {"outflow_mass [kg]", "outflow_momentum_x [kg m/s]", "outflow_momentum_y [kg m/s]",
              "outflow_momentum_z [kg m/s]", "outflow_kinetic_energy [J]"});
  }
  if (with_external_) {
    c.insert(c.end(), {"external_impulse_x [N s]", "external_impulse_y [N s]",
                       "external_impulse_z [N s]", "external_work [J]"});
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

Ledger::State Ledger::state() const {
  State s;
  s.time = time_;
  s.kinetic = kinetic_;
  s.strain = strain_;
  s.external_work = external_work_;
  s.initial_energy = initial_energy_;
  s.outflow_mass = outflow_mass_;
  s.outflow_kinetic = outflow_kinetic_;
  s.momentum = momentum_;
  s.p0 = p0_;
  s.boundary_impulse = boundary_impulse_;
  s.external_impulse = external_impulse_;
  s.outflow_momentum = outflow_momentum_;
  s.sinks = sinks_;
  return s;
}

void Ledger::restore(const State& s) {
  if (s.sinks.size() != sinks_.size()) {
    throw std::invalid_argument("ledger: " + std::to_string(s.sinks.size()) + " sink columns for " +
                                std::to_string(sinks_.size()));
  }
  time_ = s.time;
  kinetic_ = s.kinetic;
  strain_ = s.strain;
  external_work_ = s.external_work;
  initial_energy_ = s.initial_energy;
  outflow_mass_ = s.outflow_mass;
  outflow_kinetic_ = s.outflow_kinetic;
  outflow_momentum_ = s.outflow_momentum;
  momentum_ = s.momentum;
  p0_ = s.p0;
  boundary_impulse_ = s.boundary_impulse;
  external_impulse_ = s.external_impulse;
  sinks_ = s.sinks;
}

}  // namespace impact::mpm
