#include "pointdriver/driver/driver.hpp"
#include "pointdriver/format/text_format.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "models/failure/tepla.hpp"
#include "pointdriver/driver/replay.hpp"

namespace impact::pointdriver {

namespace {

Mat3 cross_matrix(const Vec3& w) {
  Mat3 m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

Mat3 rotation(const Vec3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

/// Step sizes of a leg, one at a time (a leg may have 1e9 steps: no array of them): uniform, or
/// geometric with ratio `growth`; the last one closes the leg exactly so that legs end on their
/// prescribed time.
class StepSizes {
 public:
  explicit StepSizes(const Leg& leg)
      : steps_(leg.steps),
        duration_(leg.duration),
        g_(leg.growth),
        h0_(g_ == 1.0 ? leg.duration / leg.steps
                      : leg.duration * (g_ - 1.0) / (std::pow(g_, leg.steps) - 1.0)) {}
  bool done() const { return k_ >= steps_; }
  double next() {
    const double h = k_ + 1 == steps_ ? duration_ - t_ : h0_ * std::pow(g_, k_);
    t_ += h;
    ++k_;
    return h;
  }

 private:
  int steps_;
  double duration_, g_, h0_;
  int k_ = 0;
  double t_ = 0.0;
};

/// What one (possibly cut-back) step produced.
struct Advance {
  PointState state;
  Mat3 F_path, Q, L_path, L_lab;
  StepReport report;
  FailureCause failure = FailureCause::none;
  double stress_work = 0.0, dissipated = 0.0;
  int iterations = 0, jacobians = 0, substeps = 0;
  std::string error;
};

class LegRunner {
 public:
  LegRunner(const Path& path, const Leg& leg, const ControlPlan& plan, const ElasticPlastic& model,
            const ElasticPlastic& keep_stress_twin, double leg_start_temperature)
      : path_(path),
        leg_(leg),
        plan_(plan),
        model_(model),
        twin_(keep_stress_twin),
        T_start_(leg_start_temperature) {
    rate_axis_ = leg.rotation_axis;
    rate_ = leg.rotation_angle / leg.duration;
  }

  /// Advances from (s0, F_path0, Q0) at leg time t0 over dt; halves on failure up to the
  /// cut-back limit. Returns false with `a.error` set when even the smallest piece fails.
  bool advance(const PointState& s0, const Mat3& F_path0, const Mat3& Q0, double t0, double dt,
               const Mat3& guess, int depth, Advance& a) const {
    StepContext ctx;
    const bool erodes = model_.params().erosion == Erosion::allow_no_tension ||
                        model_.params().erosion == Erosion::zero_stress;
    ctx.model = erodes && !s0.failed ? &twin_ : &model_;
    ctx.eroding_model = erodes && !s0.failed ? &model_ : nullptr;
    ctx.settings = &path_.solver;
    ctx.Q_mid = rotation(rate_axis_, rate_ * dt / 2) * Q0;
    ctx.Q_new = rotation(rate_axis_, rate_ * dt) * Q0;
    ctx.spin = cross_matrix(rate_ * rate_axis_);
    PointState start = s0;
    if (leg_.thermal == Thermal::prescribed) start.temperature = temperature_at(t0 + dt / 2);
    const StepSolution sol =
        solve_step(plan_, ctx, start, F_path0, dt, (t0 + dt) / leg_.duration, guess, &jacobian_);
    a.iterations += sol.iterations;
    a.jacobians += sol.jacobian_evaluations;
    if (sol.converged) {
      a.state = sol.state;
      if (leg_.thermal == Thermal::prescribed) a.state.temperature = temperature_at(t0 + dt);
      a.F_path = sol.F_path;
      a.Q = ctx.Q_new;
      a.L_path = sol.L_path;
      a.L_lab = ctx.spin + ctx.Q_mid * sol.L_path * ctx.Q_mid.transpose();
      a.report = sol.report;
      if (a.failure == FailureCause::none) a.failure = sol.report.failure;
      const double J0 = s0.F.determinant(), J1 = a.state.F.determinant();
      a.stress_work +=
          ddot(0.5 * (s0.stress + a.state.stress), sym(a.L_lab)) * 0.5 * (J0 + J1) * dt;
      a.dissipated += sol.report.plastic_work * J1;
      a.substeps += 1;
      return true;
    }
    if (depth >= path_.solver.max_cutbacks) {
      a.error = sol.message + " (after " + std::to_string(depth) +
                " cut-backs, dt = " + format_number(dt) + " s)";
      return false;
    }
    if (!advance(s0, F_path0, Q0, t0, dt / 2, guess, depth + 1, a)) return false;
    const PointState mid = a.state;
    const Mat3 F_mid = a.F_path, Q_mid = a.Q, L_mid = a.L_path;
    return advance(mid, F_mid, Q_mid, t0 + dt / 2, dt / 2, L_mid, depth + 1, a);
  }

  double temperature_at(double t) const {
    return T_start_ + (leg_.end_temperature - T_start_) * t / leg_.duration;
  }
  double rotation_rate() const { return rate_; }

 private:
  const Path& path_;
  const Leg& leg_;
  const ControlPlan& plan_;
  const ElasticPlastic& model_;
  const ElasticPlastic& twin_;
  double T_start_;
  mutable Eigen::MatrixXd jacobian_;  // the last Newton matrix, reused by the next step
  Vec3 rate_axis_;
  double rate_ = 0.0;
};

Row make_row(double time, int step, int leg, const PointState& s, const Mat3& Q, const Mat3& L,
             const ElasticPlasticParams& p) {
  Row r;
  r.time = time;
  r.step = step;
  r.leg = leg;
  r.F = s.F;
  r.L = L;
  r.Q = Q;
  r.state = s;
  r.stress_path = Q.transpose() * s.stress * Q;
  // A neo_hookean solid has no melting temperature (and no failure): its indicators stay 0.
  if (p.type == ConstitutiveType::neo_hookean) return r;
  r.tepla_indicator = tepla_indicator(s.porosity, p.tepla.critical_porosity, s.damage);
  r.melting_indicator =
      s.temperature / melting_temperature(p.melting, p.melt_temperature, 1.0 / s.F.determinant());
  return r;
}

}  // namespace

RunResult run_path(const Path& path, const RowSink& sink) {
  return run_path(path, path.material.model, sink);
}

RunResult run_path(const Path& path, const ElasticPlastic& model, const RowSink& sink) {
  // The path decides heating per leg: one model with eq. 8 on, one with it off.
  ElasticPlasticParams heated = model.params(), held = model.params();
  heated.heating.enabled = true;
  held.heating.enabled = false;
  const ElasticPlastic adiabatic(heated), isothermal(held);
  // KeepStress twins for the Newton iterations of a point that may fail (StepContext).
  heated.erosion = held.erosion = Erosion::keep_stress;
  const ElasticPlastic adiabatic_twin(heated), isothermal_twin(held);
  const ElasticPlasticParams& params = model.params();

  RunResult result;
  PointState s = path.initial_state;
  Mat3 Q = path.initial_frame;
  Mat3 F_path = Q.transpose() * s.F;
  Mat3 guess = Mat3::Zero();
  double t = 0.0, stress_work = 0.0, dissipated = 0.0;
  int step = 0;
  bool frozen = false;
  sink(make_row(0.0, 0, 0, s, Q, Mat3::Zero(), params));

  for (std::size_t li = 0; li < path.legs.size(); ++li) {
    const Leg& leg = path.legs[li];
    if (leg.start_temperature) s.temperature = *leg.start_temperature;
    const ControlPlan plan = make_plan(leg, F_path, Q.transpose() * s.stress * Q);
    const ElasticPlastic& m = leg.thermal == Thermal::adiabatic ? adiabatic : isothermal;
    const ElasticPlastic& twin =
        leg.thermal == Thermal::adiabatic ? adiabatic_twin : isothermal_twin;
    const LegRunner runner(path, leg, plan, m, twin, s.temperature);
    double t_leg = 0.0;
    for (StepSizes sizes(leg); !sizes.done();) {
      const double dt = sizes.next();
      ++step;
      Advance a;
      if (frozen) {
        a.state = s;
        a.F_path = F_path;
        a.Q = Q;
        a.L_path = a.L_lab = Mat3::Zero();
        a.substeps = 0;
      } else if (!runner.advance(s, F_path, Q, t_leg, dt, guess, 0, a)) {
        result.error = "leg " + std::to_string(li) + " (" + leg.label + "), step " +
                       std::to_string(step) + ", t = " + format_number(t) + " s: " + a.error;
        result.replay = replay_path(path, leg, plan, s, Q, t_leg, dt,
                                    runner.temperature_at(t_leg + dt), runner.rotation_rate());
        result.steps = step - 1;
        result.end_time = t;
        return result;
      }
      t += dt;
      t_leg += dt;
      stress_work += a.stress_work;
      dissipated += a.dissipated;
      s = a.state;
      F_path = a.F_path;
      Q = a.Q;
      if (!frozen) guess = a.L_path;
      Row row = make_row(t, step, static_cast<int>(li), s, Q, a.L_lab, params);
      row.iterations = a.iterations;
      row.jacobian_evaluations = a.jacobians;
      row.substeps = a.substeps;
      row.stress_work = stress_work;
      row.dissipated_energy = dissipated;
      row.drucker_checked = params.erosion != Erosion::none &&
                            params.stability.check != StabilityCheck::none && a.report.plastic;
      row.drucker_indicator = a.report.drucker_indicator;
      row.becker_indicator = a.report.becker_indicator;
      if (a.failure != FailureCause::none && result.failure == FailureCause::none) {
        row.failure = a.failure;
        result.failure = a.failure;
        result.failure_time = t;
      }
      sink(row);
      if (row.failure != FailureCause::none) {
        if (path.failure_policy == FailurePolicy::stop) {
          result.completed = true;
          result.steps = step;
          result.end_time = t;
          return result;
        }
        if (path.failure_policy == FailurePolicy::freeze) frozen = true;
      }
    }
  }
  result.completed = true;
  result.steps = step;
  result.end_time = t;
  return result;
}

}  // namespace impact::pointdriver
