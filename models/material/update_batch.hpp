// Constitutive updates of up to kReturnLanes points at once: the polar rotations of their
// deformation gradients together on the vector lanes (polar_rotation_batch), each point's
// remaining kinematics and trial stress (ElasticPlastic::begin_update), the radial returns of all
// of them together (johnson_cook_return), then each point's pressure, damage, failure and rotation
// back (finish_update). A point gets the same bits as from ElasticPlastic::update alone
// (tests/models/material/update_batch_test.cpp). The MPM's stress update drives one per thread.
//
//   UpdateBatch batch;
//   for each point i of a block: batch.add(model_i, s0_i, L_i, F1_i, s1_i)  (lane i)
//   batch.run(dt);                       // the returns, grouped by material
//   for each lane i: report_i = batch.finish(i, s0_i, dt, s1_i)
#pragma once

#include <array>

#include "models/kinematics/corotation_batch.hpp"
#include "models/kinematics/polar_rotation_batch.hpp"
#include "models/material/elastic_plastic.hpp"

namespace impact {

class UpdateBatch {
 public:
  static constexpr int capacity = kReturnLanes;

  int size() const { return size_; }
  bool full() const { return size_ == capacity; }

  /// Queues a point's update in the next lane; its start-of-step state and s1 must stay in place
  /// until finish. Returns the lane. A point that cannot start (det F1 <= 0) gets its report's
  /// status from run and takes no part in the return.
  int add(const ElasticPlastic& model, const PointState& s0, const Mat3& L, const Mat3& F1,
          PointState& s1);

  /// The rotations, trial stresses and radial returns of every lane added since the last clear.
  void run(double dt);

  /// Finishes lane k's update into s1 (the state passed to add) and returns its report.
  StepReport finish(int k, double dt, PointState& s1);

  /// Empties the batch for the next block.
  void clear() { size_ = 0; }

 private:
  struct Lane {
    const ElasticPlastic* model = nullptr;
    const PointState* s0 = nullptr;
    PointState* s1 = nullptr;
    Mat3 L, F1;
    UpdateTrial trial;
    StepReport report;
    ReturnResult result;
    bool started = false;
  };
  std::array<Lane, capacity> lanes_;
  PolarRotationBatch rotations_;
  CorotationBatch corotations_;
  JohnsonCookReturnBatch returns_;
  int size_ = 0;
};

}  // namespace impact
