#include "pointdriver/fit/damage_fit.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "models/damage/johnson_cook_damage.hpp"
#include "models/material/material.hpp"
#include "pointdriver/fit/byte_order_mark.hpp"
#include "pointdriver/fit/csv_text.hpp"
#include "pointdriver/fit/parameter_bounds.hpp"
#include "pointdriver/format/text_format.hpp"
#include "support/atomic_file.hpp"

namespace impact::pointdriver::fit {

namespace fs = std::filesystem;

namespace {

constexpr std::array<const char*, 5> kNames{"D1", "D2", "D3", "D4", "D5"};
constexpr std::array<const char*, 4> kColumns{"triaxiality [-]", "strain_rate [1/s]",
                                              "temperature [K]", "fracture_strain [-]"};

}  // namespace

FractureData read_fracture_data(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError({file + ": cannot open the fracture-strain file"});
  FractureData d;
  d.file = file;
  InputProblems problems(file);
  const auto add = [&](int line, const std::string& m) { problems.add_at_line(line, m); };
  std::string line;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) {
      if (const auto wrong = strip_byte_order_mark(line)) {
        add(1, *wrong);
        problems.throw_if_any();  // the rest would be a misleading error per line
      }
    }
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const auto colon = t.find(':');
      if (colon != std::string::npos && trim(t.substr(1, colon - 1)) == "source")
        d.source = trim(t.substr(colon + 1));
      continue;
    }
    if (!header) {
      header = true;
      if (t != "triaxiality [-],strain_rate [1/s],temperature [K],fracture_strain [-]")
        add(number,
            "expected the header 'triaxiality [-],strain_rate [1/s],temperature [K],"
            "fracture_strain [-]'");
      continue;
    }
    // Cells split at every comma, so that "0.3,,294,0.5" has an empty second cell.
    const std::vector<std::string> cells = split_cells(t);
    if (cells.size() != kColumns.size()) {
      add(number, std::string(cells.size() < kColumns.size() ? "short" : "long") +
                      " row: expected 4 values (triaxiality, strain_rate, temperature, "
                      "fracture_strain), got " +
                      std::to_string(cells.size()) + ": '" + t + "'");
      continue;
    }
    std::vector<double> v;
    bool ok = true;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string cell = trim(cells[c]);
      double x = 0.0;
      const bool is_number = parse_number(cell, x);
      const std::string where = "column " + std::to_string(c + 1) + " (" + kColumns[c] + "): ";
      if (cell.empty()) {
        add(number, where + "empty cell");
        ok = false;
      } else if (!is_number) {
        add(number, where + "not a number: '" + cell + "'");
        ok = false;
      } else if (!std::isfinite(x)) {
        add(number, where + "non-finite value (NaN or Inf): '" + cell + "'");
        ok = false;
      }
      v.push_back(x);
    }
    if (!ok) continue;
    if (v[1] <= 0) add(number, "strain rate must be positive [1/s]");
    if (v[2] <= 0) {
      add(number, "temperature must be positive [K]");
    } else if (const auto hint = unit_hint(Quantity::temperature, v[2])) {
      // A cryogenic test at 4 or 20 K is real: a warning, not an error.
      d.warnings.push_back(problems.line_location(number) + ": temperature " + *hint +
                           "; the value is used as given");
    }
    if (v[3] <= 0 || v[3] > 5) add(number, "fracture strain must be in (0, 5] (a fraction)");
    d.points.push_back({v[0], v[1], v[2], v[3], number});
  }
  if (d.source.empty()) add(0, "missing '# source: ...' line (the citation of the data)");
  if (!header || d.points.empty()) add(0, "no data rows");
  problems.throw_if_any();
  return d;
}

std::vector<double> fracture_strains(const JohnsonCookDamageParams& base,
                                     const std::vector<double>& d,
                                     const std::vector<FracturePoint>& points) {
  JohnsonCookDamageParams q = base;
  q.D1 = d[0];
  q.D2 = d[1];
  q.D3 = d[2];
  q.D4 = d[3];
  q.D5 = d[4];
  std::vector<double> e;
  for (const auto& p : points)
    e.push_back(jc_fracture_strain(q, p.triaxiality, p.strain_rate, p.temperature));
  return e;
}

