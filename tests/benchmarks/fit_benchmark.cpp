// Johnson-Cook fit throughput (docs/fitting.md, "Performance"). Not a test. Five free parameters,
// 30 synthetic curves (6 temperatures x 5 rates, made by the driver with a known set, 1 % noise,
// fixed seed) of 50 points each, start 30 % off; prints the wall time of the global fit, best of
// R. Usage: fit_benchmark [--steps S] [--repeats R] [--threads T]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

#include "pointdriver/fit/strength_fit.hpp"

using namespace impact;
using namespace impact::pointdriver::fit;

int main(int argc, char** argv) {
  int steps = 40, repeats = 3, threads = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--steps")) steps = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--repeats")) repeats = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--threads")) threads = std::atoi(argv[i + 1]);
  }
  const std::string material = std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json";
  const JcValues truth{300e6, 150e6, 0.35, 0.012, 1.2};
  CurveSettings settings;
  settings.steps = steps;
  settings.threads = threads;
  std::vector<Experiment> shells;
  for (double T : {294.0, 350.0, 400.0, 450.0, 500.0, 550.0})
    for (double rate : {1e-3, 1.0, 1e2, 1e3, 5e3}) {
      Experiment e;
      e.name = e.file = "synthetic";
      e.temperature = T;
      e.strain_rate = rate;
      for (int k = 0; k < 50; ++k) {
        e.plastic_strain.push_back(0.005 + 0.295 * k / 49.0);
        e.stress.push_back(1.0);
      }
      shells.push_back(e);
    }
  const CurveModel shell_model(material, Json::object(), shells, settings);
  ParameterValues values = law_values(shell_model.base().flow_stress);
  std::copy(truth.begin(), truth.end(), values.begin());  // A, B, n, C, m come first
  const auto pred = shell_model.predict({values});
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 0.01);
  for (std::size_t e = 0; e < shells.size(); ++e)
    for (std::size_t k = 0; k < 50; ++k) shells[e].stress[k] = pred[0][e][k] * (1 + normal(rng));
  const CurveModel model(material, Json::object(), shells, settings);
  FitConfig config;
  const JcValues start{truth[0] * 1.3, truth[1] * 0.7, truth[2] * 1.3, truth[3] * 0.7,
                       truth[4] * 1.3};
  const double bounds[5][2] = {{1e6, 5e9}, {0.0, 5e9}, {0.01, 2.0}, {0.0, 0.5}, {0.05, 10.0}};
  for (std::size_t i = 0; i < 5; ++i)
    config.parameters.push_back(
        {jc_names[i], i < 2 ? "Pa" : "-", true, start[i], bounds[i][0], bounds[i][1]});
  config.initial_guess = "start";
  double best = 1e300;
  StrengthFit fit;
  for (int r = 0; r < repeats; ++r) {
    fit = fit_strength(model, config);
    best = std::min(best, fit.lsq.wall_time);
  }
  std::printf(
      "5 parameters, 30 curves x 50 points, %d driver steps per curve: best of %d %.3f s "
      "(%d iterations, %d parameter sets = %d driver runs)\n",
      steps, repeats, best, fit.lsq.iterations, fit.lsq.residual_evaluations,
      30 * fit.lsq.residual_evaluations);
  for (std::size_t i = 0; i < 5; ++i)
    std::printf("  %s fitted %.6g (truth %.6g, %+.3f %%)\n", jc_names[i], fit.fitted[i], truth[i],
                100 * (fit.fitted[i] / truth[i] - 1));
  return 0;
}
