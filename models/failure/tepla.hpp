// TEPLA-F failure criterion: Johnson & Addessio (1988), J. Appl. Phys. 64:6699-6712; report eq.
// (9):
//   (f / f_c)^2 + D^2 >= 1  ->  failed,
// with f the porosity, f_c the critical porosity and D = eps_p / eps_p^f the Johnson-Cook damage
// (damage/johnson_cook_damage), which equals eps_p / eps_f on a path at constant triaxiality, rate
// and temperature. The report kept the porosity at zero (its sec. 3), so by default it does not
// evolve and the criterion reduces to D >= 1.
//
// Optional porosity growth (the 2004 code's, docs/report_code.md sec. 3):
//   f_dot = (1 - f) max(tr D, 0) + A(eps_p) eps_dot_p,
//   A(eps_p) = f_n / (s_n sqrt(2 pi)) exp(-((eps_p - e_n) / s_n)^2 / 2)
// (void growth from the dilatation rate by mass conservation of the matrix; Chu & Needleman (1980),
// J. Eng. Mater. Technol. 102:249, strain-controlled nucleation, whose integral over eps_p is f_n).
// The matrix here is pressure-insensitive J2, so it has no plastic dilatation; the growth term uses
// the total tr D as the 2004 code did (it includes the elastic dilatation, a small overestimate).
// Integrated by forward Euler over the step with the start-of-step f and eps_p; f is kept in
// [0, 1) so that (1 - f) stays positive and the point never becomes all void.
#pragma once

#include "models/core/input.hpp"

namespace impact {

/// When porosity evolves: at every plastic step with dilatation (the 2004 code's), or only while
/// the mean stress is tensile: compression does not open voids (growth and nucleation).
enum class PorosityGrowth { dilatation, tension };

struct TeplaParams {
  bool enabled = true;             ///< check the criterion (only when erosion is on, report sec. 3)
  double critical_porosity = 0.5;  ///< f_c [-]
  double initial_porosity = 0.0;   ///< f_0 [-]
  bool evolve_porosity = false;    ///< off: the report kept f = 0
  double nucleation_fraction = 0.1;  ///< f_n, volume fraction of void-nucleating particles [-]
  double nucleation_strain = 0.3;    ///< e_n, mean plastic strain of nucleation [-]
  double nucleation_std = 0.1;       ///< s_n, standard deviation of the nucleation strain [-]
  PorosityGrowth growth = PorosityGrowth::dilatation;  ///< the report's: dilatation
};

/// TEPLA-F indicator (f/f_c)^2 + D^2; the point has failed when it is >= 1.
double tepla_indicator(double porosity, double critical_porosity, double damage);

/// Chu-Needleman nucleation intensity A(eps_p) [-] (df = A d eps_p).
double nucleation_intensity(const TeplaParams& p, double plastic_strain);

/// Porosity at the end of a step of length dt [s] from the start-of-step porosity and plastic
/// strain, tr D [1/s] and the plastic-strain increment of the step. Does not look at
/// `evolve_porosity`: the caller decides whether porosity evolves.
double porosity_update(const TeplaParams& p, double porosity, double trace_D, double plastic_strain,
                       double delta_plastic_strain, double dt);

/// Reads {"enabled", "critical_porosity", "initial_porosity", "evolve_porosity",
/// "nucleation_fraction", "nucleation_strain", "nucleation_std", "porosity_growth"}; every key is
/// optional.
TeplaParams read_tepla(JsonReader& r);

}  // namespace impact
