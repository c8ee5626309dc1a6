#include "mpm/output/particle_paths.hpp"

#include <array>
#include <limits>

#include "models/material/material.hpp"
#include "mpm/output/atomic_file.hpp"

namespace impact::mpm {

namespace fs = std::filesystem;

namespace {

constexpr std::array<const char*, 9> kTensor{"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"};

Json tensor(const Mat3& a) {
  Json j = Json::object();
  for (int k = 0; k < 9; ++k) j[kTensor[k]] = a(k / 3, k % 3);
  return j;
}

Json symmetric(const Mat3& a) {
  return {{"xx", a(0, 0)}, {"yy", a(1, 1)}, {"zz", a(2, 2)},
          {"xy", a(0, 1)}, {"yz", a(1, 2)}, {"zx", a(2, 0)}};
}

}  // namespace

ParticlePaths::ParticlePaths(const Scene& scene, const Particles& initial) {
  for (const ParticlePathSpec& spec : scene.output.particle_paths) {
    Track t;
    t.name = spec.name;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t p = 0; p < initial.size(); ++p) {
      if (initial.object[p] != spec.object) continue;
      const double d = (initial.x[p] - spec.position).squaredNorm();
      if (d < best) {
        best = d;
        t.particle = p;
      }
    }
    t.start = initial.state[t.particle];
    tracks_.push_back(std::move(t));
  }
}

void ParticlePaths::before_step(const Particles& P) {
  for (Track& t : tracks_) t.pending_temperature = P.state[t.particle].temperature;
}

void ParticlePaths::after_step(const Particles& P, double time, double dt) {
  for (Track& t : tracks_) {
    t.steps.push_back({time, dt, t.pending_temperature, P.L[t.particle], P.state[t.particle]});
  }
}

void ParticlePaths::write(const fs::path& dir, const Scene& scene, const std::string& scene_file,
                          double start_time) const {
  if (tracks_.empty()) return;
  const fs::path out = dir / "paths";
  fs::create_directories(out);
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const Track& t = tracks_[i];
    const ParticlePathSpec& spec = scene.output.particle_paths[i];
    const Material& material = scene.materials[scene.objects[spec.object].material].material;
    const std::string material_file = t.name + ".material.json";
    write_file_atomically(out / material_file,
                          [&](std::ostream& o) { o << to_json(material).dump(2) << '\n'; });
    Json doc;
    doc["description"] = "Path of particle " + std::to_string(t.particle) + " (object " +
                         scene.objects[spec.object].name + ") of " + scene_file +
                         " from t = " + std::to_string(start_time) + " s, written by mpm run " +
                         "(output.particle_paths." + t.name + ")";
    doc["material"] = material_file;
    doc["temperature"] = t.start.temperature;
    doc["thermal"] = "isothermal";
    doc["failure_policy"] = "continue";
    const PointState& s = t.start;
    doc["initial_state"] = {{"stress", symmetric(s.stress)},
                            {"deformation_gradient", tensor(s.F)},
                            {"polar_rotation", tensor(s.R)},
                            {"plastic_strain", s.plastic_strain},
                            {"plastic_strain_rate", s.plastic_strain_rate},
                            {"internal_energy", s.internal_energy},
                            {"damage", s.damage},
                            {"porosity", s.porosity},
                            {"failed", s.failed}};
    Json legs = Json::array();
    for (const Step& st : t.steps) {
      legs.push_back({{"duration", st.dt},
                      {"steps", 1},
                      {"velocity_gradient", tensor(st.L)},
                      {"start_temperature", st.start_temperature}});
    }
    doc["legs"] = std::move(legs);
    write_file_atomically(out / (t.name + ".json"),
                          [&](std::ostream& o) { o << doc.dump() << '\n'; });
    write_file_atomically(out / (t.name + ".csv"), [&](std::ostream& o) {
      o.precision(17);
      o << "time [s],dt [s],start_temperature [K],stress_xx [Pa],stress_yy [Pa],stress_zz [Pa],"
           "stress_xy [Pa],stress_yz [Pa],stress_zx [Pa],plastic_strain [-],temperature [K],"
           "damage [-],failed [-]\n";
      for (const Step& st : t.steps) {
        const Mat3& a = st.end.stress;
        o << st.time << ',' << st.dt << ',' << st.start_temperature << ',' << a(0, 0) << ','
          << a(1, 1) << ',' << a(2, 2) << ',' << a(0, 1) << ',' << a(1, 2) << ',' << a(2, 0) << ','
          << st.end.plastic_strain << ',' << st.end.temperature << ',' << st.end.damage << ','
          << (st.end.failed ? 1 : 0) << '\n';
      }
    });
  }
}

}  // namespace impact::mpm
