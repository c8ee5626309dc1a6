#include "pointdriver/fit/curve_check.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "pointdriver/fit/fit_report.hpp"

namespace impact::pointdriver::fit {

namespace {

/// The tolerances a curve's errors exceed, as messages.
std::vector<std::string> exceeded_tolerances(const CurveErrors& c, const CheckTolerance& t) {
  std::vector<std::string> out;
  auto test = [&](const char* what, std::optional<double> limit, double value, const char* unit,
                  double scale) {
    if (limit && value > *limit) {
      std::ostringstream s;
      s << c.name << ": " << what << ' ' << value / scale << ' ' << unit << " exceeds "
        << *limit / scale << ' ' << unit;
      out.push_back(s.str());
    }
  };
  test("RMS", t.rms, c.rms, "MPa", 1e6);
  test("max", t.max, c.max, "MPa", 1e6);
  test("|mean signed|", t.mean_signed, std::abs(c.mean_signed), "MPa", 1e6);
  test("RMS", t.rms_percent, c.rms_percent(), "%", 1.0);
  return out;
}

}  // namespace

CurveCheck check_curves(const CheckConfig& config) {
  const CurveModel model =
      make_curve_model(config.material_file, config.overrides, config.data, config.curves);
  CurveCheck out;
  out.experiments = model.experiments();
  out.curves = model.curves({law_values(model.base().flow_stress)})[0];
  const std::string classname = "check." + std::filesystem::path(config.file).stem().string();
  for (std::size_t e = 0; e < out.experiments.size(); ++e) {
    const Experiment& x = out.experiments[e];
    std::vector<double> v;
    for (double eps : x.plastic_strain) v.push_back(interpolate_stress(out.curves[e], eps));
    out.errors.push_back(curve_errors(x, v, model.adiabatic(e)));
    if (!out.curves[e].completed) {
      out.warnings.push_back(x.name +
                             ": the driver run did not complete (points past the last solved "
                             "step are compared with its stress): " +
                             out.curves[e].error);
    }
    const CurveErrors& c = out.errors.back();
    const auto failed = exceeded_tolerances(c, config.tolerance);
    std::ostringstream what;
    what << "RMS " << c.rms / 1e6 << " MPa (" << c.rms_percent() << " %), max " << c.max / 1e6
         << " MPa, mean signed " << c.mean_signed / 1e6 << " MPa";
    std::optional<std::string> failure;
    for (const auto& f : failed) failure = failure ? *failure + "; " + f : f;
    out.junit.push_back({c.name, classname, 0.0, failure, what.str()});
    out.exceeded.insert(out.exceeded.end(), failed.begin(), failed.end());
  }
  out.overall = overall(out.errors);
  if (config.overall_rms) {
    const bool over = out.overall.rms > *config.overall_rms;
    std::ostringstream s;
    s << "overall RMS " << out.overall.rms / 1e6 << " MPa" << (over ? " exceeds " : ", limit ")
      << *config.overall_rms / 1e6 << " MPa";
    if (over) out.exceeded.push_back(s.str());
    out.junit.push_back(
        {"overall RMS", classname, 0.0, over ? std::optional(s.str()) : std::nullopt, s.str()});
  }
  out.report = {{"configuration", config.file},
                {"material", config.material_file},
                {"curves", errors_json(out.errors)},
                {"overall", {{"rms [Pa]", out.overall.rms}, {"max [Pa]", out.overall.max}}},
                {"exceeded", out.exceeded},
                {"passed", out.exceeded.empty()}};
  return out;
}

}  // namespace impact::pointdriver::fit
