#include "mpm/simulation/fault_injection.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace impact::mpm {

std::optional<FaultInjection> parse_fault_injection(const std::string& text) {
  using Kind = FaultInjection::Kind;
  static const std::pair<const char*, Kind> kinds[] = {
      {"nan", Kind::nan},         {"nan_velocity", Kind::nan_velocity},
      {"outside", Kind::outside}, {"jacobian", Kind::jacobian},
      {"sigterm", Kind::sigterm}, {"sigint", Kind::sigint}};
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t colon = text.find(':', start);
    parts.push_back(text.substr(start, colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  FaultInjection f;
  bool known = false;
  for (const auto& [name, kind] : kinds) {
    if (parts[0] == name) {
      f.kind = kind;
      known = true;
    }
  }
  if (!known || parts.size() != (f.is_signal() ? 2u : 3u)) return std::nullopt;
  const auto whole = [](const std::string& s, long long& v) {
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 15)
      return false;
    v = std::stoll(s);
    return true;
  };
  long long step = 0, particle = 0;
  if (!whole(parts[1], step) || step < 1) return std::nullopt;
  if (!f.is_signal() && !whole(parts[2], particle)) return std::nullopt;
  f.step = static_cast<long>(step);
  f.particle = static_cast<std::size_t>(particle);
  return f;
}

std::ptrdiff_t apply_faults(const std::vector<FaultInjection>& faults, long step, Particles& P,
                            const GridSpec& grid) {
  std::ptrdiff_t nan_stress = -1;
  for (const FaultInjection& f : faults) {
    if (f.step != step) continue;
    // Its index here: the seed index itself in seed order; else by P.id, on the rank holding it.
    std::size_t p = f.particle;
    if (!P.id.empty()) {
      const auto it = std::find(P.id.begin(), P.id.end(), f.particle);
      if (it == P.id.end()) continue;
      p = static_cast<std::size_t>(it - P.id.begin());
    }
    switch (f.kind) {
      case FaultInjection::Kind::nan:
        nan_stress = static_cast<std::ptrdiff_t>(p);
        break;
      case FaultInjection::Kind::nan_velocity:
        P.v[p].setConstant(std::numeric_limits<double>::quiet_NaN());
        break;
      case FaultInjection::Kind::outside:
        P.x[p](0) = grid.upper(0) + grid.spacing()(0);
        break;
      case FaultInjection::Kind::jacobian:
        P.state[p].F.col(0) *= -1.0;
        break;
      case FaultInjection::Kind::sigterm:
      case FaultInjection::Kind::sigint:
        break;
    }
  }
  return nan_stress;
}

}  // namespace impact::mpm
