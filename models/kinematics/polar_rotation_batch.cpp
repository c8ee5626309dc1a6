#include "models/kinematics/polar_rotation_batch.hpp"

namespace impact {

// One copy per instruction set, chosen at load time; the template is inlined into each (see
// models/plasticity/johnson_cook_return.cpp).
#if defined(__x86_64__) && defined(__has_attribute)
#if __has_attribute(target_clones)
__attribute__((target_clones("avx512f", "avx2", "default"), flatten))
#endif
#endif
void polar_rotation_batch(PolarRotationBatch& batch) {
  batch.out = polar_rotation_lanes(batch.F, batch.guess);
}

}  // namespace impact
