#include "pointdriver/study/convergence_study.hpp"
#include "pointdriver/format/text_format.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "pointdriver/driver/driver.hpp"
#include "support/atomic_file.hpp"
#include "support/shipped_file.hpp"

namespace impact::pointdriver {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr int common_points = 10;  // x_k = k/10 x_end: output points of every run (N % 10 == 0)

/// A study path: a named leg with `steps` left open, a strain measure and the series run on it.
struct StudyPath {
  std::string name;
  Json leg;        ///< named leg without "steps"
  Json overrides;  ///< material merge patch common to every series
  double duration = 0.0;
  double strain_end = 0.0;                           ///< x at the end of the path
  std::function<double(const Row&)> strain;          ///< x of a row
  std::vector<std::pair<std::string, Json>> series;  ///< variant name -> extra material patch
  std::vector<std::string> descriptions;
};

Json cm(Json inner) {
  return Json{{"constitutive_model", std::move(inner)}};
}

std::vector<StudyPath> study_paths() {
  // Failure detection off (erosion none) in every series: the study measures the integration of
  // the flow, and a failure criterion firing at a step-dependent time would end runs early.
  const Json no_failure = cm({{"erosion", {{"algorithm", "none"}}}});
  const Json report_2004 = cm({{"return_algorithm", "report_2004"}});
  const Json jaumann = cm({{"objective_rate", "jaumann"}});
  std::vector<StudyPath> paths;
  {
    StudyPath p;
    p.name = "uniaxial_stress_adiabatic";
    p.leg = {{"type", "uniaxial_stress"},
             {"strain", 0.3},
             {"strain_rate", 1000.0},
             {"thermal", "adiabatic"}};
    p.overrides = no_failure;
    p.duration = 0.3 / 1000.0;
    p.strain_end = 0.3;
    p.strain = [](const Row& r) { return std::log(r.F(0, 0)); };
    p.series = {{"newton", Json::object()}, {"report_2004", report_2004}};
    p.descriptions = {
        "uniaxial stress (named leg: sigma_yy = sigma_zz = 0, shears free: 5 stress-controlled "
        "unknowns), 1e3 /s, adiabatic heating "
        "(eq. 8), log strain 0.3; Green-Naghdi rate, Newton radial return",
        "as newton with the 2004 one-shot return (d = |eta| dt)"};
    paths.push_back(std::move(p));
  }
  {
    StudyPath p;
    p.name = "simple_shear";
    p.leg = {{"type", "simple_shear"}, {"gamma", 2.0}, {"gamma_rate", 1000.0}};
    p.overrides = no_failure;
    p.duration = 2.0 / 1000.0;
    p.strain_end = 2.0;
    p.strain = [](const Row& r) { return r.F(0, 1); };
    p.series = {{"newton", Json::object()}, {"report_2004", report_2004}, {"jaumann", jaumann}};
    p.descriptions = {
        "simple shear F_xy = gamma to 2 at 1e3 /s (F-controlled, no unknowns), "
        "isothermal; Green-Naghdi rate, Newton radial return",
        "as newton with the 2004 one-shot return",
        "as newton with the Jaumann rate (Hughes-Winget rotation)"};
    paths.push_back(std::move(p));
  }
  {
    // Density ratio rho / rho0 = 1.2: axial log strain -ln 1.2.
    const double e = -std::log(1.2);
    StudyPath p;
    p.name = "uniaxial_strain_mie_gruneisen";
    p.leg = {{"type", "uniaxial_strain"},
             {"strain", e},
             {"strain_rate", -1e4},
             {"thermal", "adiabatic"}};
    p.overrides = no_failure;
    p.overrides.merge_patch(cm({{"equation_of_state", {{"type", "mie_gruneisen"}}}}));
    p.duration = e / -1e4;
    p.strain_end = e;
    p.strain = [](const Row& r) { return std::log(r.F(0, 0)); };
    p.series = {{"newton", Json::object()}, {"report_2004", report_2004}};
    p.descriptions = {
        "uniaxial-strain compression at 1e4 /s to rho/rho0 = 1.2 (no unknowns), "
        "Mie-Gruneisen EOS, adiabatic; Green-Naghdi rate, Newton radial return",
        "as newton with the 2004 one-shot return"};
    paths.push_back(std::move(p));
  }
  return paths;
}

/// What a run leaves for the error measures: x / x_end and the path-frame stress per row.
struct Capture {
  std::vector<double> progress;
  std::vector<std::array<double, 6>> stress;
  bool finite = true;
};

double frobenius(const std::array<double, 6>& s) {
  return std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2] +
                   2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

std::array<double, 6> difference(const std::array<double, 6>& a, const std::array<double, 6>& b) {
  std::array<double, 6> d;
  for (int c = 0; c < 6; ++c) d[c] = a[c] - b[c];
  return d;
}

/// Stress at progress q by linear interpolation (progress increases along a run).
std::array<double, 6> stress_at(const Capture& c, double q) {
  const auto it = std::lower_bound(c.progress.begin(), c.progress.end(), q);
  if (it == c.progress.end()) return c.stress.back();
  const auto i = static_cast<std::size_t>(it - c.progress.begin());
  if (i == 0 || *it == q) return c.stress[i];
  const double w = (q - c.progress[i - 1]) / (c.progress[i] - c.progress[i - 1]);
  std::array<double, 6> s;
  for (int k = 0; k < 6; ++k) s[k] = (1 - w) * c.stress[i - 1][k] + w * c.stress[i][k];
  return s;
}

/// Relative curve error (max norm over the common points) and final-stress error of a vs ref.
std::pair<double, double> errors(const Capture& a, const Capture& ref) {
  if (a.progress.empty() || ref.progress.empty()) return {nan, nan};
  // A run that stopped short of the path's end has no error.
  if (a.progress.back() < 1.0 - 1e-9 || ref.progress.back() < 1.0 - 1e-9) return {nan, nan};
  double num = 0.0, den = 0.0;
  for (int k = 1; k <= common_points; ++k) {
    const double q = static_cast<double>(k) / common_points;
    const auto sr = stress_at(ref, q);
    num = std::max(num, frobenius(difference(stress_at(a, q), sr)));
    den = std::max(den, frobenius(sr));
  }
  const double fin =
      frobenius(difference(a.stress.back(), ref.stress.back())) / frobenius(ref.stress.back());
  return {num / den, fin};
}

struct Fit {
  double slope = nan, r2 = nan;
};

Fit least_squares(const std::vector<double>& x, const std::vector<double>& y) {
  Fit f;
  const auto n = static_cast<double>(x.size());
  if (x.size() < 2) return f;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / n, my += y[i] / n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  f.slope = sxy / sxx;
  f.r2 = syy > 0 ? sxy * sxy / (sxx * syy) : 1.0;
  return f;
}

std::string fmt(double v, int precision = 3) {
  return std::isfinite(v) ? format_number(v, precision) : "-";
}

}  // namespace

