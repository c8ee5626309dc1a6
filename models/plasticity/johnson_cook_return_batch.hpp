// The radial return (radial_return.hpp) on the Johnson-Cook flow stress for a vector of points at
// once: the batched half of the constitutive update (models/material/update_batch.hpp). The
// vector is lane::Vec (eight doubles, GCC's vector extension); its operations are compiled for
// AVX-512, AVX2 and SSE2 and the widest the CPU has is chosen when the program loads. The law and
// the return are the templates the one-point update instantiates with double (radial_return with
// JohnsonCookAtTemperature, used by ElasticPlastic::update and so by the point driver), and every
// operation is an IEEE basic one (models/core/lane_math.hpp), so a point gets the same bits in a
// vector as alone: tests/models/plasticity/radial_return_test.cpp and
// tests/models/material/update_batch_test.cpp check it.
#pragma once

#include "models/core/lane_math.hpp"
#include "models/flow_stress/johnson_cook.hpp"
#include "models/plasticity/radial_return.hpp"

namespace impact {

/// Points per batch: the lanes of lane::Vec.
inline constexpr int kReturnLanes = lane::kLaneWidth;

/// The return's inputs and outputs for kReturnLanes points of one material, with each point's
/// temperature factor of the flow stress (johnson_cook_thermal at its start-of-step temperature).
struct alignas(lane::kLaneBytes) JohnsonCookReturnBatch {
  ReturnValues<lane::Vec> lanes;
  lane::Vec thermal_factor{};
  lane::Vec thermal_d_factor{};

  /// Lane k as an elastic no-op (q_trial = 0), for a batch that is not full.
  void clear(int k);
};

/// Newton's radial return on every lane (ReturnAlgorithm::newton).
void johnson_cook_return_batch(const JohnsonCookParams& p, const ReturnTolerance& tol,
                               JohnsonCookReturnBatch& batch);

}  // namespace impact
