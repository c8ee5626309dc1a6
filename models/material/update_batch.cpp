#include "models/material/update_batch.hpp"

#include "models/kinematics/polar_decomposition.hpp"

namespace impact {

int UpdateBatch::add(const ElasticPlastic& model, const PointState& s0, const Mat3& L,
                     const Mat3& F1, PointState& s1) {
  const int k = size_++;
  Lane& lane = lanes_[k];
  lane.model = &model;
  lane.s0 = &s0;
  lane.s1 = &s1;
  lane.L = L;
  lane.F1 = F1;
  return k;
}

void UpdateBatch::run(double dt) {
  // The polar rotations of F1 on the lanes (green_naghdi points with det F1 > 0; the others get
  // the identity, a harmless input), then each point's own kinematics and trial stress.
  bool polar[capacity] = {};
  for (int k = 0; k < capacity; ++k) {
    const Lane& lane = lanes_[k];
    polar[k] = k < size_ && lane.model->params().objective_rate == ObjectiveRate::green_naghdi &&
               lane.F1.determinant() > 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double identity = i == j ? 1.0 : 0.0;
        lane::set(rotations_.F.a[i][j], k, polar[k] ? lane.F1(i, j) : identity);
        lane::set(rotations_.guess.a[i][j], k, polar[k] ? lane.s0->R(i, j) : identity);
      }
  }
  polar_rotation_batch(rotations_);
  // Each lane's R_new (the cold start where the warm one did not converge, as for one point), then
  // the un-rotations of its stress and D on the lanes.
  Mat3 R_new[capacity];
  for (int k = 0; k < capacity; ++k) {
    const Lane& lane = lanes_[k];
    Mat3 R_old = Mat3::Identity(), stress = Mat3::Zero(), D = Mat3::Zero();
    R_new[k] = Mat3::Identity();
    if (polar[k]) {
      if (lane::get(rotations_.out.converged, k) != 0) {
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) R_new[k](i, j) = lane::get(rotations_.out.R.a[i][j], k);
      } else {
        R_new[k] = polar_rotation(lane.F1, lane.s0->R);
      }
      R_old = lane.s0->R;
      stress = lane.s0->stress;
      D = sym(lane.L);
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        lane::set(corotations_.R_old.a[i][j], k, R_old(i, j));
        lane::set(corotations_.R_new.a[i][j], k, R_new[k](i, j));
        lane::set(corotations_.stress.a[i][j], k, stress(i, j));
        lane::set(corotations_.D.a[i][j], k, D(i, j));
      }
  }
  corotation_batch(corotations_);
  for (int k = 0; k < size_; ++k) {
    Lane& lane = lanes_[k];
    Corotated c;
    if (polar[k]) {
      const auto lane_matrix = [k](const LaneMat3<lane::Vec>& m) {
        Mat3 A;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) A(i, j) = lane::get(m.a[i][j], k);
        return A;
      };
      if (lane::get(corotations_.out.wide, k) != 0)  // beyond ~151 degrees: as for one point
        c = corotate(lane.s0->R, R_new[k], lane.s0->stress, sym(lane.L));
      else
        c = {R_new[k], lane_matrix(corotations_.out.R_mid), lane_matrix(corotations_.out.stress),
             lane_matrix(corotations_.out.D)};
    }
    lane.started = lane.model->begin_update(*lane.s0, lane.L, lane.F1, dt, *lane.s1, lane.trial,
                                            lane.report, polar[k] ? &c : nullptr);
  }

  // Lanes that need no Newton return (molten, the 2004 return) take the one-point path.
  bool pending[capacity] = {};
  for (int k = 0; k < size_; ++k) {
    Lane& lane = lanes_[k];
    pending[k] = lane.started && lane.trial.batched;
    if (lane.started && !lane.trial.batched)
      lane.result = lane.model->unbatched_return(*lane.s0, lane.trial, dt);
  }
  // One kernel call per material in the block (one, unless the block straddles two bodies): the
  // flow-stress parameters are the kernel's, the lanes' states its vectors.
  for (int first = 0; first < size_; ++first) {
    if (!pending[first]) continue;
    const ElasticPlastic& model = *lanes_[first].model;
    for (int k = 0; k < capacity; ++k) {
      const bool mine = k < size_ && pending[k] && lanes_[k].model == &model;
      if (!mine) {
        returns_.clear(k);
        continue;
      }
      model.to_lane(*lanes_[k].s0, lanes_[k].trial, dt, returns_.lanes, k);
      lane::set(returns_.thermal_factor, k, lanes_[k].trial.thermal.factor);
      lane::set(returns_.thermal_d_factor, k, lanes_[k].trial.thermal.d_factor);
    }
    johnson_cook_return(model.params().flow_stress, model.params().return_tolerance, returns_);
    for (int k = 0; k < size_; ++k) {
      if (!pending[k] || lanes_[k].model != &model) continue;
      lanes_[k].result = finish_return(lanes_[k].trial.s_trial, returns_.lanes, k);
      pending[k] = false;
    }
  }
}

StepReport UpdateBatch::finish(int k, double dt, PointState& s1) {
  Lane& lane = lanes_[k];
  if (lane.started)
    lane.model->finish_update(*lane.s0, lane.trial, lane.result, dt, s1, lane.report);
  return lane.report;
}

}  // namespace impact
