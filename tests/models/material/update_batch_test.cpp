// UpdateBatch (models/material/update_batch.hpp) against ElasticPlastic::update, the one-point
// path the point driver takes: the same bits for every point, whatever its neighbours in the
// batch. Points on random loading histories (elastic, plastic, at a jump of the 2004 rate form,
// hot enough to melt), batches that are not full, and batches mixing two materials. Without the
// lanes' independence (a lane's result depending on another's iteration count, a mask leaking a
// neighbour's value) or with a different law in the vector path, the states differ.
#include "models/material/update_batch.hpp"

#include <Eigen/Geometry>
#include <boost/test/unit_test.hpp>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "models/material/material.hpp"

using namespace impact;

namespace {

const std::string kMaterialFile = std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json";

// Bitwise equality of one member (a Mat3 by its nine doubles).
template <class T>
bool same(const T& x, const T& y) {
  if constexpr (std::is_same_v<T, Mat3>)
    return std::memcmp(x.data(), y.data(), sizeof(double) * 9) == 0;
  else
    return std::memcmp(&x, &y, sizeof x) == 0;
}

// The first member in which a and b differ in any bit, by name ("" when none). The structured
// bindings name every member: one added to PointState or StepReport without a line here is a
// compile error ("only N names provided"), so no member goes unchecked.
std::string differing_field(const PointState& a, const PointState& b) {
  const auto& [stress, F, R, ep, rate, T, e, D, f, internal, melted, failed, cause, instability,
               in_tension] = a;
  const auto& [stress_b, F_b, R_b, ep_b, rate_b, T_b, e_b, D_b, f_b, internal_b, melted_b, failed_b,
               cause_b, instability_b, in_tension_b] = b;
  const std::pair<bool, const char*> fields[] = {
      {same(stress, stress_b), "stress"},
      {same(F, F_b), "F"},
      {same(R, R_b), "R"},
      {same(ep, ep_b), "plastic_strain"},
      {same(rate, rate_b), "plastic_strain_rate"},
      {same(T, T_b), "temperature"},
      {same(e, e_b), "internal_energy"},
      {same(D, D_b), "damage"},
      {same(f, f_b), "porosity"},
      {same(internal, internal_b), "flow_internal"},
      {same(melted, melted_b), "melted"},
      {same(failed, failed_b), "failed"},
      {same(cause, cause_b), "failure_cause"},
      {same(instability, instability_b), "instability"},
      {same(in_tension, in_tension_b), "failed_in_tension"}};
  for (const auto& [equal, name] : fields)
    if (!equal) return name;
  return "";
}

std::string differing_field(const StepReport& a, const StepReport& b) {
  const auto& [status, plastic, iterations, wave, work, heating, failure, drucker, becker, eroded] =
      a;
  const auto& [status_b, plastic_b, iterations_b, wave_b, work_b, heating_b, failure_b, drucker_b,
               becker_b, eroded_b] = b;
  const std::pair<bool, const char*> fields[] = {
      {same(status, status_b), "report.status"},
      {same(plastic, plastic_b), "report.plastic"},
      {same(iterations, iterations_b), "report.return_iterations"},
      {same(wave, wave_b), "report.wave_speed"},
      {same(work, work_b), "report.plastic_work"},
      {same(heating, heating_b), "report.temperature_rise"},
      {same(failure, failure_b), "report.failure"},
      {same(drucker, drucker_b), "report.drucker_indicator"},
      {same(becker, becker_b), "report.becker_indicator"},
      {same(eroded, eroded_b), "report.eroded_energy"}};
  for (const auto& [equal, name] : fields)
    if (!equal) return name;
  return "";
}

struct Point {
  const ElasticPlastic* model;
  PointState state;
  Mat3 L;
};

struct Differences {
  int points = 0;     ///< point updates whose state or report differ in any bit
  std::string first;  ///< the first: step, point and member
};

// One step of points 0..n-1 in as few batches as the lanes allow (one batch of 8 in GCC's builds,
// batches of 2 in clang's: models/core/lane_math.hpp); add(k) adds point k, writing into next[k].
template <class Add>
std::vector<StepReport> step_in_batches(int n, double dt, std::vector<PointState>& next,
                                        const Add& add) {
  UpdateBatch batch;
  std::vector<StepReport> reports(static_cast<std::size_t>(n));
  for (int k0 = 0; k0 < n; k0 += UpdateBatch::capacity) {
    const int k1 = std::min(n, k0 + UpdateBatch::capacity);
    batch.clear();
    for (int k = k0; k < k1; ++k) add(batch, k);
    batch.run(dt);
    for (int k = k0; k < k1; ++k) reports[k] = batch.finish(k - k0, dt, next[k]);
  }
  return reports;
}

// Advances every point `steps` steps both ways, in batches of `batch_size` (1..8) points, and
// counts the points whose state or report differ in any bit. Every step's velocity gradient is
// random: compression, tension and shear at 1e2..1e6 /s with spin.
Differences differing_points(std::vector<Point> points, int steps, int batch_size,
                             std::mt19937_64& gen, int& plastic_updates,
                             int* failed_points = nullptr) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double dt = 2e-9;
  batch_size = std::min(batch_size, UpdateBatch::capacity);  // 2 in clang's builds
  std::vector<Point> alone = points;
  Differences differing;
  // On the heap, as an MPM thread's or a caller's container may hold it: the AVX-512 kernels load
  // its vectors with 64-byte aligned instructions (a 16-byte aligned batch crashed them).
  std::vector<UpdateBatch> batches(3);
  UpdateBatch& batch = batches[1];
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      Mat3 L;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) L(a, b) = u(gen);
      L *= std::pow(10.0, 2.0 + 2.0 * (u(gen) + 1.0));
      points[i].L = alone[i].L = L;
    }
    std::vector<PointState> next(points.size()), next_alone(points.size());
    std::vector<StepReport> reports(points.size()), reports_alone(points.size());
    for (std::size_t i0 = 0; i0 < points.size(); i0 += batch_size) {
      const std::size_t i1 = std::min(points.size(), i0 + batch_size);
      batch.clear();
      std::vector<Mat3> F1(i1 - i0);  // in place until finish, as add requires
      for (std::size_t i = i0; i < i1; ++i) {
        F1[i - i0] = (Mat3::Identity() + points[i].L * dt) * points[i].state.F;
        batch.add(*points[i].model, points[i].state, points[i].L, F1[i - i0], next[i]);
      }
      batch.run(dt);
      for (std::size_t i = i0; i < i1; ++i) reports[i] = batch.finish(int(i - i0), dt, next[i]);
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Mat3 F1 = (Mat3::Identity() + alone[i].L * dt) * alone[i].state.F;
      reports_alone[i] = alone[i].model->update(alone[i].state, alone[i].L, F1, dt, next_alone[i]);
      std::string field = differing_field(next[i], next_alone[i]);
      if (field.empty()) field = differing_field(reports[i], reports_alone[i]);
      if (!field.empty() && differing.points++ == 0)
        differing.first = "step " + std::to_string(step) + ", point " + std::to_string(i) + ": " +
                          field + " differs";
      plastic_updates += reports[i].plastic;
      points[i].state = next[i];
      alone[i].state = next_alone[i];
    }
  }
  if (failed_points)
    for (const Point& p : points) *failed_points += p.state.failed;
  return differing;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(material_update_batch)

