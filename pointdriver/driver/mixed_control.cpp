#include "pointdriver/driver/mixed_control.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <limits>

#include "models/kinematics/deformation_gradient.hpp"

namespace impact::pointdriver {

namespace {

Mat3 unit(int i, int j) {
  Mat3 e = Mat3::Zero();
  e(i, j) = 1.0;
  return e;
}

using Vector = Eigen::VectorXd;

/// One evaluation of the material at trial unknowns u.
struct Trial {
  bool ok = false;
  Vector residual;  ///< raw: Pa for stress rows, - for F rows
  Mat3 L_path, F_path;
  PointState state;
  StepReport report;
};

class StepProblem {
 public:
  StepProblem(const ControlPlan& plan, const StepContext& ctx, const PointState& s0,
              const Mat3& F_path0, double dt, double s_end)
      : plan_(plan), ctx_(ctx), s0_(s0), F0_(F_path0), dt_(dt), s_end_(s_end) {
    const auto& p = ctx.model->params();
    stress_scale_ = p.bulk_modulus + 4.0 / 3.0 * p.shear_modulus;
  }

  std::size_t size() const { return plan_.generators.size(); }

  Trial evaluate(const Vector& u) const { return evaluate(u, *ctx_.model); }

  Trial evaluate(const Vector& u, const ElasticPlastic& model) const {
    Trial t;
    t.L_path = plan_.L_fixed;
    for (std::size_t m = 0; m < size(); ++m) t.L_path += u(m) * plan_.generators[m];
    t.F_path = advance_deformation_gradient(F0_, t.L_path, dt_, FIntegration::exponential);
    // Superposed rotation (Brannon-style): F* = Q F, L* = Omega + Q L Q^T (exact in time).
    const Mat3 L_lab = ctx_.spin + ctx_.Q_mid * t.L_path * ctx_.Q_mid.transpose();
    const Mat3 F_lab = ctx_.Q_new * t.F_path;
    t.report = model.update(s0_, L_lab, F_lab, dt_, t.state);
    t.ok = t.report.status == UpdateStatus::ok;
    const Mat3 stress = ctx_.Q_new.transpose() * t.state.stress * ctx_.Q_new;
    t.residual.resize(static_cast<Eigen::Index>(plan_.equations.size()));
    for (std::size_t e = 0; e < plan_.equations.size(); ++e) {
      const ControlEquation& q = plan_.equations[e];
      double r = 0.0;
      switch (q.kind) {
        case ControlEquation::Kind::stress:
          r = stress(q.i, q.j) - q.target(s_end_);
          break;
        case ControlEquation::Kind::stress_ratio:
          r = stress(q.i, q.j) - q.ratio * stress(q.oi, q.oj);
          break;
        case ControlEquation::Kind::deformation:
          r = t.F_path(q.i, q.j) - q.target(s_end_);
          break;
      }
      t.residual(static_cast<Eigen::Index>(e)) = r;
    }
    if (!t.residual.allFinite()) t.ok = false;
    return t;
  }

  /// Residual in strain units, for the Newton norm and the line search.
  Vector scaled(const Vector& r) const {
    Vector s = r;
    for (std::size_t e = 0; e < plan_.equations.size(); ++e) {
      if (plan_.equations[e].kind != ControlEquation::Kind::deformation) {
        s(static_cast<Eigen::Index>(e)) /= stress_scale_;
      }
    }
    return s;
  }

  bool converged(const Trial& t, double& max_stress, double& max_strain) const {
    const Vector& r = t.residual;
    max_stress = max_strain = 0.0;
    bool ok = true;
    const double stress_tol =
        ctx_.settings->stress_tolerance +
        ctx_.settings->relative_stress_tolerance * t.state.stress.cwiseAbs().maxCoeff();
    for (std::size_t e = 0; e < plan_.equations.size(); ++e) {
      const double a = std::abs(r(static_cast<Eigen::Index>(e)));
      if (plan_.equations[e].kind == ControlEquation::Kind::deformation) {
        max_strain = std::max(max_strain, a);
        ok = ok && a <= ctx_.settings->strain_tolerance;
      } else {
        max_stress = std::max(max_stress, a);
        ok = ok && a <= stress_tol;
      }
    }
    return ok;
  }

  /// d(scaled residual)/du by central differences; a strain perturbation of 1e-7 per unknown.
  Eigen::MatrixXd central_difference_jacobian(const Vector& u, bool& ok) const {
    const auto n = static_cast<Eigen::Index>(size());
    Eigen::MatrixXd J(n, n);
    ok = true;
    for (Eigen::Index m = 0; m < n; ++m) {
      const double h = 1e-7 / dt_;
      Vector up = u, um = u;
      up(m) += h;
      um(m) -= h;
      const Trial a = evaluate(up), b = evaluate(um);
      ok = ok && a.ok && b.ok;
      J.col(m) = (scaled(a.residual) - scaled(b.residual)) / (2.0 * h);
    }
    return J;
  }

