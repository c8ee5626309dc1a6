#include "models/material/update_batch.hpp"

#include "models/kinematics/polar_decomposition.hpp"

namespace impact {

namespace {

template <class T>
void set_lane(LaneMat3<lane::Vec>& m, int k, const T& A) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.a[i][j][k] = A(i, j);
}

Mat3 lane_matrix(const LaneMat3<lane::Vec>& m, int k) {
  Mat3 A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = m.a[i][j][k];
  return A;
}

}  // namespace

int UpdateBatch::add(const ElasticPlastic& model, const PointState& s0, const Mat3& L,
                     const Mat3& F1, PointState& s1) {
  const int k = size_++;
  Lane& lane = lanes_[k];
  lane.model = &model;
  lane.s0 = &s0;
  lane.s1 = &s1;
  lane.L = &L;
  lane.F1 = &F1;
  lane.started = false;
  lane.report = StepReport{};
  const ElasticPlasticParams& p = model.params();
  const double J1 = lane_algebra::determinant(to_lanes(F1));
  lane.polar = !model.hyperelastic() && p.objective_rate == ObjectiveRate::green_naghdi && J1 > 0.0;
  // The one combination with vector kernels (speed); the catalogues' other models take the
  // one-point steps (docs/extending.md, "Where a model is still named").
  lane.lanes = lane.polar && p.return_algorithm == ReturnAlgorithm::newton && !model.molten(s0) &&
               std::holds_alternative<DefaultHypoParams>(p.equation_of_state) &&
               std::holds_alternative<JohnsonCookParams>(p.flow_stress) &&
               is_constant(p.shear_modulus_model);
  // The rotations' inputs; a lane without them gets the identity and zeros, harmless inputs.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double identity = i == j ? 1.0 : 0.0;
      rotations_.F.a[i][j][k] = lane.polar ? F1(i, j) : identity;
      rotations_.guess.a[i][j][k] = lane.polar ? s0.R(i, j) : identity;
      corotations_.R_old.a[i][j][k] = lane.polar ? s0.R(i, j) : identity;
      corotations_.stress.a[i][j][k] = lane.polar ? s0.stress(i, j) : 0.0;
      corotations_.D.a[i][j][k] = lane.polar ? 0.5 * (L(i, j) + L(j, i)) : 0.0;  // sym L
    }
  const MaterialLanes<double> m = model.material_lanes<double>();
  steps_.material.density[k] = m.density;
  steps_.material.shear_modulus[k] = m.shear_modulus;
  steps_.material.hypo_bulk_modulus[k] = lane.lanes ? m.hypo_bulk_modulus : 1.0;
  steps_.material.heating[k] = m.heating;
  steps_.material.taylor_quinney[k] = m.taylor_quinney;
  steps_.material.specific_heat[k] = m.specific_heat;
  steps_.J_n[k] = lane.lanes ? lane_algebra::determinant(to_lanes(s0.F)) : 1.0;
  steps_.J_1[k] = lane.lanes ? J1 : 1.0;
  steps_.T_n[k] = s0.temperature;
  steps_.e_n[k] = s0.internal_energy;
  if (lane.lanes)
    lane.trial.thermal =
        johnson_cook_thermal(std::get<JohnsonCookParams>(p.flow_stress), s0.temperature);
  return k;
}

void UpdateBatch::run(double dt) {
  // Lanes beyond the batch's points: identities, zeros and unit moduli.
  for (int k = size_; k < capacity; ++k) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double identity = i == j ? 1.0 : 0.0;
        rotations_.F.a[i][j][k] = rotations_.guess.a[i][j][k] = identity;
        corotations_.R_old.a[i][j][k] = identity;
        corotations_.stress.a[i][j][k] = corotations_.D.a[i][j][k] = 0.0;
      }
    steps_.material.density[k] = steps_.material.shear_modulus[k] = 1.0;
    steps_.material.hypo_bulk_modulus[k] = steps_.material.specific_heat[k] = 1.0;
    steps_.J_n[k] = steps_.J_1[k] = 1.0;
  }
  for (int k = 0; k < capacity; ++k) steps_.dt[k] = dt;

  // The polar rotations of F1 (a lane whose warm start did not converge takes the cold
  // decomposition, as one point does), then the un-rotations of the stress and D.
  polar_rotation_batch(rotations_);
  corotations_.R_new = rotations_.out.R;
  for (int k = 0; k < size_; ++k) {
    const Lane& lane = lanes_[k];
    if (lane.polar && rotations_.out.converged[k] == 0)
      set_lane(corotations_.R_new, k, polar_rotation(*lane.F1, lane.s0->R));
  }
  corotation_batch(corotations_);
  for (int k = 0; k < size_; ++k) {  // beyond ~151 degrees: as for one point
    const Lane& lane = lanes_[k];
    if (!lane.polar || corotations_.out.wide[k] == 0) continue;
    const Corotated c =
        corotate(lane.s0->R, lane_matrix(corotations_.R_new, k), lane.s0->stress, sym(*lane.L));
    set_lane(corotations_.out.R_mid, k, c.R_mid);
    set_lane(corotations_.out.stress, k, c.stress);
    set_lane(corotations_.out.D, k, c.D);
  }
  trial_kernel(corotations_.out, steps_);
  start_one_point_lanes(dt);
  return_by_material(dt);
  finish_on_lanes(dt);
}