BOOST_AUTO_TEST_CASE(batches_are_aligned_for_the_widest_vector_loads) {
  BOOST_TEST(alignof(UpdateBatch) % lane::kLaneBytes == 0);
  BOOST_TEST(alignof(JohnsonCookReturnBatch) == std::size_t(lane::kLaneBytes));
  BOOST_TEST(alignof(PolarRotationBatch) == std::size_t(lane::kLaneBytes));
  BOOST_TEST(alignof(CorotationBatch) == std::size_t(lane::kLaneBytes));
  std::vector<UpdateBatch> heap(3);
  BOOST_TEST(reinterpret_cast<std::uintptr_t>(&heap[1]) % lane::kLaneBytes == 0);
}

BOOST_AUTO_TEST_CASE(a_batch_gives_every_point_the_bits_of_the_one_point_update) {
  const Material al = load_material(kMaterialFile);
  // A second material in the same batches: the 2004 return and rate form, a lower yield stress,
  // damage and failure off.
  const Material soft = load_material(kMaterialFile, Json::parse(R"({"constitutive_model": {
      "flow_stress": {"A": 1.5e8, "rate_form": "report_2004"},
      "erosion": {"algorithm": "none"}}})"));
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> points;
  for (int i = 0; i < 61; ++i) {  // not a multiple of 8: the last batch is partial
    const ElasticPlastic* model = (i % 5 == 3) ? &soft.model : &al.model;
    // Temperatures from room to above melting (925 K), plastic strains from 0 to 0.5.
    PointState s = model->initial_state(294.0 + 700.0 * u(gen) * u(gen));
    s.plastic_strain = i % 3 == 0 ? 0.0 : 0.5 * u(gen);
    s.plastic_strain_rate = i % 2 == 0 ? 0.0 : 1e4 * u(gen);
    points.push_back({model, s, Mat3::Zero()});
  }
  for (const int size : {8, 5, 1}) {
    int plastic = 0;
    const Differences differing = differing_points(points, 40, size, gen, plastic);
    BOOST_TEST_INFO("batches of " << size << ": " << plastic << " plastic updates of "
                                  << 40 * points.size() << "; " << differing.first);
    BOOST_TEST(differing.points == 0);
    BOOST_TEST(plastic > 200);  // the returns were exercised
  }
}

