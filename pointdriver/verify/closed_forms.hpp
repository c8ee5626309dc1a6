// Reference solutions of the point driver's verification suite, written here again from their
// sources (not by calling models/), so that a check compares two independent implementations.
// SI units: Pa, 1/s, K, kg/m^3, J/kg.
#pragma once

namespace impact::pointdriver::closed_forms {

// ---- isotropic linear elasticity (any text, e.g. Timoshenko & Goodier, Theory of Elasticity) ----

/// Poisson's ratio nu = (3K - 2mu) / (2 (3K + mu)).
double poisson_ratio(double bulk_modulus, double shear_modulus);

/// Young's modulus E = 9 K mu / (3K + mu).
double young_modulus(double bulk_modulus, double shear_modulus);

/// Constrained (P-wave) modulus M = K + 4 mu / 3: sigma_xx = M eps_xx in uniaxial strain.
double constrained_modulus(double bulk_modulus, double shear_modulus);

// ---- elastic-perfectly-plastic uniaxial strain (von Mises, yield stress Y) ----
// Elastic: sigma_xx = M eps, sigma_yy = (K - 2mu/3) eps, so sigma_xx - sigma_yy = 2 mu eps reaches
// Y at |eps| = Y/(2mu): the Hugoniot elastic limit sigma_xx = M Y/(2mu) (e.g. Meyers, Dynamic
// Behavior of Materials, 1994, sec. 7.2). Beyond it
// |sigma_xx - sigma_yy| = Y and sigma_xx = K eps -+ 2Y/3.
struct UniaxialStrainYield {
  double strain = 0.0;        ///< |eps_xx| at first yield [-]
  double axial_stress = 0.0;  ///< |sigma_xx| at first yield [Pa]
  double plateau = 0.0;       ///< |sigma_xx - sigma_yy| after yield [Pa]
};
UniaxialStrainYield uniaxial_strain_yield(double bulk_modulus, double shear_modulus,
                                          double yield_stress);

// ---- Johnson-Cook flow stress (Johnson & Cook 1983; report eq. 5), written again here ----
struct JohnsonCook {
  double A = 0.0, B = 0.0, n = 1.0, C = 0.0, m = 1.0;
  double reference_rate = 1.0;  ///< [1/s]
  double room_temperature = 294.0, melt_temperature = 925.0;
};
/// sigma_y = (A + B ep^n)(1 + C ln max(rate/rate0, 1))(1 - T*^m), T* = (T - T_r)/(T_m - T_r),
/// with the temperature factor 1 below room temperature and 0 above melting (the "clamped" rate
/// form of the material file).
double johnson_cook_flow_stress(const JohnsonCook& p, double plastic_strain, double rate,
                                double temperature);

// ---- finite simple shear of a hypoelastic solid, F = I + gamma e_x (x) e_y ----
struct ShearStress {
  double xx = 0.0, yy = 0.0, xy = 0.0;  ///< Cauchy stress in the fixed (lab) frame [Pa]
};
/// Green-Naghdi (polar) rate: Dienes (1979), Acta Mech. 32:217-232, eq. (4.11); with
/// tan beta = gamma / 2,
///   sigma_xx = -sigma_yy = 4 mu (cos 2b ln cos b + b sin 2b - sin^2 b),
///   sigma_xy = 2 mu cos 2b (2b - 2 tan 2b ln cos b - tan b).
ShearStress green_naghdi_simple_shear(double shear_modulus, double gamma);

/// Jaumann rate: sigma_xy = mu sin gamma, sigma_xx = -sigma_yy = mu (1 - cos gamma) (Dienes 1979,
/// eq. (3.9); Nagtegaal & de Jong 1982): the spurious oscillation of the shear stress.
ShearStress jaumann_simple_shear(double shear_modulus, double gamma);

/// The small-gamma expansion of the Green-Naghdi solution, derived separately from the rate
/// equation (not from Dienes's formula): with R the rotation of F = R U (tan b = gamma/2),
/// sigma_hat = 2 mu int_0^gamma R^T sym(e_x (x) e_y) R dg is expanded term by term and rotated
/// back:
///   sigma_xy / mu = g - g^3/6 + 11 g^5/240 - 79 g^7/6720 + 479 g^9/161280 + O(g^11),
///   sigma_xx / mu = g^2/2 - 5 g^4/48 + g^6/40 - 331 g^8/53760 + 493 g^10/322560 + O(g^12)
/// (coefficients from a computer-algebra expansion of that integral).
/// Used to check the closed form at small gamma before trusting it.
ShearStress green_naghdi_simple_shear_series(double shear_modulus, double gamma);

/// The same integral evaluated by composite Simpson quadrature with `intervals` (even) intervals:
/// a check of the closed form at large gamma that shares none of its algebra.
ShearStress green_naghdi_simple_shear_quadrature(double shear_modulus, double gamma, int intervals);

// ---- Mie-Gruneisen EOS on the linear Us-up Hugoniot (Meyers 1994, ch. 4; Uintah MPM user
//      guide) ----
struct MieGruneisen {
  double rho0 = 0.0, C0 = 0.0, S = 0.0, Gamma0 = 0.0;
};
/// eta = 1 - rho0/rho, compression positive.
double compression(double rho0, double rho);
/// Hugoniot pressure p_H = rho0 C0^2 eta / (1 - S eta)^2 [Pa].
double hugoniot_pressure(const MieGruneisen& p, double rho);
/// Hugoniot specific energy e_H = p_H eta / (2 rho0) [J/kg] (Rankine-Hugoniot energy jump).
double hugoniot_energy(const MieGruneisen& p, double rho);
/// p(rho, e) = p_H (1 - Gamma0 eta / 2) + Gamma0 rho0 e (rho Gamma = rho0 Gamma0) [Pa].
double mie_gruneisen_pressure(const MieGruneisen& p, double rho, double e);
/// Jump conditions of a shock of particle speed up into material at rest: U_s = C0 + S up,
/// p = rho0 U_s up, rho = rho0 U_s / (U_s - up).
struct ShockState {
  double pressure = 0.0, density = 0.0;
};
ShockState shock_state(const MieGruneisen& p, double particle_speed);

// ---- Johnson-Cook fracture strain (Johnson & Cook 1985; report eq. 7) ----
struct JohnsonCookDamage {
  double D1 = 0.0, D2 = 0.0, D3 = 0.0, D4 = 0.0, D5 = 0.0;
  double reference_rate = 1.0;
  double room_temperature = 294.0, melt_temperature = 925.0;
};
/// eps_f = (D1 + D2 exp(D3 eta)) (1 + D4 ln max(rate/rate0, 1)) (1 + D5 T*), eta =
/// sigma_m/sigma_eq, T* clamped to [0, 1].
double johnson_cook_fracture_strain(const JohnsonCookDamage& p, double triaxiality, double rate,
                                    double temperature);

// ---- the compressible neo-Hookean solid (models/elasticity/neo_hookean.hpp), written here
// from W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2 alone, not from the library ----
/// Simple shear F = I + gamma e_x (x) e_y: J = 1 and sigma = mu (b - I), so sigma_xy = mu gamma,
/// sigma_xx = mu gamma^2, sigma_yy = 0 (Ogden 1984, Non-linear Elastic Deformations, sec. 5.2.2,
/// for any J = 1 neo-Hookean).
ShearStress neo_hookean_simple_shear(double mu, double gamma);

/// Uniaxial stress F = diag(s, t, t): the lateral stretch t solves sigma_yy = 0,
///   mu (t^2 - 1) + lambda ln(s t^2) = 0   (monotonic in t for lambda > 0; GSL's Brent),
/// and then sigma_xx = mu (s^2 - t^2) / (s t^2).
struct UniaxialStretch {
  double lateral = 1.0;  ///< t [-]
  double axial = 0.0;    ///< sigma_xx [Pa]
};
UniaxialStretch neo_hookean_uniaxial_stress(double mu, double lambda, double stretch);

// ---- adiabatic heating (Taylor & Quinney 1934; report eq. 8) ----
/// Temperature rise chi W / (rho cp) of a plastic work per unit mass W/rho [J/kg].
double adiabatic_temperature_rise(double taylor_quinney, double plastic_work_per_mass,
                                  double specific_heat);

}  // namespace impact::pointdriver::closed_forms
