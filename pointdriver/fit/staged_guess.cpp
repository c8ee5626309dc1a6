#include "pointdriver/fit/staged_guess.hpp"
#include "pointdriver/format/text_format.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

namespace impact::pointdriver::fit {

namespace {

struct Pt {
  double ep, sigma, x, temperature;  // x: the rate variable ln(rate*)
};

/// Golden-section minimisation of f on [a, b].
double golden(const std::function<double(double)>& f, double a, double b, int iterations = 80) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < iterations; ++i) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

/// B and n from the log-log regression of (sigma - A) against eps_p (points with sigma > A),
/// weighted by (sigma - A)^2 so that it approximates least squares in stress (a residual d ln y
/// is a stress residual y d ln y); unweighted, noise at small sigma - A biases n.
bool loglog(const std::vector<Pt>& pts, double A, double& B, double& n) {
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  int k = 0;
  for (const auto& p : pts) {
    if (p.sigma <= A || p.ep <= 0) continue;
    const double w = (p.sigma - A) * (p.sigma - A);
    const double x = std::log(p.ep), y = std::log(p.sigma - A);
    sw += w;
    sx += w * x;
    sy += w * y;
    sxx += w * x * x;
    sxy += w * x * y;
    ++k;
  }
  if (k < 2) return false;
  const double det = sw * sxx - sx * sx;
  if (std::abs(det) <= 1e-12 * sw * sxx) return false;
  n = (sw * sxy - sx * sy) / det;
  B = std::exp((sy - n * sx) / sw);
  return true;
}

std::string fmt(double v) {
  return format_number(v, 4);
}

}  // namespace

