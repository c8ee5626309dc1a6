#include "pointdriver/driver/replay.hpp"

#include <filesystem>

namespace impact::pointdriver {

Json tensor_json(const Mat3& a) {
  Json j = Json::object();
  for (int k = 0; k < 9; ++k) j[tensor_names[k]] = a(k / 3, k % 3);
  return j;
}

Json stress_json(const Mat3& a) {
  Json j = Json::object();
  for (int c = 0; c < 6; ++c) j[stress_names[c]] = a(stress_index[c][0], stress_index[c][1]);
  return j;
}

Json replay_path(const Path& path, const Leg& leg, const ControlPlan& plan, const PointState& s0,
                 const Mat3& Q, double t_leg, double dt, double end_temperature,
                 double rotation_rate) {
  Json doc = Json::object();
  doc["description"] = "Replay of a step the point driver could not solve: " + path.file +
                       ", leg '" + leg.label + "' at leg time " + std::to_string(t_leg) + " s";
  // The material as the original path named it, with its file made absolute so the replay runs
  // from any directory.
  Json material = path.material_source;
  if (material.is_string()) material = Json{{"file", material}};
  if (material.contains("file")) {
    material["file"] = std::filesystem::absolute(path.material.file).string();
  }
  doc["material"] = material;
  doc["temperature"] = s0.temperature;
  doc["failure_policy"] = "stop";
  doc["solver"] = {{"stress_tolerance", path.solver.stress_tolerance},
                   {"relative_stress_tolerance", path.solver.relative_stress_tolerance},
                   {"strain_tolerance", path.solver.strain_tolerance},
                   {"max_iterations", path.solver.max_iterations},
                   {"max_cutbacks", path.solver.max_cutbacks},
                   {"jacobian", path.solver.jacobian == SolverSettings::Jacobian::elastic
                                    ? "elastic"
                                    : "central_difference"}};
  doc["initial_state"] = {{"stress", stress_json(s0.stress)},
                          {"deformation_gradient", tensor_json(s0.F)},
                          {"polar_rotation", tensor_json(s0.R)},
                          {"frame_rotation", tensor_json(Q)},
                          {"plastic_strain", s0.plastic_strain},
                          {"plastic_strain_rate", s0.plastic_strain_rate},
                          {"internal_energy", s0.internal_energy},
                          {"damage", s0.damage},
                          {"porosity", s0.porosity},
                          {"failed", s0.failed}};
  Json l = {{"label", "replay of " + leg.label}, {"duration", dt}, {"steps", 1}};
  const char* thermal[] = {"isothermal", "adiabatic", "prescribed"};
  l["thermal"] = thermal[static_cast<int>(leg.thermal)];
  if (leg.thermal == Thermal::prescribed) l["temperature"] = end_temperature;
  if (rotation_rate != 0.0) {
    l["rotation"] = {
        {"axis", {leg.rotation_axis.x(), leg.rotation_axis.y(), leg.rotation_axis.z()}},
        {"angle", rotation_rate * dt}};
  }
  const double s_end = (t_leg + dt) / leg.duration;
  if (plan.all_deformation) {
    l["velocity_gradient"] = tensor_json(plan.L_fixed);
  } else {
    Json L = Json::object(), F = Json::object(), S = Json::object(), ratio = Json::object();
    for (int k = 0; k < 9; ++k) {
      if (leg.velocity_gradient[k]) L[tensor_names[k]] = *leg.velocity_gradient[k];
    }
    for (const ControlEquation& q : plan.equations) {
      const int k = 3 * q.i + q.j;
      int c = 0;  // the stress component of a stress row (0 for F rows, unused)
      while (c < 5 && !(stress_index[c][0] == q.i && stress_index[c][1] == q.j)) ++c;
      switch (q.kind) {
        case ControlEquation::Kind::deformation:
          F[tensor_names[k]] = q.target(s_end);
          break;
        case ControlEquation::Kind::stress:
          S[stress_names[c]] = q.target(s_end);
          break;
        case ControlEquation::Kind::stress_ratio:
          ratio[stress_names[c]] = q.ratio;
          ratio["of"] = stress_names[leg.ratio_of];
          break;
      }
    }
    if (!L.empty()) l["velocity_gradient"] = L;
    if (!F.empty()) l["deformation_gradient"] = F;
    if (!S.empty()) l["stress"] = S;
    if (!ratio.empty()) l["stress_ratio"] = ratio;
  }
  doc["legs"] = Json::array({l});
  return doc;
}

}  // namespace impact::pointdriver