// A lane whose step rotates by more than ~151 degrees leaves the vector midpoint rotation for the
// polar factor of the mean rotation (corotation.cpp), in a batch as alone; the others stay on the
// lanes. Without the per-lane fallback its D would be rotated by a midpoint that lost its digits.
BOOST_AUTO_TEST_CASE(a_lane_rotating_beyond_151_degrees_in_one_step_gets_the_one_point_bits) {
  const Material al = load_material(kMaterialFile);
  const double dt = 2e-9;
  std::vector<PointState> s0(8, al.model.initial_state(294.0));
  std::vector<Mat3> L(8), F1(8);
  for (int k = 0; k < 8; ++k) {
    s0[k].stress << 1e8, 2e7, 0, 2e7, -5e7, 3e7, 0, 3e7, 4e7;
    L[k] << 1e4 * k, 3e3, 0, -2e3, -5e3, 1e3, 4e2, 0, 2e3;
    const double angle = (k == 2 || k == 5) ? 2.8 : 1e-3 * k;  // 160 degrees on lanes 2 and 5
    const Mat3 Q = Eigen::AngleAxisd(angle, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    F1[k] = Q * (Mat3::Identity() + sym(L[k]) * dt);
  }
  std::vector<PointState> batched(8), alone(8);
  const std::vector<StepReport> reports = step_in_batches(
      8, dt, batched,
      [&](UpdateBatch& batch, int k) { batch.add(al.model, s0[k], L[k], F1[k], batched[k]); });
  for (int k = 0; k < 8; ++k) {
    const StepReport& r = reports[k];
    const StepReport r_alone = al.model.update(s0[k], L[k], F1[k], dt, alone[k]);
    BOOST_TEST_INFO("lane " << k);
    BOOST_TEST(differing_field(batched[k], alone[k]) == "");
    BOOST_TEST(differing_field(r, r_alone) == "");
  }
  // The wide lane's midpoint is the half rotation (to round-off), R_new the full one.
  const Mat3 Q = Eigen::AngleAxisd(2.8, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Corotated c = corotate(Mat3::Identity(), Q, s0[2].stress, sym(L[2]));
  const Mat3 half = Eigen::AngleAxisd(1.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  BOOST_TEST((c.R_mid - half).norm() < 1e-14);
  BOOST_TEST((batched[2].R - Q).norm() < 1e-12);
}

BOOST_AUTO_TEST_CASE(the_2004_return_algorithm_takes_the_one_point_path_in_a_batch) {
  const Material old = load_material(kMaterialFile, Json::parse(R"({"constitutive_model": {
      "return_algorithm": "report_2004", "erosion": {"algorithm": "none"}}})"));
  std::mt19937_64 gen(3);
  std::vector<Point> points(13, Point{&old.model, old.model.initial_state(294.0), Mat3::Zero()});
  int plastic = 0;
  const Differences differing = differing_points(points, 30, 8, gen, plastic);
  BOOST_TEST_INFO(differing.first);
  BOOST_TEST(differing.points == 0);
  BOOST_TEST(plastic > 10);
}

// The lanes' whole step (green_naghdi, Newton, default_hypo) next to lanes that take the one-point
// steps (Mie-Gruneisen, Jaumann, the incremental Green-Naghdi rotation) in the same batches, with
// heating off on one material and a damage law that fails points within a few plastic steps: the
// failed points' erosion runs between the lanes' pressure and their rotation back.
BOOST_AUTO_TEST_CASE(lanes_on_the_whole_step_and_one_point_lanes_mix_with_the_one_point_bits) {
  const Material al = load_material(kMaterialFile);
  const auto variant = [](const char* patch) {
    return load_material(kMaterialFile, Json::parse(patch));
  };
  const Material mg = variant(R"({"constitutive_model": {"equation_of_state":
      {"type": "mie_gruneisen"}}})");
  const Material jaumann = variant(R"({"constitutive_model": {"objective_rate": "jaumann"}})");
  const Material spin =
      variant(R"({"constitutive_model": {"objective_rate": "green_naghdi_incremental"}})");
  const Material cold_brittle = variant(R"({"constitutive_model": {
      "adiabatic_heating": {"enabled": false},
      "damage": {"D1": 0.002, "D2": 0.0, "D3": 0.0, "D4": 0.0, "D5": 0.0},
      "erosion": {"algorithm": "ZeroStress"}}})");
  const ElasticPlastic* models[] = {&al.model,          &mg.model,           &al.model,
                                    &jaumann.model,     &cold_brittle.model, &spin.model,
                                    &cold_brittle.model};
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> points;
  for (int i = 0; i < 45; ++i) {
    const ElasticPlastic* model = models[i % 7];
    PointState s = model->initial_state(294.0 + 300.0 * u(gen));
    s.plastic_strain = 0.2 * u(gen);
    points.push_back({model, s, Mat3::Zero()});
  }
  int plastic = 0, failed = 0;
  const Differences differing = differing_points(points, 40, 8, gen, plastic, &failed);
  BOOST_TEST_INFO(differing.first);
  BOOST_TEST(differing.points == 0);
  BOOST_TEST_INFO(plastic << " plastic updates, " << failed << " failed points");
  BOOST_TEST(plastic > 50);
  BOOST_TEST(failed >= 3);  // erosion was exercised
}