std::vector<int> quick_convergence_steps() {
  return {10, 20, 50, 100, 200, 500, 1000};
}

std::vector<ConvergenceSeries> convergence_series() {
  std::vector<ConvergenceSeries> out;
  for (const auto& p : study_paths()) {
    for (std::size_t v = 0; v < p.series.size(); ++v) {
      out.push_back({p.name, p.series[v].first, p.descriptions[v]});
    }
  }
  return out;
}

ConvergenceResult run_convergence_study(const ConvergenceSettings& settings) {
  using Clock = std::chrono::steady_clock;
  if (settings.steps.size() < 2) throw std::invalid_argument("convergence: need two step counts");
  for (int n : settings.steps) {
    if (n <= 0 || n % common_points != 0) {
      throw std::invalid_argument("convergence: step counts must be positive multiples of 10");
    }
  }
  const std::string material = settings.material_file.empty()
                                   ? shipped_file("data/materials/al6061_t6.json").string()
                                   : settings.material_file;

  ConvergenceResult result;
  for (const StudyPath& sp : study_paths()) {
    Capture baseline_ref;
    for (const auto& [variant, patch] : sp.series) {
      Json overrides = sp.overrides;
      overrides.merge_patch(patch);
      std::vector<Capture> captures;
      const std::size_t first = result.runs.size();
      for (int n : settings.steps) {
        Json leg = sp.leg;
        leg["steps"] = n;
        const Json doc = {{"material", {{"file", material}, {"overrides", overrides}}},
                          {"temperature", 294.0},
                          {"legs", Json::array({leg})}};
        const Path path = read_path(doc, "convergence study: " + sp.name + " (" + variant + ")");
        const int repeats = n <= 1000    ? settings.repeats_small
                            : n <= 10000 ? settings.repeats_medium
                                         : 1;
        Capture keep;
        RunResult rr;
        double best = std::numeric_limits<double>::infinity();
        long iterations = 0, substeps = 0;
        for (int rep = 0; rep < std::max(1, repeats); ++rep) {
          Capture c;
          c.progress.reserve(static_cast<std::size_t>(n) + 1);
          c.stress.reserve(static_cast<std::size_t>(n) + 1);
          long it = 0, sub = 0;
          const auto t0 = Clock::now();
          rr = run_path(path, [&](const Row& row) {
            const Mat3& s = row.stress_path;
            c.progress.push_back(sp.strain(row) / sp.strain_end);
            c.stress.push_back({s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(2, 0)});
            c.finite = c.finite && s.allFinite();
            it += row.iterations;
            sub += row.step > 0 ? row.substeps : 0;
          });
          best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
          if (rep == 0) {
            keep = std::move(c);
            iterations = it;
            substeps = sub;
          }
        }
        ConvergenceRun run;
        run.path = sp.name;
        run.variant = variant;
        run.steps = n;
        run.dt = sp.duration / n;
        run.wall_time = best;
        run.iterations_per_step = static_cast<double>(iterations) / n;
        run.substeps_per_step = static_cast<double>(substeps) / n;
        if (!rr.completed) {
          run.status = "unsolved";
          run.message = rr.error;
        } else if (!keep.finite) {
          run.status = "non_finite";
        } else if (rr.failure != FailureCause::none) {
          run.status = "failed_" + std::string(to_string(rr.failure));
        } else {
          run.status = "ok";
        }
        if (run.status != "ok" && run.status != "reference") keep.progress.clear();
        if (settings.progress) {
          std::ostringstream line;
          line << sp.name << " / " << variant << ": N = " << n << ", " << fmt(best, 4) << " s, "
               << run.status << (run.message.empty() ? "" : " (" + run.message + ")");
          settings.progress(line.str());
        }
        result.runs.push_back(run);
        captures.push_back(std::move(keep));
      }
      // The reference: the most refined run of the series that completed with finite output
      // (runs beyond it, if any, are marked and have no error).
      std::size_t r = captures.size();
      while (r > 0 && result.runs[first + r - 1].status != "ok") --r;
      const Capture none;
      const Capture& ref = r > 0 ? captures[r - 1] : none;
      const int n_ref = r > 0 ? result.runs[first + r - 1].steps : 0;
      if (r > 0) result.runs[first + r - 1].status = "reference";
      if (variant == sp.series.front().first) baseline_ref = ref;
      std::vector<double> lx, ly, lyf;
      for (std::size_t k = 0; k < captures.size(); ++k) {
        ConvergenceRun& run = result.runs[first + k];
        std::tie(run.error, run.final_error) = errors(captures[k], ref);
        run.baseline_error = errors(captures[k], baseline_ref).first;
        run.local_order = nan;
        if (k > 0 && run.status == "ok") {
          const ConvergenceRun& prev = result.runs[first + k - 1];
          run.local_order = std::log(prev.error / run.error) / std::log(prev.dt / run.dt);
        }
        if (run.status != "ok" || !(run.error > 0) || !(run.final_error > 0)) continue;
        if (run.steps * 500 < n_ref || run.steps * 10 > n_ref) continue;
        lx.push_back(std::log(run.dt));
        ly.push_back(std::log(run.error));
        lyf.push_back(std::log(run.final_error));
      }
      ConvergenceOrder o;
      o.path = sp.name;
      o.variant = variant;
      const Fit f = least_squares(lx, ly), ff = least_squares(lx, lyf);
      o.order = f.slope;
      o.r_squared = f.r2;
      o.final_order = ff.slope;
      o.points = static_cast<int>(lx.size());
      o.n_ref = n_ref;
      o.n_min = std::max(n_ref / 500, settings.steps.front());
      o.n_max = n_ref / 10;
      result.orders.push_back(o);
    }
  }
  return result;
}

