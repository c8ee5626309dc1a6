#include "pointdriver/verify/closed_forms.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impact::pointdriver::closed_forms {

double poisson_ratio(double K, double mu) {
  return (3.0 * K - 2.0 * mu) / (2.0 * (3.0 * K + mu));
}

double young_modulus(double K, double mu) {
  return 9.0 * K * mu / (3.0 * K + mu);
}

double constrained_modulus(double K, double mu) {
  return K + 4.0 * mu / 3.0;
}

UniaxialStrainYield uniaxial_strain_yield(double K, double mu, double Y) {
  UniaxialStrainYield y;
  y.strain = Y / (2.0 * mu);
  y.axial_stress = constrained_modulus(K, mu) * y.strain;
  y.plateau = Y;
  return y;
}

double johnson_cook_flow_stress(const JohnsonCook& p, double ep, double rate, double T) {
  const double strain_part = p.A + p.B * std::pow(std::max(ep, 0.0), p.n);
  const double rate_part = 1.0 + p.C * std::log(std::max(rate / p.reference_rate, 1.0));
  const double Tstar = (T - p.room_temperature) / (p.melt_temperature - p.room_temperature);
  const double thermal_part = Tstar <= 0.0 ? 1.0 : Tstar >= 1.0 ? 0.0 : 1.0 - std::pow(Tstar, p.m);
  return strain_part * rate_part * thermal_part;
}

ShearStress green_naghdi_simple_shear(double mu, double gamma) {
  const double b = std::atan(gamma / 2.0);
  const double c2 = std::cos(2.0 * b), s2 = std::sin(2.0 * b), lc = std::log(std::cos(b));
  ShearStress s;
  s.xx = 4.0 * mu * (c2 * lc + b * s2 - std::sin(b) * std::sin(b));
  s.yy = -s.xx;
  s.xy = 2.0 * mu * c2 * (2.0 * b - 2.0 * std::tan(2.0 * b) * lc - std::tan(b));
  return s;
}

ShearStress jaumann_simple_shear(double mu, double gamma) {
  ShearStress s;
  s.xy = mu * std::sin(gamma);
  s.xx = mu * (1.0 - std::cos(gamma));
  s.yy = -s.xx;
  return s;
}

ShearStress green_naghdi_simple_shear_series(double mu, double g) {
  const double g2 = g * g;
  ShearStress s;
  s.xy = mu * g *
         (1.0 +
          g2 * (-1.0 / 6.0 + g2 * (11.0 / 240.0 + g2 * (-79.0 / 6720.0 + g2 * 479.0 / 161280.0))));
  s.xx = mu * g2 *
         (0.5 +
          g2 * (-5.0 / 48.0 + g2 * (1.0 / 40.0 + g2 * (-331.0 / 53760.0 + g2 * 493.0 / 322560.0))));
  s.yy = -s.xx;
  return s;
}

ShearStress green_naghdi_simple_shear_quadrature(double mu, double gamma, int intervals) {
  // R = [[c, s], [-s, c]] (tan b = g/2) is the rotation of F = [[1, g], [0, 1]]; the unrotated
  // rate of deformation per unit gamma is R^T S R with S = [[0, 1/2], [1/2, 0]].
  const auto integrand = [](double g, double& a11, double& a12) {
    const double b = std::atan(g / 2.0);
    const double c = std::cos(b), s = std::sin(b);
    // (R^T S R)_11 = -c s... written out: R^T S R = [[-c s, (c^2 - s^2)/2], [.., c s]].
    a11 = -c * s;
    a12 = 0.5 * (c * c - s * s);
  };
  const int n = intervals + intervals % 2;
  const double h = gamma / n;
  double h11 = 0.0, h12 = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    double a11 = 0.0, a12 = 0.0;
    integrand(k * h, a11, a12);
    h11 += w * a11;
    h12 += w * a12;
  }
  h11 *= 2.0 * mu * h / 3.0;  // sigma_hat_11 = -sigma_hat_22
  h12 *= 2.0 * mu * h / 3.0;
  // sigma = R sigma_hat R^T.
  const double b = std::atan(gamma / 2.0);
  const double c = std::cos(b), s = std::sin(b);
  ShearStress out;
  out.xx = (c * c - s * s) * h11 + 2.0 * c * s * h12;
  out.yy = -out.xx;
  out.xy = -2.0 * c * s * h11 + (c * c - s * s) * h12;
  return out;
}