LeastSquaresResult fit_damage(const std::vector<FracturePoint>& points,
                              const JohnsonCookDamageParams& base,
                              const std::vector<Parameter>& parameters,
                              const LeastSquaresOptions& options,
                              const std::vector<double>& weights) {
  const BatchResidual residual = [&](const std::vector<std::vector<double>>& sets) {
    std::vector<Eigen::VectorXd> r;
    for (const auto& s : sets) {
      const auto e = fracture_strains(base, s, points);
      Eigen::VectorXd v(static_cast<long>(points.size()));
      for (std::size_t k = 0; k < points.size(); ++k)
        v(static_cast<long>(k)) =
            (weights.empty() ? 1.0 : weights[k]) * (e[k] - points[k].fracture_strain);
      r.push_back(v);
    }
    return r;
  };
  return least_squares(parameters, residual, options);
}

int run_damage_fit(const FitConfig& config, std::ostream& out) {
  const Material material = load_material(config.material_file, config.overrides);
  const auto& mp = material.model.params();
  JohnsonCookDamageParams base;
  if (const auto* jc = std::get_if<JohnsonCookDamageParams>(&mp.damage)) base = *jc;
  base.room_temperature = mp.room_temperature;
  base.melt_temperature = mp.melt_temperature;
  std::vector<FracturePoint> points;
  std::vector<std::string> sources;
  std::vector<double> weights;
  for (const auto& d : config.data) {
    const FractureData f = read_fracture_data(d.file);
    for (const auto& w : f.warnings) std::cerr << "pointdriver fit: warning: " << w << '\n';
    sources.push_back(f.source);
    for (const auto& p : f.points) {
      points.push_back(p);
      weights.push_back(std::sqrt(d.weight));
    }
  }
  const std::array<double, 5> material_values{base.D1, base.D2, base.D3, base.D4, base.D5};
  std::vector<Parameter> parameters;
  std::vector<std::string> warnings;  // start values moved, parameters ended on a bound
  for (std::size_t i = 0; i < 5; ++i) {
    const ParameterSpec& s = config.parameters[i];
    Parameter p{kNames[i], s.start ? *s.start : material_values[i], s.free, s.lower, s.upper};
    if (const auto moved = p.free ? move_inside_bounds(p, p.value) : std::nullopt) {
      warnings.push_back("start value of " + p.name + " (" + format_number(p.value) + ", " +
                         (s.start ? "the configuration's" : "the material's") +
                         ") is on or outside its bounds [" + format_number(p.lower) + ", " +
                         format_number(p.upper) + "]: moved to " + format_number(*moved));
      p.value = *moved;
    }
    parameters.push_back(p);
  }
  auto predict = [&](const std::vector<double>& v) { return fracture_strains(base, v, points); };
  std::vector<double> start;
  for (const auto& p : parameters) start.push_back(p.value);
  const LeastSquaresResult lsq = fit_damage(points, base, parameters, config.solver, weights);
  std::array<BoundSide, 5> side{};
  int on_bound = 0;
  for (std::size_t i = 0; i < 5; ++i) {
    if (!parameters[i].free) continue;
    side[i] = at_bound(parameters[i], lsq.values[i]);
    if (side[i] == BoundSide::none) continue;
    ++on_bound;
    warnings.push_back(at_bound_message(parameters[i], side[i], lsq.values[i], "-"));
  }
  for (const auto& w : warnings) std::cerr << "pointdriver fit: warning: " << w << '\n';
  auto rms_of = [&](const std::vector<double>& v, double& max) {
    const auto e = predict(v);
    double ss = 0;
    max = 0;
    for (std::size_t k = 0; k < e.size(); ++k) {
      const double r = e[k] - points[k].fracture_strain;
      ss += r * r;
      max = std::max(max, std::abs(r));
    }
    return std::sqrt(ss / static_cast<double>(e.size()));
  };
  double max_fit = 0, max_mat = 0;
  const double rms_fit = rms_of(lsq.values, max_fit);
  const double rms_mat = rms_of({material_values.begin(), material_values.end()}, max_mat);

  out << "Johnson-Cook damage fit (eq. 7, constant triaxiality): " << points.size()
      << " fracture strains\nsources:";
  for (const auto& s : sources) out << "\n  " << s;
  out << "\n"
      << lsq.iterations << " iterations, " << lsq.stop_reason << ", " << std::setprecision(3)
      << lsq.wall_time << " s\n";
  out << "par      material       start      fitted     std err  status\n";
  for (std::size_t i = 0; i < 5; ++i)
    out << std::left << std::setw(5) << kNames[i] << std::right << std::setprecision(5)
        << std::setw(11) << material_values[i] << std::setw(12) << start[i] << std::setw(12)
        << lsq.values[i] << std::setw(12) << std::setprecision(3) << lsq.std_errors[i] << "  "
        << (!parameters[i].free           ? "fixed"
            : side[i] == BoundSide::lower ? "AT LOWER BOUND"
            : side[i] == BoundSide::upper ? "AT UPPER BOUND"
                                          : "free")
        << " [" << parameters[i].lower << ", " << parameters[i].upper << "]\n";
  for (const auto& w : warnings) out << "WARNING: " << w << '\n';
  out << "correlation:\n" << std::setprecision(3) << lsq.correlation << '\n';
  out << "fracture strain RMS: fitted " << rms_fit << " (max " << max_fit << "), material's set "
      << rms_mat << " (max " << max_mat << ")\n";

  const fs::path dir = config.output_directory;
  Json report;
  report["configuration"] = config.file;
  report["sources"] = sources;
  for (std::size_t i = 0; i < 5; ++i)
    report["parameters"][kNames[i]] = {
        {"material", material_values[i]},
        {"start", start[i]},
        {"fitted", lsq.values[i]},
        {"std_error", lsq.std_errors[i]},
        {"free", parameters[i].free},
        {"lower", parameters[i].lower},
        {"upper", parameters[i].upper},
        {"at_bound", side[i] == BoundSide::none ? Json() : Json(to_string(side[i]))}};
  Json at_bounds = Json::array();
  for (std::size_t i = 0; i < 5; ++i)
    if (side[i] != BoundSide::none) at_bounds.push_back(kNames[i]);
  report["parameters_at_bounds"] = at_bounds;
  report["warnings"] = warnings;
  Json corr = Json::array();
  for (long i = 0; i < 5; ++i) {
    Json row = Json::array();
    for (long k = 0; k < 5; ++k) row.push_back(lsq.correlation(i, k));
    corr.push_back(row);
  }
  report["correlation"] = corr;
  report["rms"] = {{"fitted", rms_fit}, {"material", rms_mat}};
  report["max"] = {{"fitted", max_fit}, {"material", max_mat}};
  report["solver"] = {{"iterations", lsq.iterations}, {"stop_reason", lsq.stop_reason}};
  write_file_atomically(dir / "damage_fit_report.json",
                        [&](std::ostream& o) { o << report.dump(2) << '\n'; });
  Json doc = load_json_file(config.material_file);
  Json& dmg = doc["constitutive_model"]["damage"];
  dmg["type"] = "johnson_cook";
  for (std::size_t i = 0; i < 5; ++i) dmg[kNames[i]] = lsq.values[i];
  if (!doc.contains("sources") || !doc["sources"].is_object()) doc["sources"] = Json::object();
  doc["sources"]["damage"] = "Johnson-Cook D1..D5 fitted by `pointdriver fit " + config.file +
                             "` (fracture strain RMS " + std::to_string(rms_fit) + ")";
  doc["description"] =
      "Johnson-Cook damage fitted by pointdriver fit (sources.damage); "
      "everything else from " +
      config.material_file + ": " + doc.value("description", std::string());
  read_material(doc, "fitted material");
  write_file_atomically(dir / config.output_material,
                        [&](std::ostream& o) { o << doc.dump(2) << '\n'; });
  out << "wrote " << (dir / "damage_fit_report.json").string() << ", "
      << (dir / config.output_material).string() << '\n';
  if (lsq.status != 0) return 3;
  if (config.fail_at_bound && on_bound > 0) {
    std::cerr << "pointdriver fit: " << on_bound
              << " parameter(s) ended on a bound (--fail-at-bound): exit 3\n";
    return 3;
  }
  return 0;
}

}  // namespace impact::pointdriver::fit
