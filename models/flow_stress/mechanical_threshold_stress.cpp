#include "models/flow_stress/mechanical_threshold_stress.hpp"

#include <algorithm>
#include <cmath>

namespace impact {

namespace {

constexpr double kBoltzmann = 1.380649e-23;  // [J/K]

/// mu(T) (Varshni) and d mu / d T.
struct Modulus {
  double mu = 0.0, d_T = 0.0;
};
Modulus varshni(const MechanicalThresholdStressParams& p, double T) {
  if (p.D == 0.0 || p.T0 <= 0.0 || T <= 0.0 || p.T0 / T > 700.0) return {p.mu0, 0.0};
  const double e = std::exp(p.T0 / T);
  return {p.mu0 - p.D / (e - 1.0), -p.D * e * p.T0 / (T * T) / ((e - 1.0) * (e - 1.0))};
}

/// The law's mu and d mu / d T: its own Varshni, or the nested block's catalogue form.
Modulus modulus(const MechanicalThresholdStressParams& p, const FlowConditions& c) {
  if (!p.shear_modulus) return varshni(p, c.temperature);
  const ModulusConditions mc{c.temperature, c.pressure, c.compression, c.density,
                             c.melt_temperature > 0.0 ? c.melt_temperature : p.melt_temperature};
  const ModulusWithSlope m = shear_modulus_with_slope(*p.shear_modulus, p.mu0, mc);
  return {m.mu, m.d_T};
}

/// A hardening-rate fit c0 + c1 ln(rate) + c2 sqrt(rate) - c3 T held at 0 where it is negative
/// (theta_0 and theta_IV; see the header), with its derivatives (0 on the clamped side).
struct Rate {
  double value = 0.0, d_rate = 0.0, d_T = 0.0;
};
Rate hardening_rate(double c0, double c1, double c2, double c3, double rate, bool rate_clamped,
                    double T) {
  const double value = c0 + c1 * std::log(rate) + c2 * std::sqrt(rate) - c3 * T;
  if (!(value > 0.0)) return {0.0, 0.0, 0.0};
  return {value, rate_clamped ? 0.0 : c1 / rate + 0.5 * c2 / std::sqrt(rate), -c3};
}

/// A thermal-activation factor S = [1 - x^(1/q)]^(1/p), x = k T / (g0 b^3 mu) ln(eps0 / rate),
/// with its derivatives in rate and T.
struct Activation {
  double S = 1.0, d_rate = 0.0, d_T = 0.0;
};
Activation activation(double g0, double eps0, double p_exp, double q_exp, double b, double rate,
                      bool rate_clamped, double T, const Modulus& m) {
  const double c = kBoltzmann / (g0 * b * b * b);
  const double log_ratio = std::log(eps0 / rate);
  const double x = c * T / m.mu * log_ratio;
  if (x <= 0.0) return {1.0, 0.0, 0.0};  // faster than the reference rate: no thermal help
  const double y = 1.0 - std::pow(x, 1.0 / q_exp);
  if (y <= 0.0) return {0.0, 0.0, 0.0};  // the barrier is overcome thermally
  const double S = std::pow(y, 1.0 / p_exp);
  const double dS_dx = -(1.0 / p_exp) * std::pow(y, 1.0 / p_exp - 1.0) * (1.0 / q_exp) *
                       std::pow(x, 1.0 / q_exp - 1.0);
  const double dx_drate = rate_clamped ? 0.0 : -c * T / m.mu / rate;
  const double dx_dT = c * log_ratio * (m.mu - T * m.d_T) / (m.mu * m.mu);
  return {S, dS_dx * dx_drate, dS_dx * dx_dT};
}

/// theta(sigma_e, rate, T) = theta_0 (1 - F(X)) + theta_IV F(X) and its derivatives in rate and
/// T.
struct Hardening {
  double theta = 0.0, d_rate = 0.0, d_T = 0.0;
};
Hardening hardening(const MechanicalThresholdStressParams& p, double sigma_e, double rate,
                    bool rate_clamped, double T, const Modulus& m) {
  const Rate theta0 = hardening_rate(p.a0, p.a1, p.a2, p.a3, rate, rate_clamped, T);
  const Rate theta_iv = hardening_rate(p.aIV0, p.aIV1, p.aIV2, p.aIV3, rate, rate_clamped, T);
  const double c_es = kBoltzmann / (p.g0_es * p.burgers * p.burgers * p.burgers);
  const double log_ratio = std::log(rate / p.eps0_es);
  const double sigma_es = p.sigma_es0 * std::exp(c_es * T / m.mu * log_ratio);
  const double dses_drate = rate_clamped ? 0.0 : sigma_es * c_es * T / m.mu / rate;
  const double dses_dT = sigma_es * log_ratio * c_es * (m.mu - T * m.d_T) / (m.mu * m.mu);
  const double X = sigma_e / sigma_es;
  const double tanh_alpha = std::tanh(p.alpha);
  const double t = std::tanh(p.alpha * X);
  const double F = t / tanh_alpha;
  const double dF_dX = p.alpha * (1.0 - t * t) / tanh_alpha;
  const double dX_drate = -X / sigma_es * dses_drate, dX_dT = -X / sigma_es * dses_dT;
  Hardening h{theta0.value * (1.0 - F), theta0.d_rate * (1.0 - F) - theta0.value * dF_dX * dX_drate,
              theta0.d_T * (1.0 - F) - theta0.value * dF_dX * dX_dT};
  if (theta_iv.value > 0.0) {  // stage IV adds its terms (none without: stage III bit for bit)
    h.theta += theta_iv.value * F;
    h.d_rate += theta_iv.d_rate * F + theta_iv.value * dF_dX * dX_drate;
    h.d_T += theta_iv.d_T * F + theta_iv.value * dF_dX * dX_dT;
  }
  return h;
}

/// The law's parameters at temperature T, without the block: above its T_c, the block's set.
MechanicalThresholdStressParams at_temperature(const MechanicalThresholdStressParams& p, double T) {
  MechanicalThresholdStressParams q = p;
  q.above_critical_temperature.reset();
  if (!p.above_critical_temperature || !(T > p.above_critical_temperature->T_c)) return q;
  const MtsAboveCriticalTemperature& a = *p.above_critical_temperature;
  q.sigma_i = a.sigma_i;
  q.g0_i = a.g0_i;
  q.sigma_es0 = a.sigma_es0;
  q.g0_es = a.g0_es;
  q.a0 = a.a0;
  q.a1 = a.a1;
  q.a2 = a.a2;
  q.a3 = a.a3;
  q.aIV0 = a.aIV0;
  q.aIV1 = a.aIV1;
  q.aIV2 = a.aIV2;
  q.aIV3 = a.aIV3;
  return q;
}

}  // namespace

MtsFactors mts_factors(const MechanicalThresholdStressParams& law, double rate,
                       const FlowConditions& c) {
  const double T = c.temperature;
  if (law.above_critical_temperature) return mts_factors(at_temperature(law, T), rate, c);
  const MechanicalThresholdStressParams& p = law;
  const bool clamped = rate < p.minimum_strain_rate;
  const double r = clamped ? p.minimum_strain_rate : rate;
  const Modulus m = modulus(p, c);
  const Hardening h = hardening(p, 0.0, r, clamped, T, m);
  const double c_es = kBoltzmann / (p.g0_es * p.burgers * p.burgers * p.burgers);
  return {m.mu,
          activation(p.g0_i, p.eps0_i, p.p_i, p.q_i, p.burgers, r, clamped, T, m).S,
          activation(p.g0_e, p.eps0_e, p.p_e, p.q_e, p.burgers, r, clamped, T, m).S,
          h.theta,
          p.sigma_es0 * std::exp(c_es * T / m.mu * std::log(r / p.eps0_es)),
          hardening_rate(p.aIV0, p.aIV1, p.aIV2, p.aIV3, r, clamped, T).value};
}

MtsFactors mts_factors(const MechanicalThresholdStressParams& p, double rate, double T) {
  FlowConditions c;
  c.temperature = T;
  return mts_factors(p, rate, c);
}

FlowStress flow_stress(const MechanicalThresholdStressParams& law, double ep, double rate,
                       const FlowConditions& c) {
  const double T = c.temperature;
  if (law.above_critical_temperature) return flow_stress(at_temperature(law, T), ep, rate, c);
  const MechanicalThresholdStressParams& p = law;
  const bool clamped = rate < p.minimum_strain_rate;
  const double r = clamped ? p.minimum_strain_rate : rate;
  const Modulus m = modulus(p, c);
  // A catalogue form floored at 0 (above its range: no shear stiffness, as molten).
  if (p.shear_modulus && !(m.mu > 0.0)) return {p.sigma_a, 0.0, 0.0, 0.0};
  const Activation Si = activation(p.g0_i, p.eps0_i, p.p_i, p.q_i, p.burgers, r, clamped, T, m);
  const Activation Se = activation(p.g0_e, p.eps0_e, p.p_e, p.q_e, p.burgers, r, clamped, T, m);
  const Hardening h = hardening(p, c.internal, r, clamped, T, m);
  double d_ep = std::max(ep - c.start_plastic_strain, 0.0);
  double sigma_e = c.internal + h.theta * d_ep;
  double theta = h.theta;
  if (sigma_e < 0.0) sigma_e = theta = d_ep = 0.0;  // held at 0: nothing varies it there
  const double scale = m.mu / p.mu0;
  const double thermal = Si.S * p.sigma_i + Se.S * sigma_e;
  FlowStress f;
  f.value = p.sigma_a + thermal * scale;
  f.d_plastic_strain = Se.S * theta * scale;
  f.d_rate = (Si.d_rate * p.sigma_i + Se.d_rate * sigma_e + Se.S * h.d_rate * d_ep) * scale;
  f.d_temperature = (Si.d_T * p.sigma_i + Se.d_T * sigma_e + Se.S * h.d_T * d_ep) * scale +
                    thermal * m.d_T / p.mu0;
  return f;
}

double internal_after(const MechanicalThresholdStressParams& law, double internal, double d_ep,
                      double rate, const FlowConditions& c) {
  if (law.above_critical_temperature)
    return internal_after(at_temperature(law, c.temperature), internal, d_ep, rate, c);
  const MechanicalThresholdStressParams& p = law;
  const bool clamped = rate < p.minimum_strain_rate;
  const double r = clamped ? p.minimum_strain_rate : rate;
  const Modulus m = modulus(p, c);
  if (p.shear_modulus && !(m.mu > 0.0)) return internal;
  return std::max(internal + hardening(p, internal, r, clamped, c.temperature, m).theta * d_ep,
                  0.0);
}

// Finite bounds on the hardening polynomials' coefficients, so that a typo (1e300) is refused
// here rather than stalling a return: 1000 GPa for the constant term (the 4340 fits' largest is
// 41 GPa), 100 GPa per unit of ln(rate) or sqrt(rate) (0.22 GPa), 10 GPa/K (0.11 GPa/K).
const Range kRateTerm0 = Range::closed(-1e12, 1e12);
const Range kRateTerm = Range::closed(-1e11, 1e11);
const Range kPerKelvin = Range::closed(-1e10, 1e10);

MechanicalThresholdStressParams read_law(JsonReader& r, const MechanicalThresholdStressParams*,
                                         double, double melt_temperature) {
  using P = MechanicalThresholdStressParams;
  P p;
  r.ignore("type");
  const auto stress = [&](const char* key, double P::*member, Range range, const char* what) {
    p.*member = r.quantity(key, Quantity::stress, range, what);
  };
  const auto number = [&](const char* key, double P::*member, Range range, const char* what) {
    p.*member = r.number(key, range, what);
  };
  stress("sigma_a", &P::sigma_a, Range::non_negative(), "MTS athermal stress sigma_a [Pa]");
  stress("sigma_i", &P::sigma_i, Range::non_negative(), "MTS intrinsic barrier sigma_i [Pa]");
  // An fcc metal has no intrinsic barrier (sigma_i = 0; Follansbee & Kocks' copper): its
  // activation keys are then optional, since S_i multiplies zero.
  const auto intrinsic = [&](const char* key, double P::*member, Range range, const char* what) {
    p.*member =
        p.sigma_i > 0.0 ? r.number(key, range, what) : r.number_or(key, p.*member, range, what);
  };
  intrinsic("g0_i", &P::g0_i, Range::positive(), "MTS intrinsic activation energy g0_i [-]");
  intrinsic("eps0_i", &P::eps0_i, Range::positive(), "MTS intrinsic reference rate [1/s]");
  intrinsic("p_i", &P::p_i, Range::open_closed(0.0, 1.0), "MTS intrinsic exponent p_i [-]");
  intrinsic("q_i", &P::q_i, Range::closed(1.0, 2.0), "MTS intrinsic exponent q_i [-]");
  number("g0_e", &P::g0_e, Range::positive(), "MTS structure activation energy g0_e [-]");
  number("eps0_e", &P::eps0_e, Range::positive(), "MTS structure reference rate [1/s]");
  number("p_e", &P::p_e, Range::open_closed(0.0, 1.0), "MTS structure exponent p_e [-]");
  number("q_e", &P::q_e, Range::closed(1.0, 2.0), "MTS structure exponent q_e [-]");
  // a0 may be negative: the hardening-rate fits of Banerjee (2007) are polynomials whose terms
  // together, not a0 alone, are the positive rate (Rc 30: a0 = -5210 MPa).
  stress("a0", &P::a0, kRateTerm0, "MTS hardening rate a0 [Pa]");
  number("a1", &P::a1, kRateTerm, "MTS hardening rate a1 (per ln rate) [Pa]");
  number("a2", &P::a2, kRateTerm, "MTS hardening rate a2 (per sqrt rate) [Pa s^0.5]");
  number("a3", &P::a3, kPerKelvin, "MTS hardening rate a3 (per K) [Pa/K]");
  // Stage IV (Banerjee 2007 eq. 8; Goto et al. 2000): optional, 0 without.
  p.aIV0 = r.quantity_or("aIV0", 0.0, Quantity::stress, kRateTerm0,
                         "MTS stage-IV hardening rate aIV0 [Pa]");
  p.aIV1 = r.number_or("aIV1", 0.0, kRateTerm, "MTS stage-IV rate aIV1 (per ln rate) [Pa]");
  p.aIV2 = r.number_or("aIV2", 0.0, kRateTerm, "MTS stage-IV rate aIV2 (per sqrt rate) [Pa s^0.5]");
  p.aIV3 = r.number_or("aIV3", 0.0, kPerKelvin, "MTS stage-IV rate aIV3 (per K) [Pa/K]");
  number("alpha", &P::alpha, Range::positive(), "MTS tanh hardening shape alpha [-]");
  stress("sigma_es0", &P::sigma_es0, Range::positive(), "MTS saturation stress sigma_es0 [Pa]");
  number("g0_es", &P::g0_es, Range::positive(), "MTS saturation activation energy g0_es [-]");
  number("eps0_es", &P::eps0_es, Range::positive(), "MTS saturation reference rate [1/s]");
  number("burgers", &P::burgers, Range::open_closed(0.0, 1e-8), "Burgers vector b [m]");
  stress("mu0", &P::mu0, Range::open_closed(0.0, 2e12), "MTS shear modulus at 0 K mu0 [Pa]");
  if (auto block =
          r.optional_child("shear_modulus", "the law's shear modulus mu (absent: Varshni)")) {
    p.shear_modulus = read_shear_modulus(*block);
    p.melt_temperature = melt_temperature;
    for (const char* key : {"D", "T0"}) {
      if (!r.has(key)) continue;
      r.problems().add(r.key_path(key),
                       "Varshni's key beside a shear_modulus block: give the modulus once");
      r.ignore(key);  // named once, above, not again as unknown
    }
  } else {
    stress("D", &P::D, Range::non_negative(), "Varshni D [Pa]");
    number("T0", &P::T0, Range::non_negative(), "Varshni T0 [K]");
  }
  p.minimum_strain_rate = r.number_or("minimum_strain_rate", 1e-6, Range::positive(),
                                      "slowest rate the law is evaluated at [1/s]");
  if (auto block = r.optional_child("above_critical_temperature",
                                    "the set that replaces the law's above T_c")) {
    MtsAboveCriticalTemperature a;
    a.T_c = block->number("T_c", Range::positive(), "MTS critical temperature T_c [K]");
    a.sigma_i = block->quantity("sigma_i", Quantity::stress, Range::non_negative(),
                                "MTS intrinsic barrier above T_c [Pa]");
    a.g0_i = block->number("g0_i", Range::positive(), "MTS g0_i above T_c [-]");
    a.sigma_es0 = block->quantity("sigma_es0", Quantity::stress, Range::positive(),
                                  "MTS saturation stress above T_c [Pa]");
    a.g0_es = block->number("g0_es", Range::positive(), "MTS g0_es above T_c [-]");
    a.a0 = block->quantity("a0", Quantity::stress, kRateTerm0, "MTS a0 above T_c [Pa]");
    a.a1 = block->number("a1", kRateTerm, "MTS a1 above T_c [Pa]");
    a.a2 = block->number("a2", kRateTerm, "MTS a2 above T_c [Pa s^0.5]");
    a.a3 = block->number("a3", kPerKelvin, "MTS a3 above T_c [Pa/K]");
    a.aIV0 =
        block->quantity_or("aIV0", 0.0, Quantity::stress, kRateTerm0, "MTS aIV0 above T_c [Pa]");
    a.aIV1 = block->number_or("aIV1", 0.0, kRateTerm, "MTS aIV1 above T_c [Pa]");
    a.aIV2 = block->number_or("aIV2", 0.0, kRateTerm, "MTS aIV2 above T_c [Pa s^0.5]");
    a.aIV3 = block->number_or("aIV3", 0.0, kPerKelvin, "MTS aIV3 above T_c [Pa/K]");
    block->reject_unknown_keys();
    p.above_critical_temperature = a;
  }
  r.reject_unknown_keys();
  return p;
}

Json to_json(const MechanicalThresholdStressParams& p) {
  Json j = parameters_to_json(p);
  if (p.shear_modulus) {  // the block replaces Varshni's keys (read_law refuses both)
    j.erase("D");
    j.erase("T0");
    j["shear_modulus"] = to_json(*p.shear_modulus);
  }
  if (const auto& a = p.above_critical_temperature) {
    j["above_critical_temperature"] = {{"T_c", a->T_c},     {"sigma_i", a->sigma_i},
                                       {"g0_i", a->g0_i},   {"sigma_es0", a->sigma_es0},
                                       {"g0_es", a->g0_es}, {"a0", a->a0},
                                       {"a1", a->a1},       {"a2", a->a2},
                                       {"a3", a->a3},       {"aIV0", a->aIV0},
                                       {"aIV1", a->aIV1},   {"aIV2", a->aIV2},
                                       {"aIV3", a->aIV3}};
  }
  return j;
}

}  // namespace impact
