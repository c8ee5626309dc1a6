// The Simulation's part of a checkpoint (format in mpm/run/checkpoint.hpp): every particle array,
// the boxes, the counters and every ledger accumulator, so that load() continues bit for bit.
#include <algorithm>

#include "mpm/output/checkpoint_stream.hpp"
#include "mpm/simulation/simulation.hpp"

namespace impact::mpm {

namespace {

// The tags of the boxes' boundaries along x, y and z (format 6).
constexpr const char* kBoxTags[3] = {"boxes_x", "boxes_y", "boxes_z"};

// A new PointState or Particles member must be added to save()/load() below (and the format
// version raised): these fail to compile until then.
static_assert(sizeof(PointState) == 3 * sizeof(Mat3) + 7 * sizeof(double) + 8,
              "PointState changed: update Simulation::save/load and kCheckpointVersion");
static_assert(sizeof(Particles) == 15 * sizeof(std::vector<double>),
              "Particles changed: update Simulation::save/load and kCheckpointVersion");
// Eigen's fixed-size Vec3 and Mat3 are plain arrays of doubles: written as stored.
static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Mat3) == 9 * sizeof(double));

// The PointState members, one record per particle (no padding bytes in the file).
constexpr std::uint32_t kStateRecord = 3 * sizeof(Mat3) + 7 * sizeof(double) + 5;

}  // namespace

void Simulation::save(CheckpointWriter& out) const {
  const Particles& P = particles_;
  out.array("x", P.x);
  out.array("v", P.v);
  out.array("mass", P.mass);
  out.array("volume0", P.volume0);
  out.array("volume", P.volume);
  out.array("L", P.L);
  out.section("state", P.size(), kStateRecord);
  for (const PointState& s : P.state) {
    out.value(s.stress);
    out.value(s.F);
    out.value(s.R);
    for (const double d : {s.plastic_strain, s.plastic_strain_rate, s.temperature,
                           s.internal_energy, s.damage, s.porosity, s.flow_internal})
      out.value(d);
    out.value(static_cast<std::uint8_t>(s.melted));
    out.value(static_cast<std::uint8_t>(s.failed));
    out.value(static_cast<std::uint8_t>(s.failure_cause));
    out.value(s.instability);
    out.value(static_cast<std::uint8_t>(s.failed_in_tension));
  }
  out.array("wave_speed", P.wave_speed);
  out.array("material", P.material);
  out.array("object", P.object);
  out.array("field", P.field);
  out.array("q", P.q);
  out.array("fault", P.fault);
  out.array("removed", P.removed);
  out.array("id", P.id);
  for (int d = 0; d < 3; ++d) out.array(kBoxTags[d], boxes_.axis(d).first_cells());
  out.value(static_cast<std::int64_t>(rebalances_));
  out.section("simulation", 1, 3 * sizeof(double) + 4 * sizeof(std::int64_t));
  out.value(time_);
  out.value(static_cast<std::int64_t>(steps_));
  out.value(max_signal_speed_);
  out.value(static_cast<std::int64_t>(failed_));
  out.value(static_cast<std::int64_t>(converted_));
  out.value(static_cast<std::int64_t>(faulted_));
  out.value(static_cast<std::int64_t>(removed_));
  const Ledger::State& l = ledger_.state();
  const std::vector<double> record = all_fields(l);  // Ledger::State::kFields order
  out.section("ledger", 1, std::uint32_t(record.size() * sizeof(double)));
  for (const double d : record) out.value(d);
  out.array("ledger_sinks", l.sinks);
}

void Simulation::load(CheckpointReader& in) {
  Particles& P = particles_;
  const std::uint64_t n = P.size();
  in.array("x", P.x, n);
  in.array("v", P.v, n);
  in.array("mass", P.mass, n);
  in.array("volume0", P.volume0, n);
  in.array("volume", P.volume, n);
  in.array("L", P.L, n);
  in.section("state", kStateRecord, n);
  for (PointState& s : P.state) {
    in.bytes(&s.stress, sizeof s.stress);
    in.bytes(&s.F, sizeof s.F);
    in.bytes(&s.R, sizeof s.R);
    for (double* d : {&s.plastic_strain, &s.plastic_strain_rate, &s.temperature, &s.internal_energy,
                      &s.damage, &s.porosity, &s.flow_internal})
      *d = in.value<double>();
    s.melted = in.value<std::uint8_t>() != 0;
    s.failed = in.value<std::uint8_t>() != 0;
    const auto cause = in.value<std::uint8_t>();
    if (cause > static_cast<std::uint8_t>(FailureCause::becker))
      in.fail("failure cause out of range");
    s.failure_cause = static_cast<FailureCause>(cause);
    s.instability = in.value<std::uint8_t>();
    s.failed_in_tension = in.value<std::uint8_t>() != 0;
  }
  in.array("wave_speed", P.wave_speed, n);
  in.array("material", P.material, n);
  in.array("object", P.object, n);
  in.array("field", P.field, n);
  in.array("q", P.q, P.q.size());
  in.array("fault", P.fault, P.fault.size());
  in.array("removed", P.removed, P.removed.size());
  in.array("id", P.id, P.id.size());
  std::array<SlabDecomposition, 3> axes;
  for (int d = 0; d < 3; ++d) {
    std::vector<int> first_cells;
    in.array(kBoxTags[d], first_cells, std::uint64_t(boxes_.axis(d).ranks()) + 1);
    if (first_cells.front() != 0 || first_cells.back() != scene_.grid.cells[std::size_t(d)] ||
        !std::is_sorted(first_cells.begin(), first_cells.end()))
      in.fail(std::string(kBoxTags[d]) + ": box boundaries out of order (corrupt checkpoint)");
    axes[std::size_t(d)] = SlabDecomposition(std::move(first_cells));
  }
  boxes_ = BoxDecomposition(std::move(axes));
  if (ranks_.several()) rebuild_grid();  // the nodes of the restored box
  rebalances_ = static_cast<long>(in.value<std::int64_t>());
  for (std::size_t p = 0; p < n; ++p) {
    if (P.material[p] >= scene_.materials.size() || P.object[p] >= scene_.objects.size() ||
        P.field[p] >= static_cast<std::size_t>(grid_.fields()))
      in.fail("particle " + std::to_string(p) + ": material, object or field out of range");
  }
  in.section("simulation", 3 * sizeof(double) + 4 * sizeof(std::int64_t), 1);
  time_ = in.value<double>();
  steps_ = static_cast<long>(in.value<std::int64_t>());
  max_signal_speed_ = in.value<double>();
  failed_ = static_cast<long>(in.value<std::int64_t>());
  converted_ = static_cast<long>(in.value<std::int64_t>());
  faulted_ = static_cast<long>(in.value<std::int64_t>());
  removed_ = static_cast<long>(in.value<std::int64_t>());
  Ledger::State l;
  std::vector<double> record(field_count<Ledger::State>());
  in.section("ledger", std::uint32_t(record.size() * sizeof(double)), 1);
  for (double& d : record) d = in.value<double>();
  set_all_fields(l, record);
  in.array("ledger_sinks", l.sinks, ledger_.sink_names().size());
  ledger_.restore(l);
}

}  // namespace impact::mpm
