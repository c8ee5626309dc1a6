// What the verification cases share (pointdriver/verify/cases/): running a path built in code,
// recording checks against independent references, and writing figure data. Internal to the
// cases (not installed: it uses the programs' support/atomic_file.hpp).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pointdriver/driver/driver.hpp"
#include "pointdriver/verify/closed_forms.hpp"
#include "pointdriver/verify/verification_suite.hpp"
#include "support/atomic_file.hpp"

namespace impact::pointdriver::verify {

namespace cf = closed_forms;
namespace fs = std::filesystem;
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

inline std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// ---- running paths ----

struct Run {
  Path path;
  RunResult result;
  std::vector<Row> rows;
  const ElasticPlasticParams& params() const { return path.material.model.params(); }
};

/// {"constitutive_model": inner}: a merge patch on the material file.
inline Json model_patch(const Json& inner) {
  return Json{{"constitutive_model", inner}};
}

/// A purely elastic material: the yield stress is made unreachable.
inline Json elastic_patch() {
  return model_patch(Json{{"flow_stress", Json{{"A", 1e15}}}});
}

inline Json path_document(const SuiteContext& ctx, const Json& overrides, const Json& legs,
                          double temperature = 294.0, const std::string& thermal = "isothermal",
                          const std::string& policy = "stop") {
  Json doc = Json::object();
  doc["material"] = Json{{"file", ctx.material_file}, {"overrides", overrides}};
  doc["temperature"] = temperature;
  doc["thermal"] = thermal;
  doc["failure_policy"] = policy;
  doc["legs"] = legs.is_array() ? legs : Json::array({legs});
  return doc;
}

/// Runs a path built in code; a step that cannot be solved is an error of the case.
inline Run run(const Json& document, const std::string& name) {
  Run r;
  r.path = read_path(document, "verification path '" + name + "'");
  r.result = run_path(r.path, [&](const Row& row) { r.rows.push_back(row); });
  if (!r.result.completed) throw std::runtime_error(name + ": " + r.result.error);
  return r;
}

inline double axial_log_strain(const Row& r, int i = 0) {
  return std::log(r.F(i, i));  // F is diagonal on these paths
}

inline double von_mises_of(const Mat3& s) {
  const Mat3 d = s - s.trace() / 3.0 * Mat3::Identity();
  return std::sqrt(1.5 * (d.array() * d.array()).sum());
}

inline double max_abs(const Mat3& a) {
  return a.cwiseAbs().maxCoeff();
}

// ---- recording checks ----

/// The worst point of a comparison along a path.
struct Worst {
  double error = nan, expected = nan, got = nan;
  int count = 0;
  void update(double expected_value, double got_value, double scale) {
    const double e = std::abs(got_value - expected_value) / scale;
    if (count == 0 || !(e <= error)) {
      error = e;
      expected = expected_value;
      got = got_value;
    }
    ++count;
  }
};

class Recorder {
 public:
  explicit Recorder(std::string name) : case_(std::move(name)) {}

  void add(const std::string& quantity, double expected, double got, double error,
           double tolerance) {
    checks_.push_back({case_, quantity, expected, got, error, tolerance,
                       std::isfinite(error) && error <= tolerance});
  }
  void add(const std::string& quantity, double expected, double got, double error, double tolerance,
           bool pass) {
    checks_.push_back({case_, quantity, expected, got, error, tolerance, pass});
  }
  /// error = |got - expected| / scale (scale 0: |expected|).
  void compare(const std::string& quantity, double expected, double got, double tolerance,
               double scale = 0.0) {
    const double s = scale > 0.0 ? scale : std::abs(expected);
    add(quantity, expected, got, std::abs(got - expected) / s, tolerance);
  }
  /// A comparison along a path; fails when no point was compared.
  void worst(const std::string& quantity, const Worst& w, double tolerance) {
    add(quantity + " [worst of " + std::to_string(w.count) + " steps]", w.expected, w.got,
        w.count > 0 ? w.error : nan, tolerance);
  }
  std::vector<Check> take() { return std::move(checks_); }

 private:
  std::string case_;
  std::vector<Check> checks_;
};

// ---- figure data ----

/// A figure's data, written whole or not at all (support/atomic_file.hpp): close() puts it in
/// place; a case that stops before close() leaves the previous file. Writes nothing without an
/// output directory.
class FigureCsv {
 public:
  FigureCsv(const SuiteContext& ctx, const std::string& name, std::vector<std::string> header) {
    if (ctx.out_dir.empty()) return;
    out_ = std::make_unique<AtomicFile>(fs::path(ctx.out_dir) / name);
    for (std::size_t i = 0; i < header.size(); ++i) out_->stream() << (i ? "," : "") << header[i];
    out_->stream() << '\n';
  }
  void row(const std::vector<double>& v) {
    if (!out_) return;
    char buf[32];
    for (std::size_t i = 0; i < v.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%.12g", v[i]);
      out_->stream() << (i ? "," : "") << buf;
    }
    out_->stream() << '\n';
    out_->check();
  }
  /// OutputError (the case then fails, naming the file) when the data cannot be written.
  void close() {
    if (out_) out_->commit();
  }

 private:
  std::unique_ptr<AtomicFile> out_;
};

}  // namespace impact::pointdriver::verify
