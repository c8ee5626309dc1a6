#include "mpm/output/particle_paths.hpp"

#include <array>
#include <limits>
#include <type_traits>

#include "models/material/material.hpp"
#include "support/atomic_file.hpp"

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

ParticlePaths::ParticlePaths(const Scene& scene, const Particles& initial, const Communicator& comm)
    : comm_(comm) {
  // Each rank's nearest candidate per path; on several ranks every rank's, then the nearest.
  struct Candidate {
    double distance;
    std::uint64_t id;
    PointState state;
  };
  std::vector<Candidate> best;
  for (const ParticlePathSpec& spec : scene.output.particle_paths) {
    Candidate c{std::numeric_limits<double>::infinity(), 0, PointState{}};
    for (std::size_t p = 0; p < initial.size(); ++p) {
      if (initial.object[p] != spec.object) continue;
      // Ties go to the lowest seed index, whatever the storage order (solver.shuffle_particles)
      // or the rank count.
      const double d = (initial.x[p] - spec.position).squaredNorm();
      const std::uint64_t id = seed_index(initial, p);
      if (d < c.distance || (d == c.distance && id < c.id)) c = {d, id, initial.state[p]};
    }
    best.push_back(c);
  }
  if (comm_.several()) {
    const std::vector<Candidate> every = comm_.concatenate(best);
    for (std::size_t i = 0; i < best.size(); ++i) {
      for (std::size_t r = 0; r < every.size() / best.size(); ++r) {
        const Candidate& c = every[r * best.size() + i];
        if (c.distance < best[i].distance || (c.distance == best[i].distance && c.id < best[i].id))
          best[i] = c;
      }
    }
  }
  for (std::size_t i = 0; i < best.size(); ++i) {
    Track t;
    t.name = scene.output.particle_paths[i].name;
    t.id = best[i].id;
    t.start = best[i].state;
    tracks_.push_back(std::move(t));
  }
}

std::size_t ParticlePaths::find(Track& t, const Particles& P) const {
  if (P.id.empty()) return t.id < P.size() ? t.id : P.size();  // seed order: the seed index
  if (t.held < P.size() && P.id[t.held] == t.id) return t.held;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.id[p] == t.id) return t.held = p;
  }
  return P.size();
}

void ParticlePaths::begin_at(const Particles& P) {
  struct Start {
    std::uint32_t track;
    PointState state;
  };
  std::vector<Start> mine;
  for (std::uint32_t i = 0; i < tracks_.size(); ++i) {
    const std::size_t p = find(tracks_[i], P);
    if (p < P.size()) mine.push_back({i, P.state[p]});
  }
  for (const Start& s : comm_.concatenate(mine)) tracks_[s.track].start = s.state;
}

void ParticlePaths::before_step(const Particles& P) {
  for (Track& t : tracks_) {
    const std::size_t p = find(t, P);
    t.pending = p < P.size();
    if (t.pending) t.pending_temperature = P.state[p].temperature;
  }
}

void ParticlePaths::after_step(const Particles& P, double time, double dt) {
  if (!comm_.several()) {
    for (Track& t : tracks_) {
      const std::size_t p = find(t, P);
      t.steps.push_back({time, dt, t.pending_temperature, P.L[p], P.state[p]});
    }
    return;
  }
  // What this rank knows of the step: the start temperature (held before it), the rest (held
  // after it); every rank's pieces, then each track's step put together.
  struct Piece {
    std::uint32_t track;
    bool temperature, rest;
    Step step;
  };
  std::vector<Piece> mine;
  for (std::uint32_t i = 0; i < tracks_.size(); ++i) {
    Track& t = tracks_[i];
    const std::size_t p = find(t, P);
    const bool rest = p < P.size();
    if (!t.pending && !rest) continue;
    Piece piece{i, t.pending, rest, {time, dt, t.pending_temperature, Mat3::Zero(), PointState{}}};
    if (rest) {
      piece.step.L = P.L[p];
      piece.step.end = P.state[p];
    }
    mine.push_back(piece);
  }
  std::vector<Step> steps(tracks_.size(), Step{time, dt, 0.0, Mat3::Zero(), PointState{}});
  for (const Piece& piece : comm_.concatenate(mine)) {
    Step& s = steps[piece.track];
    if (piece.temperature) s.start_temperature = piece.step.start_temperature;
    if (piece.rest) {
      s.L = piece.step.L;
      s.end = piece.step.end;
    }
  }
  for (std::size_t i = 0; i < tracks_.size(); ++i) tracks_[i].steps.push_back(steps[i]);
}

void ParticlePaths::write(const fs::path& dir, const Scene& scene, const std::string& scene_file,
                          double start_time) const {
  if (tracks_.empty() || !comm_.root()) return;  // rank 0 writes
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
    doc["description"] = "Path of particle " + std::to_string(t.id) + " (object " +
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
