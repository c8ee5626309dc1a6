#include "models/failure/erosion.hpp"

#include <string>

namespace impact {

namespace {

/// The catalogue of erosion algorithms, one line each: the value and its name in a material file
/// (the report's spelling). The reader's choices, erosion_name and erosion_from_name come from it.
struct ErosionEntry {
  Erosion algorithm;
  std::string_view name;
};
constexpr ErosionEntry kAlgorithms[] = {{Erosion::none, "none"},
                                        {Erosion::allow_no_tension, "AllowNoTension"},
                                        {Erosion::keep_stress, "KeepStress"},
                                        {Erosion::zero_stress, "ZeroStress"}};

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
  for (const ErosionEntry& e : kAlgorithms)
    if (e.algorithm == algorithm) return e.name;
  return "none";
}

std::optional<Erosion> erosion_from_name(std::string_view name) {
  for (const ErosionEntry& e : kAlgorithms)
    if (e.name == name) return e.algorithm;
  return std::nullopt;
}

std::vector<std::string_view> erosion_names() {
  std::vector<std::string_view> names;
  for (const ErosionEntry& e : kAlgorithms) names.push_back(e.name);
  return names;
}

Erosion read_erosion(JsonReader& r) {
  const std::string name = r.choice("algorithm", erosion_names(),
                                    "stress operation on failed points; none also turns failure "
                                    "detection off");
  r.reject_unknown_keys();
  // A bad name has been recorded as a problem; none is a harmless stand-in until it is thrown.
  return erosion_from_name(name).value_or(Erosion::none);
}

}  // namespace impact
