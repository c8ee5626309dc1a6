#include "models/failure/tepla.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impact {

double tepla_indicator(double porosity, double critical_porosity, double damage) {
  const double f_ratio = porosity / critical_porosity;
  return f_ratio * f_ratio + damage * damage;
}

double nucleation_intensity(const TeplaParams& p, double plastic_strain) {
  const double z = (plastic_strain - p.nucleation_strain) / p.nucleation_std;
  return p.nucleation_fraction / (p.nucleation_std * std::sqrt(2.0 * std::numbers::pi)) *
         std::exp(-0.5 * z * z);
}

double porosity_update(const TeplaParams& p, double porosity, double trace_D, double plastic_strain,
                       double delta_plastic_strain, double dt) {
  // Voids grow only under dilatation; compression does not close them (the 2004 code's choice).
  const double growth = (1.0 - porosity) * std::max(trace_D, 0.0) * dt;
  const double nucleation = nucleation_intensity(p, plastic_strain) * delta_plastic_strain;
  static constexpr double kBelowOne = 1.0 - 1e-12;  // keeps 1 - f > 0 at the next step
  return std::clamp(porosity + growth + nucleation, 0.0, kBelowOne);
}

TeplaParams read_tepla(JsonReader& r) {
  TeplaParams p;
  p.enabled = r.boolean_or("enabled", p.enabled, "check the TEPLA-F criterion on failed points");
  p.critical_porosity = r.number_or("critical_porosity", p.critical_porosity,
                                    Range::open_closed(0.0, 1.0), "critical porosity f_c [-]");
  p.initial_porosity = r.number_or("initial_porosity", p.initial_porosity,
                                   Range{0.0, 1.0, false, true}, "initial porosity f_0 [-]");
  p.evolve_porosity =
      r.boolean_or("evolve_porosity", p.evolve_porosity, "grow and nucleate voids (eq. 9's f)");
  p.nucleation_fraction =
      r.number_or("nucleation_fraction", p.nucleation_fraction, Range::closed(0.0, 1.0),
                  "Chu-Needleman void-nucleating volume fraction f_n [-]");
  p.nucleation_strain = r.number_or("nucleation_strain", p.nucleation_strain, Range::non_negative(),
                                    "Chu-Needleman mean strain e_n [-]");
  p.nucleation_std = r.number_or("nucleation_std", p.nucleation_std, Range::positive(),
                                 "Chu-Needleman strain standard deviation s_n [-]");
  const std::string growth =
      r.choice("porosity_growth", {"dilatation", "tension"},
               "when porosity evolves: plastic steps with dilatation (the 2004 code's), or only "
               "while the mean stress is tensile",
               "dilatation");
  if (growth == "tension") p.growth = PorosityGrowth::tension;
  // f_0 >= f_c would fail every point at its first plastic step.
  if (p.initial_porosity >= p.critical_porosity) {
    r.problems().add(r.key_path("initial_porosity"),
                     "expected an initial porosity below critical_porosity");
  }
  r.reject_unknown_keys();
  return p;
}

}  // namespace impact