StagedGuess staged_guess(const std::vector<Experiment>& experiments,
                         const std::vector<bool>& adiabatic, const ElasticPlasticParams& material,
                         const JcValues& start, const std::array<bool, 5>& free,
                         double room_tolerance) {
  // The staged guess is Johnson-Cook's (CurveModel accepts no other law).
  const JohnsonCookParams& jc = std::get<JohnsonCookParams>(material.flow_stress);
  const double room = material.room_temperature, melt = material.melt_temperature;
  const double heat = material.heating.taylor_quinney / (material.density * material.specific_heat);
  JcValues v = start;
  StagedGuess out;

  auto rate_x = [&](double rate) {
    const double r = rate / jc.reference_strain_rate;
    if (jc.rate_form == JohnsonCookRateForm::report_2004 && r < 1.0) return std::log1p(r);
    return std::log(std::max(r, 1.0));
  };
  // Points of one experiment with its temperature history (adiabatic: integrated along the
  // measured curve from eps_p = 0, where the stress is taken as the first point's).
  auto points_of = [&](std::size_t i) {
    const Experiment& e = experiments[i];
    std::vector<Pt> pts;
    double T = e.temperature, ep0 = 0.0, s0 = e.stress.front();
    for (std::size_t k = 0; k < e.plastic_strain.size(); ++k) {
      if (adiabatic[i]) T += heat * 0.5 * (s0 + e.stress[k]) * (e.plastic_strain[k] - ep0);
      ep0 = e.plastic_strain[k];
      s0 = e.stress[k];
      pts.push_back({e.plastic_strain[k], e.stress[k], rate_x(e.strain_rate), T});
    }
    return pts;
  };
  auto thermal = [&](double T, double m) {
    const double ts = (T - room) / (melt - room);
    if (ts <= 0) return 1.0;
    if (ts >= 1) return 0.0;
    return 1.0 - std::pow(ts, m);
  };
  auto hardening = [&](double ep) { return v[0] + v[1] * std::pow(ep, v[2]); };

  // Groups.
  std::vector<std::size_t> reference, rate_series, hot;
  double lowest_room_rate = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < experiments.size(); ++i) {
    const Experiment& e = experiments[i];
    const bool at_room = std::abs(e.temperature - room) <= room_tolerance;
    if (at_room) lowest_room_rate = std::min(lowest_room_rate, e.strain_rate);
    if (at_room && e.strain_rate > jc.reference_strain_rate) rate_series.push_back(i);
    if (e.temperature > room + room_tolerance) hot.push_back(i);
  }
  for (std::size_t i = 0; i < experiments.size(); ++i) {
    const Experiment& e = experiments[i];
    if (std::abs(e.temperature - room) > room_tolerance) continue;
    if (e.strain_rate <= jc.reference_strain_rate || e.strain_rate == lowest_room_rate)
      reference.push_back(i);
  }

  // Stage 1: A, B, n.
  {
    Stage s;
    s.name = "1: A, B, n";
    s.method = "reference curves (T within " + fmt(room_tolerance) + " K of " + fmt(room) +
               " K, rate <= " + fmt(jc.reference_strain_rate) +
               " /s or the slowest room-temperature test): A = yield at eps_p -> 0 from the "
               "straightest ln(sigma - A) vs ln eps_p line; B, n from that line";
    std::vector<Pt> pts;
    for (std::size_t i : reference) {
      const auto p = points_of(i);
      pts.insert(pts.end(), p.begin(), p.end());
      ++s.curves;
    }
    s.points = static_cast<int>(pts.size());
    if (pts.size() >= 3) {
      // The 0.2 % offset stress: interpolated at eps_p = 0.002 on the first reference curve.
      const Experiment& e0 = experiments[reference.front()];
      double y02 = e0.stress.front();
      for (std::size_t k = 1; k < e0.plastic_strain.size(); ++k) {
        if (e0.plastic_strain[k] >= 0.002 || k + 1 == e0.plastic_strain.size()) {
          const double t = (0.002 - e0.plastic_strain[k - 1]) /
                           (e0.plastic_strain[k] - e0.plastic_strain[k - 1]);
          y02 = e0.stress[k - 1] + t * (e0.stress[k] - e0.stress[k - 1]);
          break;
        }
      }
      double smin = std::numeric_limits<double>::infinity();
      for (const auto& p : pts) smin = std::min(smin, p.sigma);
      auto sse = [&](double A) {
        double B = v[1], n = v[2];
        if (free[1] || free[2]) {
          if (!loglog(pts, A, B, n)) return std::numeric_limits<double>::max();
          if (!free[1]) B = v[1];
          if (!free[2]) n = v[2];
        }
        double r = 0;
        for (const auto& p : pts) r += std::pow(p.sigma - (A + B * std::pow(p.ep, n)), 2);
        return r;
      };
      // A is a yield stress: searched between 0.6 and 1 times the smallest reference stress (a
      // wider bracket lets scattered data trade A for a very small n).
      if (free[0]) v[0] = golden(sse, 0.6 * smin, smin * (1.0 - 1e-6));
      double B = v[1], n = v[2];
      if (loglog(pts, v[0], B, n)) {
        if (free[1]) v[1] = B;
        if (free[2]) v[2] = n;
      }
      s.rms = std::sqrt(sse(v[0]) / static_cast<double>(pts.size()));
      s.note = "0.2 % offset stress of " + e0.name + ": " + fmt(y02 / 1e6) + " MPa";
    } else {
      s.note = "fewer than 3 reference points: A, B, n kept at their start values";
    }
    s.values = v;
    out.stages.push_back(s);
  }

  // Stages 2 and 3, twice.
  for (int pass = 1; pass <= 2; ++pass) {
    {
      Stage s;
      s.name = "2: C (pass " + std::to_string(pass) + ")";
      s.method =
          "room-temperature curves above the reference rate: sigma = (A + B eps^n)(1 + C "
          "ln rate*)(1 - T*^m), least squares in stress, closed form in C";
      double num = 0, den = 0;
      std::vector<Pt> pts;
      for (std::size_t i : rate_series) {
        const auto p = points_of(i);
        pts.insert(pts.end(), p.begin(), p.end());
        ++s.curves;
      }
      for (const auto& p : pts) {
        const double gh = hardening(p.ep) * thermal(p.temperature, v[4]);
        num += (p.sigma - gh) * gh * p.x;
        den += gh * p.x * gh * p.x;
      }
      s.points = static_cast<int>(pts.size());
      if (free[3] && den > 0) v[3] = num / den;
      if (den <= 0) s.note = "no curves above the reference rate: C kept at its start value";
      double r = 0;
      for (const auto& p : pts)
        r += std::pow(p.sigma - hardening(p.ep) * (1 + v[3] * p.x) * thermal(p.temperature, v[4]),
                      2);
      s.rms = pts.empty() ? 0.0 : std::sqrt(r / static_cast<double>(pts.size()));
      s.values = v;
      out.stages.push_back(s);
    }
    {
      Stage s;
      s.name = "3: m (pass " + std::to_string(pass) + ")";
      s.method =
          "curves above room temperature: least squares in stress over m (golden "
          "section on [0.05, 10])";
      std::vector<Pt> pts;
      for (std::size_t i : hot) {
        const auto p = points_of(i);
        pts.insert(pts.end(), p.begin(), p.end());
        ++s.curves;
      }
      s.points = static_cast<int>(pts.size());
      auto sse = [&](double m) {
        double r = 0;
        for (const auto& p : pts)
          r +=
              std::pow(p.sigma - hardening(p.ep) * (1 + v[3] * p.x) * thermal(p.temperature, m), 2);
        return r;
      };
      if (pts.empty())
        s.note = "no curves above room temperature: m kept at its start value";
      else if (free[4])
        v[4] = golden(sse, 0.05, 10.0);
      s.rms = pts.empty() ? 0.0 : std::sqrt(sse(v[4]) / static_cast<double>(pts.size()));
      s.values = v;
      out.stages.push_back(s);
    }
  }
  out.values = v;
  return out;
}

}  // namespace impact::pointdriver::fit