void write_convergence_csv(const ConvergenceResult& result, const std::string& file) {
  AtomicFile csv(file);
  std::ostream& out = csv.stream();
  out << "path,variant,steps,dt [s],wall time [s],error [-],status,final stress error [-],"
         "error vs baseline reference [-],local order [-],newton iterations per step [-],"
         "substeps per step [-],message\n";
  out << std::setprecision(8);
  const auto num = [](double v) { return std::isfinite(v) ? fmt(v, 8) : std::string("nan"); };
  for (const auto& r : result.runs) {
    out << r.path << ',' << r.variant << ',' << r.steps << ',' << num(r.dt) << ','
        << num(r.wall_time) << ',' << num(r.error) << ',' << r.status << ',' << num(r.final_error)
        << ',' << num(r.baseline_error) << ',' << num(r.local_order) << ','
        << num(r.iterations_per_step) << ',' << num(r.substeps_per_step) << ','
        << csv_cell(r.message) << '\n';
  }
  csv.commit();
}

void write_convergence_orders_csv(const ConvergenceResult& result, const std::string& file) {
  AtomicFile csv(file);
  std::ostream& out = csv.stream();
  out << "path,variant,reference steps,order [-],final stress order [-],r squared [-],"
         "fit steps min,fit steps max,points\n";
  const auto num = [](double v) { return std::isfinite(v) ? fmt(v, 6) : std::string("nan"); };
  for (const auto& o : result.orders) {
    out << o.path << ',' << o.variant << ',' << o.n_ref << ',' << num(o.order) << ','
        << num(o.final_order) << ',' << num(o.r_squared) << ',' << o.n_min << ',' << o.n_max << ','
        << o.points << '\n';
  }
  csv.commit();
}

