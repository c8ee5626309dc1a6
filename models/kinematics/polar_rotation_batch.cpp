#include "models/kinematics/polar_rotation_batch.hpp"

namespace impact {

// One copy per instruction set, chosen at load time, with GCC; one generic copy with clang (see
// models/plasticity/johnson_cook_return.cpp).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void polar_rotation_batch(PolarRotationBatch& batch) {
  batch.out = polar_rotation_lanes(batch.F, batch.guess);
}

}  // namespace impact