double compression(double rho0, double rho) {
  return 1.0 - rho0 / rho;
}

double hugoniot_pressure(const MieGruneisen& p, double rho) {
  const double eta = compression(p.rho0, rho);
  const double d = 1.0 - p.S * eta;
  return p.rho0 * p.C0 * p.C0 * eta / (d * d);
}

double hugoniot_energy(const MieGruneisen& p, double rho) {
  return hugoniot_pressure(p, rho) * compression(p.rho0, rho) / (2.0 * p.rho0);
}

double mie_gruneisen_pressure(const MieGruneisen& p, double rho, double e) {
  const double eta = compression(p.rho0, rho);
  return hugoniot_pressure(p, rho) * (1.0 - 0.5 * p.Gamma0 * eta) + p.Gamma0 * p.rho0 * e;
}

ShockState shock_state(const MieGruneisen& p, double up) {
  const double Us = p.C0 + p.S * up;
  return {p.rho0 * Us * up, p.rho0 * Us / (Us - up)};
}

double johnson_cook_fracture_strain(const JohnsonCookDamage& p, double eta, double rate, double T) {
  const double Tstar =
      std::clamp((T - p.room_temperature) / (p.melt_temperature - p.room_temperature), 0.0, 1.0);
  return (p.D1 + p.D2 * std::exp(p.D3 * eta)) *
         (1.0 + p.D4 * std::log(std::max(rate / p.reference_rate, 1.0))) * (1.0 + p.D5 * Tstar);
}

double adiabatic_temperature_rise(double chi, double work_per_mass, double cp) {
  return chi * work_per_mass / cp;
}

ShearStress neo_hookean_simple_shear(double mu, double gamma) {
  return {mu * gamma * gamma, 0.0, mu * gamma};
}

UniaxialStretch neo_hookean_uniaxial_stress(double mu, double lambda, double stretch) {
  struct Data {
    double mu, lambda, s;
  } data{mu, lambda, stretch};
  gsl_function f;
  f.params = &data;
  f.function = [](double t, void* p) {
    const Data& d = *static_cast<const Data*>(p);
    return d.mu * (t * t - 1.0) + d.lambda * std::log(d.s * t * t);
  };
  // With lambda > 0, g(t) -> -inf as t -> 0 and grows as mu t^2: one root, bracketed from 1e-6
  // to 1e3 for any stretch a solid reaches.
  if (!(lambda > 0.0)) throw std::invalid_argument("neo_hookean_uniaxial_stress: lambda <= 0");
  gsl_set_error_handler_off();
  gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  if (gsl_root_fsolver_set(solver, &f, 1e-6, 1e3) != GSL_SUCCESS) {
    gsl_root_fsolver_free(solver);
    throw std::runtime_error("neo_hookean_uniaxial_stress: no bracket");
  }
  double t = 1.0;
  int status = GSL_CONTINUE;
  for (int i = 0; i < 200 && status == GSL_CONTINUE; ++i) {
    gsl_root_fsolver_iterate(solver);
    t = gsl_root_fsolver_root(solver);
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver),
                                    gsl_root_fsolver_x_upper(solver), 0.0, 1e-15);
  }
  gsl_root_fsolver_free(solver);
  if (status != GSL_SUCCESS) throw std::runtime_error("neo_hookean_uniaxial_stress: no root");
  return {t, mu * (stretch * stretch - t * t) / (stretch * t * t)};
}

}  // namespace impact::pointdriver::closed_forms
