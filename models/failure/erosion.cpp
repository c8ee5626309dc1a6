#include "models/failure/erosion.hpp"

#include <array>
#include <string>

namespace impact {

namespace {

constexpr std::array<Erosion, 4> kAll = {Erosion::none, Erosion::allow_no_tension,
                                         Erosion::keep_stress, Erosion::zero_stress};

}  // namespace

Mat3 erode_stress(Erosion algorithm, const Mat3& stress) {
  switch (algorithm) {
    case Erosion::none:
    case Erosion::keep_stress:
      return stress;
    case Erosion::allow_no_tension:
      return mean(stress) > 0.0 ? deviator(stress) : stress;
    case Erosion::zero_stress:
      return Mat3::Zero();
  }
  return stress;
}

std::string_view erosion_name(Erosion algorithm) {
  switch (algorithm) {
    case Erosion::none:
      return "none";
    case Erosion::allow_no_tension:
      return "AllowNoTension";
    case Erosion::keep_stress:
      return "KeepStress";
    case Erosion::zero_stress:
      return "ZeroStress";
  }
  return "none";
}

std::optional<Erosion> erosion_from_name(std::string_view name) {
  for (Erosion e : kAll)
    if (erosion_name(e) == name) return e;
  return std::nullopt;
}

Erosion read_erosion(JsonReader& r) {
  const std::string name =
      r.choice("algorithm", {"none", "AllowNoTension", "KeepStress", "ZeroStress"},
               "stress operation on failed points; none also turns failure "
               "detection off");
  r.reject_unknown_keys();
  // A bad name has been recorded as a problem; none is a harmless stand-in until it is thrown.
  return erosion_from_name(name).value_or(Erosion::none);
}

}  // namespace impact
