// Constitutive updates of up to kReturnLanes points at once. A point whose material uses the
// Green-Naghdi rate, Newton's return and the default_hypo pressure, and that is not molten (the
// MPM's common case), goes through the whole step on the vector lanes: the polar rotation of its
// F_{n+1} (polar_rotation_batch), the un-rotations (corotation_batch), the trial deviator, the
// radial return (johnson_cook_return_batch, grouped by material), heating and pressure, and the
// rotation back (elastic_plastic_batch.hpp); only damage, failure and erosion, where a step needs
// them, run one point at a time (ElasticPlastic::damage_and_failure). Any other point takes the
// one-point steps (ElasticPlastic::begin_update, its return, finish_update), with its rotations and
// return still on the lanes. Every point gets the same bits as from ElasticPlastic::update alone
// (tests/models/material/update_batch_test.cpp). The MPM's stress update drives one per thread.
//
//   UpdateBatch batch;
//   for each point i of a block: batch.add(model_i, s0_i, L_i, F1_i, s1_i)  (lane i)
//   batch.run(dt);
//   for each lane i: report_i = batch.finish(i, dt, s1_i)
#pragma once

#include <array>

#include "models/kinematics/corotation_batch.hpp"
#include "models/kinematics/polar_rotation_batch.hpp"
#include "models/material/elastic_plastic.hpp"
#include "models/material/elastic_plastic_batch.hpp"

namespace impact {

class UpdateBatch {
 public:
  static constexpr int capacity = kReturnLanes;

  int size() const { return size_; }
  bool full() const { return size_ == capacity; }

  /// Queues a point's update in the next lane; s0, L, F1 and s1 must stay in place until finish.
  /// Returns the lane. A point that cannot start (det F1 <= 0) gets its report's status from run
  /// and takes no part in the return.
  int add(const ElasticPlastic& model, const PointState& s0, const Mat3& L, const Mat3& F1,
          PointState& s1);

  /// Every lane's update added since the last clear, up to finish_update for the one-point lanes.
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
    const Mat3* L = nullptr;
    const Mat3* F1 = nullptr;
    UpdateTrial trial;
    StepReport report;
    ReturnResult result;
    bool started = false;
    bool polar = false;  ///< green_naghdi with det F1 > 0: its rotations are on the lanes
    bool lanes = false;  ///< the whole step on the lanes (the header's common case)
  };
  void start_one_point_lanes(double dt);
  void return_by_material(double dt);
  void finish_on_lanes(double dt);

  std::array<Lane, capacity> lanes_;
  PolarRotationBatch rotations_;
  CorotationBatch corotations_;
  JohnsonCookReturnBatch returns_;
  UpdateLanes steps_;
  int size_ = 0;
};

}  // namespace impact
