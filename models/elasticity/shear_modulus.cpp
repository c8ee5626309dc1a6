#include "models/elasticity/shear_modulus.hpp"

#include <algorithm>
#include <cmath>

namespace impact {

namespace {

constexpr double kBoltzmann = 1.380649e-23;  // [J/K]
constexpr double kAvogadro = 6.02214076e23;  // [1/mol]

double modulus(const ConstantShearModulus&, double mu0, const ModulusConditions&) {
  return mu0;
}
double modulus(const VarshniShearModulus& v, double mu0, const ModulusConditions& c) {
  return mu0 - v.D / std::expm1(v.T0 / c.temperature);
}
double modulus(const SteinbergShearModulus& s, double mu0, const ModulusConditions& c) {
  return mu0 + s.dG_dp * c.pressure / std::cbrt(c.compression) + s.dG_dT * (c.temperature - 300.0);
}
double modulus(const NadalLePoacShearModulus& n, double mu0, const ModulusConditions& c) {
  const double t = c.temperature / c.melt_temperature;
  if (t >= 1.0 + n.zeta) return 0.0;
  const double J = 1.0 + std::exp(-(1.0 + 1.0 / n.zeta) / (1.0 + n.zeta / (1.0 - t)));
  const double atom = n.molar_mass / kAvogadro;
  return ((mu0 + n.dG_dp * c.pressure / std::cbrt(c.compression)) * (1.0 - t) +
          c.density * kBoltzmann * c.temperature / (n.C * atom)) /
         J;
}

// d mu / d T of each form at fixed p and rho (the derivative of the expression above).
double slope(const ConstantShearModulus&, double, const ModulusConditions&) {
  return 0.0;
}
double slope(const VarshniShearModulus& v, double, const ModulusConditions& c) {
  const double T = c.temperature, m = std::expm1(v.T0 / T);
  return -v.D * (m + 1.0) * v.T0 / (T * T) / (m * m);
}
double slope(const SteinbergShearModulus& s, double, const ModulusConditions&) {
  return s.dG_dT;
}
// mu = N / J with N = A (1 - t) + rho k_B T / (C m_atom), A = mu0 + G'_p p / eta^(1/3), t = T /
// T_m; J = 1 + exp(-(1 + 1/zeta) / u), u = 1 + zeta / (1 - t): dJ/dt = (J - 1)(1 + zeta) / ((1 - t)
// u)^2.
double slope(const NadalLePoacShearModulus& n, double mu0, const ModulusConditions& c) {
  const double Tm = c.melt_temperature, t = c.temperature / Tm;
  if (t >= 1.0 + n.zeta) return 0.0;
  const double u = 1.0 + n.zeta / (1.0 - t);
  const double J = 1.0 + std::exp(-(1.0 + 1.0 / n.zeta) / u);
  const double dJ_dt = (J - 1.0) * (1.0 + n.zeta) / (((1.0 - t) * u) * ((1.0 - t) * u));
  const double atom = n.molar_mass / kAvogadro;
  const double A = mu0 + n.dG_dp * c.pressure / std::cbrt(c.compression);
  const double N = A * (1.0 - t) + c.density * kBoltzmann * c.temperature / (n.C * atom);
  const double dN_dT = -A / Tm + c.density * kBoltzmann / (n.C * atom);
  return dN_dT / J - N * dJ_dt / (J * J * Tm);
}

// Each form's reader: its parameters, with their ranges ("type" and unknown keys are the caller's).
ConstantShearModulus read_model(JsonReader&, const ConstantShearModulus*) {
  return {};
}
VarshniShearModulus read_model(JsonReader& r, const VarshniShearModulus*) {
  VarshniShearModulus v;
  v.D = r.quantity("D", Quantity::elastic_modulus, Range::non_negative(), "Varshni D [Pa]");
  v.T0 = r.quantity("T0", Quantity::temperature, Range::positive(), "Varshni T0 [K]");
  return v;
}
SteinbergShearModulus read_model(JsonReader& r, const SteinbergShearModulus*) {
  SteinbergShearModulus s;
  s.dG_dp = r.number("dG_dp", Range::closed(0.0, 10.0), "SCG G'_p = dG/dp [-]");
  s.dG_dT = r.number("dG_dT", Range::closed(-1e9, 0.0), "SCG G'_T = dG/dT [Pa/K]");
  return s;
}
NadalLePoacShearModulus read_model(JsonReader& r, const NadalLePoacShearModulus*) {
  NadalLePoacShearModulus n;
  n.dG_dp = r.number("dG_dp", Range::closed(0.0, 10.0), "Nadal-Le Poac dG/dp [-]");
  n.zeta = r.number("zeta", Range::open(0.0, 1.0), "Nadal-Le Poac zeta [-]");
  n.C = r.number("C", Range::positive(), "Nadal-Le Poac C [-]");
  n.molar_mass = r.number("molar_mass", Range::open(1e-3, 1.0), "molar mass [kg/mol]");
  return n;
}

}  // namespace

double shear_modulus(const ShearModulusLaw& law, double mu0, const ModulusConditions& c) {
  return std::max(std::visit([&](const auto& l) { return modulus(l, mu0, c); }, law), 0.0);
}

ModulusWithSlope shear_modulus_with_slope(const ShearModulusLaw& law, double mu0,
                                          const ModulusConditions& c) {
  const double mu = shear_modulus(law, mu0, c);
  if (mu <= 0.0) return {0.0, 0.0};
  return {mu, std::visit([&](const auto& l) { return slope(l, mu0, c); }, law)};
}

bool is_constant(const ShearModulusLaw& law) {
  return std::holds_alternative<ConstantShearModulus>(law);
}

ShearModulusLaw read_shear_modulus(JsonReader& r) {
  const std::string type = r.choice("type", model_types<ShearModulusLaw>(), "shear modulus model",
                                    ConstantShearModulus::kType);
  const ShearModulusLaw law = read_by_type<ShearModulusLaw>(type, [&](const auto* tag) {
                                return read_model(r, tag);
                              }).value_or(ShearModulusLaw{});
  r.reject_unknown_keys();
  return law;
}

Json to_json(const ShearModulusLaw& law) {
  return std::visit([](const auto& l) { return parameters_to_json(l); }, law);
}

}  // namespace impact