std::string convergence_markdown(const ConvergenceResult& result) {
  std::ostringstream md;
  std::map<std::string, std::vector<std::string>> variants;
  std::vector<std::string> paths;
  for (const auto& r : result.runs) {
    if (variants.find(r.path) == variants.end()) paths.push_back(r.path);
    auto& v = variants[r.path];
    if (std::find(v.begin(), v.end(), r.variant) == v.end()) v.push_back(r.variant);
  }
  for (const auto& p : paths) {
    md << "#### " << p << "\n\n| N | dt [s] |";
    for (const auto& v : variants[p]) {
      md << ' ' << v << ": wall [s] | error | final error | vs baseline |";
    }
    md << "\n|---:|---:|";
    for (std::size_t i = 0; i < variants[p].size(); ++i) md << "---:|---:|---:|---:|";
    md << '\n';
    std::vector<int> steps;
    for (const auto& r : result.runs) {
      if (r.path == p && std::find(steps.begin(), steps.end(), r.steps) == steps.end()) {
        steps.push_back(r.steps);
      }
    }
    std::vector<std::string> notes;
    for (int n : steps) {
      double dt = nan;
      std::ostringstream cells;
      for (const auto& v : variants[p]) {
        for (const auto& r : result.runs) {
          if (r.path != p || r.variant != v || r.steps != n) continue;
          dt = r.dt;
          const bool bad = r.status != "ok" && r.status != "reference";
          cells << ' ' << fmt(r.wall_time) << " | " << (bad ? "**" + r.status + "**" : fmt(r.error))
                << " | " << fmt(r.final_error) << " | " << fmt(r.baseline_error) << " |";
          if (bad)
            notes.push_back(v + ", N = " + std::to_string(n) + ": " + r.status +
                            (r.message.empty() ? "" : " (" + r.message + ")"));
          if (r.substeps_per_step > 1.0) {
            notes.push_back(v + ", N = " + std::to_string(n) + ": steps cut back (" +
                            fmt(r.substeps_per_step) + " sub-steps per step)");
          }
        }
      }
      md << "| " << n << " | " << fmt(dt) << " |" << cells.str() << '\n';
    }
    md << '\n';
    for (const auto& n : notes) md << "- " << n << '\n';
    if (!notes.empty()) md << '\n';
  }
  md << "#### Observed orders (least squares of log error vs log dt)\n\n"
        "| path | variant | reference N | order (curve error) | order (final stress) | R^2 | "
        "fit range N | points |\n|---|---|---:|---:|---:|---:|---|---:|\n";
  for (const auto& o : result.orders) {
    md << "| " << o.path << " | " << o.variant << " | " << o.n_ref << " | " << fmt(o.order) << " | "
       << fmt(o.final_order) << " | " << fmt(o.r_squared, 4) << " | " << o.n_min << " - " << o.n_max
       << " | " << o.points << " |\n";
  }
  return md.str();
}

}  // namespace impact::pointdriver
