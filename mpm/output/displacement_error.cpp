#include "mpm/output/displacement_error.hpp"

#include <cmath>

namespace impact::mpm {

DisplacementError::DisplacementError(const Scene& scene, const Communicator& comm)
    : exact_(scene.output.exact_displacement.value(), scene.constants), comm_(comm) {}

std::vector<double> DisplacementError::read(const Particles& P, double t) {
  const bool outflow = !P.removed.empty();
  double squares = 0.0, mass = 0.0, largest = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (outflow && P.removed[p]) continue;
    const double e2 = (P.x[p] - P.X[p] - exact_(P.X[p], t)).squaredNorm();
    squares += P.mass[p] * e2;
    mass += P.mass[p];
    if (e2 > largest || std::isnan(e2)) largest = e2;  // a NaN shows
  }
  const std::vector<double> sums = comm_.sum({squares, mass});
  const double rms = sums[1] > 0.0 ? std::sqrt(sums[0] / sums[1]) : 0.0;
  return {rms, std::sqrt(comm_.max(largest))};
}

}  // namespace impact::mpm