void UpdateBatch::start_one_point_lanes(double dt) {
  for (int k = 0; k < size_; ++k) {
    Lane& lane = lanes_[k];
    if (lane.lanes) {
      lane.started = true;
      lane.trial.q_trial = steps_.trial.q_trial[k];
      lane.trial.shear_modulus = steps_.material.shear_modulus[k];  // mu0: constant on the lanes
      lane.trial.batched = true;
      continue;
    }
    Corotated c;
    if (lane.polar)
      c = {lane_matrix(corotations_.R_new, k), lane_matrix(corotations_.out.R_mid, k),
           lane_matrix(corotations_.out.stress, k), lane_matrix(corotations_.out.D, k)};
    lane.started = lane.model->begin_update(*lane.s0, *lane.L, *lane.F1, dt, *lane.s1, lane.trial,
                                            lane.report, lane.polar ? &c : nullptr);
    // Lanes that need no Newton return (molten, the 2004 return) take the one-point return.
    if (lane.started && !lane.trial.batched)
      lane.result = lane.model->unbatched_return(*lane.s0, lane.trial, dt);
  }
}

void UpdateBatch::return_by_material(double dt) {
  bool pending[capacity] = {};
  for (int k = 0; k < size_; ++k) pending[k] = lanes_[k].started && lanes_[k].trial.batched;
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
      returns_.thermal_factor[k] = lanes_[k].trial.thermal.factor;
      returns_.thermal_d_factor[k] = lanes_[k].trial.thermal.d_factor;
    }
    johnson_cook_return_batch(std::get<JohnsonCookParams>(model.params().flow_stress),
                              model.params().return_tolerance, returns_);
    const ReturnValues<lane::Vec>& b = returns_.lanes;
    for (int k = 0; k < size_; ++k) {
      Lane& lane = lanes_[k];
      if (!pending[k] || lane.model != &model) continue;
      pending[k] = false;
      if (!lane.lanes) {
        lane.result = finish_return(lane.trial.s_trial, b, k);
        continue;
      }
      // The deviator is on the lanes (finish_kernel); a plastic lane also keeps it here, the same
      // expression, for the stability check of damage_and_failure.
      const bool plastic = b.plastic[k] != 0;
      if (plastic) {
        lane.result = finish_return(lane_matrix(steps_.trial.s_trial, k), b, k);
      } else {
        lane.result.plastic = false;
        lane.result.converged = b.converged[k] != 0;
        lane.result.iterations = static_cast<int>(b.iterations[k]);
        lane.result.delta_plastic_strain = b.increment[k];
        lane.result.flow = FlowStress{b.flow.value[k], b.flow.d_plastic_strain[k], b.flow.d_rate[k],
                                      b.flow.d_temperature[k]};
      }
      steps_.plastic[k] = plastic ? 1.0 : 0.0;
      steps_.d_ep[k] = lane.result.delta_plastic_strain;
      steps_.flow[k] = lane.result.flow.value;
    }
  }
}

void UpdateBatch::finish_on_lanes(double dt) {
  bool any = false;
  for (int k = 0; k < size_; ++k) any = any || lanes_[k].lanes;
  if (!any) return;
  for (int k = 0; k < capacity; ++k)
    if (k >= size_ || !lanes_[k].lanes) steps_.plastic[k] = steps_.d_ep[k] = steps_.flow[k] = 0.0;
  finish_kernel(corotations_.out, steps_);
  // What the lanes cannot do: the state's scalars, and damage, failure and erosion where the step
  // needs them (ElasticPlastic::damage_and_failure, one point at a time).
  for (int k = 0; k < size_; ++k) {
    Lane& lane = lanes_[k];
    if (!lane.lanes) continue;
    const PointState& s0 = *lane.s0;
    PointState& s1 = *lane.s1;
    StepReport& report = lane.report;
    const ReturnResult& r = lane.result;
    s1 = s0;
    s1.F = *lane.F1;
    s1.R = lane_matrix(corotations_.R_new, k);
    s1.melted = false;
    report.return_iterations = r.iterations;
    if (!r.converged) report.status = UpdateStatus::return_mapping_not_converged;
    report.plastic = r.plastic;
    s1.plastic_strain = s0.plastic_strain + r.delta_plastic_strain;
    s1.plastic_strain_rate = r.delta_plastic_strain / dt;
    report.plastic_work = steps_.heating.plastic_work[k];
    report.temperature_rise = steps_.heating.temperature_rise[k];
    s1.temperature = steps_.heating.temperature[k];
    s1.internal_energy = steps_.pressure.internal_energy[k];
    if (r.plastic || r.delta_plastic_strain > 0.0 || s0.failed) {
      const Mat3 stress = lane.model->damage_and_failure(
          s0, lane_matrix(corotations_.out.D, k), r, dt, steps_.trial.rho1[k],
          steps_.material.shear_modulus[k], lane_matrix(steps_.stress, k), s1, report);
      set_lane(steps_.stress, k, stress);
    }
  }
  rotate_back_kernel(corotations_.R_new, steps_);
  for (int k = 0; k < size_; ++k) {
    Lane& lane = lanes_[k];
    if (!lane.lanes) continue;
    lane.s1->stress = lane_matrix(steps_.stress, k);
    lane.model->check_end_state(*lane.s1, steps_.trial.rho1[k], steps_.wave_speed[k], lane.report);
  }
}

StepReport UpdateBatch::finish(int k, double dt, PointState& s1) {
  Lane& lane = lanes_[k];
  if (lane.started && !lane.lanes)
    lane.model->finish_update(*lane.s0, lane.trial, lane.result, dt, s1, lane.report);
  return lane.report;
}

}  // namespace impact