// Neo-Hookean points (constitutive_model.type neo_hookean: stress from F, no return) in the same
// batches as elastic-plastic ones on the lanes: each gets the one-point bits, which are sigma(F1)
// of models/elasticity/neo_hookean.hpp, and its neighbours theirs.
BOOST_AUTO_TEST_CASE(neo_hookean_points_in_a_batch_get_the_one_point_bits_and_their_stress_of_F) {
  const Material al = load_material(kMaterialFile);
  const Material soft =
      load_material(std::string(IMPACT_SOURCE_DIR) + "/data/materials/neo_hookean_soft.json");
  BOOST_TEST(soft.model.hyperelastic());
  // An elastic-plastic material on the one-point path too (the 2004 return): a lane that held a
  // neo-Hookean point in one block and this one in the next must not keep the neo-Hookean step.
  const Material old = load_material(kMaterialFile, Json::parse(R"({"constitutive_model": {
      "return_algorithm": "report_2004", "erosion": {"algorithm": "none"}}})"));
  const ElasticPlastic* models[] = {&al.model,   &soft.model, &soft.model, &old.model,
                                    &soft.model, &old.model,  &al.model};
  std::mt19937_64 gen(7);
  std::vector<Point> points;
  for (int i = 0; i < 29; ++i) {
    const ElasticPlastic* model = models[i % 7];
    points.push_back({model, model->initial_state(294.0), Mat3::Zero()});
  }
  int plastic = 0;
  const Differences differing = differing_points(points, 30, 8, gen, plastic);
  BOOST_TEST_INFO(differing.first);
  BOOST_TEST(differing.points == 0);
  BOOST_TEST(plastic > 0);  // the aluminium points yielded beside them
  // One batch step from a strained state, F1 = (I + L dt) F0 at 30 % strain: sigma(F1) exactly.
  Mat3 F0 = Mat3::Identity(), L = Mat3::Zero();
  F0(0, 1) = 0.3;
  F0(2, 2) = 1.2;
  L(0, 0) = 1e5;
  L(1, 2) = -3e5;
  const double dt = 1e-7;
  const Mat3 F1 = (Mat3::Identity() + L * dt) * F0;
  std::vector<PointState> s0(5), s1(5);
  for (int k = 0; k < 5; ++k) {
    s0[k] = models[k]->initial_state(294.0);
    s0[k].F = F0;
  }
  const std::vector<StepReport> reports = step_in_batches(
      5, dt, s1, [&](UpdateBatch& batch, int k) { batch.add(*models[k], s0[k], L, F1, s1[k]); });
  for (int k = 0; k < 5; ++k) {
    const StepReport& r = reports[k];
    if (models[k] != &soft.model) continue;
    const Mat3 expected = neo_hookean_stress(F1, soft.model.neo_hookean_moduli());
    BOOST_TEST((r.status == UpdateStatus::ok));
    BOOST_TEST((s1[k].stress - expected).norm() <= 1e-14 * expected.norm());
    BOOST_TEST(s1[k].F.isApprox(F1, 0.0));
    BOOST_TEST(r.wave_speed == neo_hookean_wave_speed(F1, soft.model.neo_hookean_moduli(),
                                                      soft.model.params().density));
  }
}

BOOST_AUTO_TEST_SUITE_END()
