// The error against an exact displacement field (output.exact_displacement, docs/scenes.md#output):
// a manufactured solution's u(X, t) (Wallstedt & Guilkey 2008) against each particle's
// displacement x_p - X_p, as two history.csv columns:
//   displacement_error_rms [m] = sqrt(sum_p m_p |x_p - X_p - u(X_p, t)|^2 / sum_p m_p),
//   displacement_error_max [m] = max_p |x_p - X_p - u(X_p, t)|,
// over the particles in play (a removed one left the simulation). Read at the history rows only.
#pragma once

#include <string>
#include <vector>

#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/particles.hpp"

namespace impact::mpm {

class DisplacementError {
 public:
  /// output.exact_displacement must be set.
  DisplacementError(const Scene& scene, const Communicator& comm);

  static std::vector<std::string> columns() {
    return {"displacement_error_rms [m]", "displacement_error_max [m]"};
  }
  /// {rms, max} at time t over the particles of every rank (collective on several ranks); P
  /// holds the reference positions (Particles::X).
  std::vector<double> read(const Particles& P, double t);

 private:
  VectorField exact_;
  const Communicator& comm_;
};

}  // namespace impact::mpm