  /// The isotropic elastic stiffness and the linearised F map, in the path frame.
  Eigen::MatrixXd elastic_jacobian() const {
    const auto& p = ctx_.model->params();
    const double lambda = p.bulk_modulus - 2.0 / 3.0 * p.shear_modulus;
    const auto n = static_cast<Eigen::Index>(size());
    Eigen::MatrixXd J(static_cast<Eigen::Index>(plan_.equations.size()), n);
    for (Eigen::Index m = 0; m < n; ++m) {
      const Mat3& G = plan_.generators[static_cast<std::size_t>(m)];
      const Mat3 dstress =
          (lambda * G.trace() * Mat3::Identity() + p.shear_modulus * (G + G.transpose())) * dt_;
      const Mat3 dF = G * F0_ * dt_;
      Vector col(static_cast<Eigen::Index>(plan_.equations.size()));
      for (std::size_t e = 0; e < plan_.equations.size(); ++e) {
        const ControlEquation& q = plan_.equations[e];
        col(static_cast<Eigen::Index>(e)) =
            q.kind == ControlEquation::Kind::deformation ? dF(q.i, q.j)
            : q.kind == ControlEquation::Kind::stress
                ? dstress(q.i, q.j) / stress_scale_
                : (dstress(q.i, q.j) - q.ratio * dstress(q.oi, q.oj)) / stress_scale_;
      }
      J.col(m) = col;
    }
    return J;
  }

