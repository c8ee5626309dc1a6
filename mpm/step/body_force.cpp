#include "mpm/step/body_force.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/threads/threads.hpp"

namespace impact::mpm {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

BodyForces::BodyForces(const Scene& scene, int threads)
    : fields_(std::size_t(std::max(1, threads))) {
  for (auto& per_object : fields_)
    for (const SceneObject& o : scene.objects)
      per_object.emplace_back(o.has_body_force() ? std::optional<VectorField>(
                                                       std::in_place, o.body_force, scene.constants)
                                                 : std::nullopt);
}

void BodyForces::evaluate(const Particles& P, double t) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(P.size());
  b_.resize(P.size());  // the particle count changes only when particles migrate between ranks
  const bool outflow = !P.removed.empty();
  const int nt = static_cast<int>(fields_.size());
  // Per thread: the largest |b_p| (a NaN wins) and its particle, the lowest seed index on a tie
  // (the particle named is the same whatever the storage order and the thread count).
  double largest[kMaxThreads] = {};
  std::ptrdiff_t where[kMaxThreads] = {};
#pragma omp parallel num_threads(nt)
  {
    std::vector<std::optional<VectorField>>& field = fields_[std::size_t(omp_get_thread_num())];
    double peak = 0.0;
    std::ptrdiff_t at = -1;
#pragma omp for schedule(static)
    for (std::ptrdiff_t p = 0; p < n; ++p) {
      std::optional<VectorField>& f = field[P.object[p]];
      b_[p] = f && !(outflow && P.removed[p]) ? (*f)(P.X[p], t) : Vec3::Zero();
      // |b| beyond sqrt(max double) squares to inf: then the scaled norm (a finite 1e300 is
      // a body force the step limit can name, not an overflow).
      const double norm = b_[p].allFinite() ? b_[p].norm() : kInfinity;
      const double size = std::isinf(norm) && b_[p].allFinite() ? b_[p].stableNorm() : norm;
      if (!std::isinf(peak) &&
          (size > peak || (size == peak && at >= 0 &&
                           seed_index(P, std::size_t(p)) < seed_index(P, std::size_t(at))))) {
        peak = size;
        at = p;
      }
    }
    largest[omp_get_thread_num()] = peak;
    where[omp_get_thread_num()] = at;
  }
  int top = 0;  // the largest; of equals, the lowest seed index
  for (int k = 1; k < nt; ++k)
    if (largest[k] > largest[top] ||
        (largest[k] == largest[top] && where[k] >= 0 &&
         (where[top] < 0 ||
          seed_index(P, std::size_t(where[k])) < seed_index(P, std::size_t(where[top])))))
      top = k;
  peak_ = largest[top];
  strongest_ = where[top] < 0 ? 0 : std::size_t(where[top]);
  finite_ = !std::isinf(peak_) || b_.empty() || b_[strongest_].allFinite();
}

}  // namespace impact::mpm
