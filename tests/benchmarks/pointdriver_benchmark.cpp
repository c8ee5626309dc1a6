// Point-driver throughput (docs/performance.md, "Point driver"). Not a test: timings never decide
// pass or fail. Usage: pointdriver_benchmark [--steps S] [--repeats R] [--batch-steps B]
//
// 1. Single paths, S steps each, best of R: steps per second, Newton iterations per step, and
//    where the time goes: the time of one material update at the run's own states (replayed), of
//    the exponential F update, and the ratio time per step / time per update, i.e. the number of
//    material evaluations a step costs (the central-difference Jacobian of mixed control).
// 2. The CSV writer's cost per row (what `pointdriver run` adds to a step).
// 3. Batch: N parameter sets x M paths in one process (run_batch), 1 and 2 threads, best of R.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "models/kinematics/deformation_gradient.hpp"
#include "pointdriver/driver/driver.hpp"
#include "pointdriver/output/csv_writer.hpp"
#include "pointdriver/study/batch.hpp"

using namespace impact;
using namespace impact::pointdriver;
using Clock = std::chrono::steady_clock;

namespace {

const std::string material_file = std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json";

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Json path_document(const Json& leg, const Json& overrides = Json::object(),
                   const Json& solver = nullptr) {
  Json doc = {{"material", {{"file", material_file}, {"overrides", overrides}}},
              {"temperature", 294.0},
              {"legs", Json::array({leg})}};
  if (!solver.is_null()) doc["solver"] = solver;
  return doc;
}

struct Scenario {
  const char* name;
  const char* unknowns;
  Json leg;  // named leg; "steps" set by the benchmark
  Json overrides = Json::object();
  Json solver = nullptr;
};

std::vector<Scenario> scenarios() {
  // Uniaxial stress with 2 unknowns: L_xx given, the shear components of L fixed at 0, sigma_yy =
  // sigma_zz = 0 solved for. The named leg "uniaxial_stress" does the same (it fixes the shears
  // too); an explicit leg that leaves the shears stress-free has 5 unknowns.
  const Json us2 = {{"duration", 2e-4},
                    {"velocity_gradient",
                     {{"xx", 1000.0},
                      {"xy", 0.0},
                      {"yx", 0.0},
                      {"yz", 0.0},
                      {"zy", 0.0},
                      {"zx", 0.0},
                      {"xz", 0.0}}},
                    {"stress", {{"yy", 0.0}, {"zz", 0.0}}}};
  const Json us5 = {{"type", "uniaxial_stress"}, {"strain", 0.2}, {"strain_rate", 1000.0}};
  const Json ue = {{"type", "uniaxial_strain"}, {"strain", -0.2}, {"strain_rate", -1000.0}};
  const Json ss = {{"type", "simple_shear"}, {"gamma", 1.0}, {"gamma_rate", 1000.0}};
  const auto with = [](Json leg, const char* thermal) {
    leg["thermal"] = thermal;
    return leg;
  };
  const Json no_checks = {{"constitutive_model", {{"erosion", {{"algorithm", "none"}}}}}};
  const Json elastic = {{"jacobian", "elastic"}};
  return {
      {"uniaxial stress, isothermal", "2 (stress)", with(us2, "isothermal")},
      {"uniaxial stress, adiabatic", "2 (stress)", with(us2, "adiabatic")},
      {"uniaxial strain, isothermal", "0", with(ue, "isothermal")},
      {"uniaxial strain, adiabatic", "0", with(ue, "adiabatic")},
      {"simple shear (F), isothermal", "0 (F given)", with(ss, "isothermal")},
      {"simple shear (F), adiabatic", "0 (F given)", with(ss, "adiabatic")},
      {"uniaxial stress (named leg), isothermal", "2 (stress)", with(us5, "isothermal")},
      {"uniaxial stress, iso, no failure checks", "2 (stress)", with(us2, "isothermal"), no_checks},
      {"uniaxial stress, iso, elastic Jacobian", "2 (stress)", with(us2, "isothermal"),
       Json::object(), elastic},
      {"uniaxial stress (named), iso, elastic Jac.", "2 (stress)", with(us5, "isothermal"),
       Json::object(), elastic},
  };
}

void single_paths(int steps, int repeats) {
  std::printf("single paths: %d steps each, best of %d, one thread\n", steps, repeats);
  std::printf("%-43s %-11s %9s %8s %6s %9s %8s %6s %6s %s\n", "path", "unknowns", "steps/s",
              "us/step", "iters", "update us", "expF us", "ratio", "evals", "end");
  for (const Scenario& sc : scenarios()) {
    Json leg = sc.leg;
    leg["steps"] = steps;
    const Path path = read_path(path_document(leg, sc.overrides, sc.solver), sc.name);
    std::vector<Row> rows;
    rows.reserve(static_cast<std::size_t>(steps) + 1);
    RunResult r;
    double best = 1e300;
    for (int rep = 0; rep < repeats; ++rep) {
      rows.clear();
      const auto t0 = Clock::now();
      r = run_path(path, [&](const Row& row) { rows.push_back(row); });
      best = std::min(best, seconds_since(t0));
    }
    long iterations = 0, jacobians = 0;
    for (const Row& row : rows) {
      iterations += row.iterations;
      jacobians += row.jacobian_evaluations;
    }
    const double n = static_cast<double>(r.steps);

    // One material update per step at the run's own states (the converged L and F): the cost of
    // a single evaluation, with the model the driver used for this leg.
    ElasticPlasticParams p = path.material.model.params();
    p.heating.enabled = path.legs[0].thermal == Thermal::adiabatic;
    const ElasticPlastic model(p);
    PointState out;
    double update = 1e300, expf = 1e300, sink = 0.0;
    for (int rep = 0; rep < repeats; ++rep) {
      auto t0 = Clock::now();
      for (std::size_t k = 1; k < rows.size(); ++k) {
        model.update(rows[k - 1].state, rows[k].L, rows[k].F, rows[k].time - rows[k - 1].time, out);
        sink += out.stress(0, 0);
      }
      update = std::min(update, seconds_since(t0));
      t0 = Clock::now();
      for (std::size_t k = 1; k < rows.size(); ++k) {
        sink +=
            advance_deformation_gradient(rows[k - 1].F, rows[k].L, rows[k].time - rows[k - 1].time,
                                         FIntegration::exponential)(0, 1);
      }
      expf = std::min(expf, seconds_since(t0));
    }
    if (sink == 42.0) std::puts("");
    // Material evaluations per step when every line search accepts the full Newton step (callgrind
    // confirms it for these paths): the start, 1 trial per iteration, 2 per unknown per fresh
    // central-difference Jacobian (counted by the solver; reused Jacobians cost nothing).
    const double unknowns = std::atof(sc.unknowns);
    const bool elastic = !sc.solver.is_null();
    const double evals =
        1.0 + (iterations + (elastic ? 0.0 : 2.0 * unknowns * double(jacobians))) / n;
    std::printf("%-43s %-11s %9.0f %8.2f %6.2f %9.3f %8.3f %6.1f %6.1f %s\n", sc.name, sc.unknowns,
                n / best, best / n * 1e6, iterations / n, update / n * 1e6, expf / n * 1e6,
                best / update, unknowns > 0 ? evals : 1.0,
                r.completed ? to_string(r.failure).data() : "UNSOLVED");
  }
  std::printf(
      "(iters: Newton iterations per step; update us: one material update at the run's states;\n"
      " expF us: one exponential F update; ratio: time per step / time per update; evals:\n"
      " material evaluations per step, 1 + iters + 2 unknowns per fresh central-difference\n"
      " Jacobian (reused across steps while Newton contracts); end: failure cause)\n\n");
}

void csv_cost(int steps, int repeats) {
  Json leg = {{"type", "uniaxial_stress"}, {"strain", 0.2}, {"strain_rate", 1000.0}};
  leg["steps"] = steps;
  const Path path = read_path(path_document(leg), "csv");
  std::vector<Row> rows;
  run_path(path, [&](const Row& row) { rows.push_back(row); });
  const std::string file =
      (std::filesystem::temp_directory_path() / "pointdriver_benchmark.csv").string();
  double best = 1e300;
  for (int rep = 0; rep < repeats; ++rep) {
    const auto t0 = Clock::now();
    {
      CsvWriter csv(file, path.material.model.params());
      for (const Row& row : rows) csv.write(row);
    }
    best = std::min(best, seconds_since(t0));
  }
  std::filesystem::remove(file);
  // The derived quantities alone (log strain, invariants, indicators), without formatting.
  double values = 1e300, sink = 0.0;
  for (int rep = 0; rep < repeats; ++rep) {
    const auto t0 = Clock::now();
    for (const Row& row : rows) sink += csv_values(row, path.material.model.params())[12];
    values = std::min(values, seconds_since(t0));
  }
  if (sink == 42.0) std::puts("");
  const double n = static_cast<double>(rows.size());
  std::printf(
      "CSV writer: %.2f us per row (%zu columns), of which csv_values %.2f us; best of %d\n\n",
      best / n * 1e6, csv_columns().size(), values / n * 1e6, repeats);
}

void batch(int steps, int repeats) {
  // 16 parameter sets (Johnson-Cook A and B scaled by 0.85 ... 1.15) x 4 paths.
  const Material base = load_material(material_file);
  std::vector<ElasticPlastic> models;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      ElasticPlasticParams p = base.model.params();
      set_parameter(p.flow_stress, "A", parameter(p.flow_stress, "A") * (0.85 + 0.1 * i));
      set_parameter(p.flow_stress, "B", parameter(p.flow_stress, "B") * (0.85 + 0.1 * j));
      models.emplace_back(p);
    }
  }
  std::vector<Path> paths;
  for (const Scenario& sc : scenarios()) {
    if (paths.size() == 4) break;
    if (std::strstr(sc.name, "adiabatic") && !std::strstr(sc.name, "stress")) continue;
    Json leg = sc.leg;
    leg["steps"] = steps;
    paths.push_back(read_path(path_document(leg, sc.overrides, sc.solver), sc.name));
  }
  std::printf("batch: %zu parameter sets x %zu paths (", models.size(), paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i) {
    std::printf("%s%s", i ? "; " : "", paths[i].file.c_str());
  }
  std::printf("), %d steps each, best of %d\n", steps, repeats);
  std::printf("%8s %10s %12s %10s %8s\n", "threads", "time s", "steps/s", "runs/s", "speedup");
  double serial = 0.0;
  for (int threads : {1, 2}) {
    BatchOptions o;
    o.threads = threads;
    double best = 1e300;
    long total = 0;
    int unsolved = 0;
    for (int rep = 0; rep < repeats; ++rep) {
      const auto t0 = Clock::now();
      const auto results = run_batch(paths, models, o);
      best = std::min(best, seconds_since(t0));
      total = 0;
      unsolved = 0;
      for (const auto& r : results) {
        total += r.result.steps;
        unsolved += !r.result.completed;
      }
    }
    if (threads == 1) serial = best;
    std::printf("%8d %10.4f %12.0f %10.1f %8.2f%s\n", threads, best, total / best,
                static_cast<double>(paths.size() * models.size()) / best, serial / best,
                unsolved ? "  (some runs unsolved)" : "");
  }
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 2000, repeats = 5, batch_steps = 500;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--steps") == 0 && i + 1 < argc) {
      steps = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--repeats") == 0 && i + 1 < argc) {
      repeats = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--batch-steps") == 0 && i + 1 < argc) {
      batch_steps = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr,
                   "usage: pointdriver_benchmark [--steps S] [--repeats R] [--batch-steps B]\n");
      return 1;
    }
  }
  single_paths(steps, repeats);
  csv_cost(steps, repeats);
  batch(batch_steps, repeats);
  return 0;
}