 private:
  const ControlPlan& plan_;
  const StepContext& ctx_;
  const PointState& s0_;
  Mat3 F0_;
  double dt_, s_end_;
  double stress_scale_ = 1.0;
};

}  // namespace

double ControlEquation::target(double s) const {
  if (kind == Kind::deformation && i == j && start > 0.0 && end > 0.0) {
    return start * std::pow(end / start, s);  // constant stretch rate: exp of a constant L_ii
  }
  return start + (end - start) * s;
}

ControlPlan make_plan(const Leg& leg, const Mat3& F_start, const Mat3& stress_start) {
  ControlPlan plan;
  const auto& L = leg.velocity_gradient;
  const auto& F = leg.deformation_gradient;
  const bool any_stress = [&] {
    for (int c = 0; c < 6; ++c) {
      if (leg.stress[c] || leg.stress_ratio[c]) return true;
    }
    return false;
  }();
  plan.all_deformation = !any_stress;
  for (int k = 0; k < 9; ++k) plan.all_deformation = plan.all_deformation && F[k].has_value();
  if (plan.all_deformation) {
    Mat3 F_end;
    for (int k = 0; k < 9; ++k) F_end(k / 3, k % 3) = *F[k];
    plan.L_fixed = constant_velocity_gradient(F_start, F_end, leg.duration);
    return plan;
  }

  const auto kinematic = [&](int i, int j) {
    const int k = 3 * i + j;
    if (L[k]) {
      plan.L_fixed(i, j) = *L[k];
    } else if (F[k]) {
      plan.generators.push_back(unit(i, j));
      ControlEquation q;
      q.kind = ControlEquation::Kind::deformation;
      q.i = i, q.j = j, q.start = F_start(i, j), q.end = *F[k];
      plan.equations.push_back(q);
    }
  };
  for (int c = 0; c < 6; ++c) {
    const auto [i, j] = stress_index[c];
    const int ij = 3 * i + j, ji = 3 * j + i;
    const bool kin_ij = L[ij] || F[ij];
    const bool kin_ji = L[ji] || F[ji];
    kinematic(i, j);
    if (i != j) kinematic(j, i);
    // The stress equation of this component, unless it is fully kinematic.
    if (i == j ? kin_ij : (kin_ij && kin_ji)) continue;
    if (i == j || kin_ij) {
      plan.generators.push_back(unit(kin_ij ? j : i, kin_ij ? i : j));
    } else if (kin_ji) {
      plan.generators.push_back(unit(i, j));
    } else {
      plan.generators.push_back(unit(i, j) + unit(j, i));  // no spin
    }
    ControlEquation q;
    q.i = i, q.j = j;
    if (leg.stress_ratio[c]) {
      q.kind = ControlEquation::Kind::stress_ratio;
      q.ratio = *leg.stress_ratio[c];
      q.oi = stress_index[leg.ratio_of][0], q.oj = stress_index[leg.ratio_of][1];
    } else {
      q.kind = ControlEquation::Kind::stress;
      // Given: ramped from the leg's start. Not given: stress-free throughout (MTest's rule).
      q.start = leg.stress[c] ? stress_start(i, j) : 0.0;
      q.end = leg.stress[c].value_or(0.0);
    }
    plan.equations.push_back(q);
  }
  return plan;
}

StepSolution solve_step(const ControlPlan& plan, const StepContext& ctx, const PointState& s0,
                        const Mat3& F_path0, double dt, double s_end, const Mat3& guess,
                        Eigen::MatrixXd* jacobian) {
  StepProblem problem(plan, ctx, s0, F_path0, dt, s_end);
  StepSolution out;
  const auto n = static_cast<Eigen::Index>(problem.size());
  Vector u(n);
  for (Eigen::Index m = 0; m < n; ++m) {
    // Start from the guess projected on each unknown direction (|G|^2 = 1 or 2).
    const Mat3& G = plan.generators[static_cast<std::size_t>(m)];
    u(m) = ddot(guess, G) / ddot(G, G);
  }
  Trial t = problem.evaluate(u);
  // The previous step's rate is a close guess under steady loading; after a rate jump (1e3 to
  // 1e-3 /s) it is a strain of L dt = 120, far outside a stiff law's range (a neo-Hookean solid's
  // stress at J = 1e-104 made the Newton matrix singular). Start from the unknowns at rest then,
  // when that is the smaller residual.
  if (n > 0 && u.squaredNorm() > 0.0) {
    const Trial rest = problem.evaluate(Vector::Zero(n));
    if (rest.ok &&
        (!t.ok || problem.scaled(rest.residual).norm() < problem.scaled(t.residual).norm())) {
      u.setZero();
      t = rest;
    }
  }
  const auto finish = [&](const Trial& trial, bool converged, std::string message) {
    // The failing step: apply the real (eroding) model once at the converged unknowns.
    const bool erode =
        converged && ctx.eroding_model != nullptr && trial.state.failed && !s0.failed;
    const Trial eroded = erode ? problem.evaluate(u, *ctx.eroding_model) : Trial{};
    const Trial& tr = erode ? eroded : trial;
    out.converged = converged;
    out.L_path = tr.L_path;
    out.F_path = tr.F_path;
    out.state = tr.state;
    out.report = tr.report;
    out.message = std::move(message);
    return out;
  };
  if (n == 0) {
    return finish(t, t.ok, t.ok ? "" : std::string(to_string(t.report.status)));
  }
  const SolverSettings& st = *ctx.settings;
  bool fresh_needed = false;
  for (int it = 0;; ++it) {
    if (t.ok && problem.converged(t, out.max_stress_residual, out.max_strain_residual)) {
      out.iterations = it;
      return finish(t, true, "");
    }
    if (!t.ok) {
      return finish(t, false, "material update failed: " + std::string(to_string(t.report.status)));
    }
    if (it == st.max_iterations) {
      out.iterations = it;
      char buf[160];
      std::snprintf(buf, sizeof buf,
                    "Newton did not converge in %d iterations (largest stress residual %.3g Pa, "
                    "strain residual %.3g)",
                    it, out.max_stress_residual, out.max_strain_residual);
      return finish(t, false, buf);
    }
    // The Jacobian: reused from the previous step while it keeps Newton contracting (a chord
    // iteration, MTest's stiffness-update policy), recomputed when it does not.
    const Vector r = problem.scaled(t.residual);
    const bool reuse =
        jacobian != nullptr && !fresh_needed && jacobian->rows() == n && jacobian->cols() == n;
    Eigen::MatrixXd J;
    bool jac_ok = true;
    if (reuse) {
      J = *jacobian;
    } else {
      J = st.jacobian == SolverSettings::Jacobian::elastic
              ? problem.elastic_jacobian()
              : problem.central_difference_jacobian(u, jac_ok);
      out.jacobian_evaluations += 1;
      if (jacobian != nullptr) *jacobian = J;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
    if (!jac_ok || qr.rank() < n) {
      out.iterations = it;
      return finish(t, false, "singular mixed-control Jacobian");
    }
    const Vector du = -qr.solve(r);
    // Backtracking line search on |r|: halve the step until the scaled residual decreases.
    double alpha = 1.0;
    Trial next;
    for (int ls = 0; ls < 12; ++ls, alpha *= 0.5) {
      next = problem.evaluate(u + alpha * du);
      if (next.ok && problem.scaled(next.residual).norm() < r.norm()) break;
    }
    const bool decreased = next.ok && problem.scaled(next.residual).norm() < r.norm();
    if (reuse && (!decreased || problem.scaled(next.residual).norm() > 0.1 * r.norm())) {
      fresh_needed = true;  // the old Jacobian no longer contracts well: recompute it
      if (!decreased) continue;
    }
    if (!next.ok || !(problem.scaled(next.residual).norm() < r.norm())) {
      // Stagnation at round-off: accept only if it is already within tolerance.
      out.iterations = it + 1;
      const bool conv =
          t.ok && problem.converged(t, out.max_stress_residual, out.max_strain_residual);
      char buf[160];
      std::snprintf(buf, sizeof buf,
                    "line search found no decrease of the residual (largest stress residual %.3g "
                    "Pa, strain residual %.3g)",
                    out.max_stress_residual, out.max_strain_residual);
      return finish(t, conv, conv ? "" : buf);
    }
    u += alpha * du;
    t = std::move(next);
  }
}

}  // namespace impact::pointdriver
