// The Simulation's part of a checkpoint (format in mpm/run/checkpoint.hpp): every particle array,
// the boxes, the counters and every ledger accumulator, so that load() continues bit for bit.
#include <algorithm>
#include <type_traits>

#include "models/core/point_state_fields.hpp"
#include "mpm/output/checkpoint_stream.hpp"
#include "mpm/simulation/simulation.hpp"

namespace impact::mpm {

namespace {

// The tags of the boxes' boundaries along x, y and z (format 6).
constexpr const char* kBoxTags[3] = {"boxes_x", "boxes_y", "boxes_z"};

// Eigen's fixed-size Vec3 and Mat3 are plain arrays of doubles: written as stored.
static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Mat3) == 9 * sizeof(double));

// A PointState member's bytes in the file: tensors and numbers as stored, flags and codes as one
// byte each (no padding bytes in the file).
template <class T>
constexpr std::uint32_t stored_size() {
  return std::is_same_v<T, Mat3> || std::is_same_v<T, double> ? sizeof(T) : 1;
}

// The PointState members, one record per particle, in the order of kPointStateMembers.
constexpr std::uint32_t state_record() {
  std::uint32_t bytes = 0;
  for_each_state_member(
      [&](const auto& m) { bytes += stored_size<typename std::decay_t<decltype(m)>::Type>(); });
  return bytes;
}
constexpr std::uint32_t kStateRecord = state_record();
static_assert(kStateRecord == 3 * sizeof(Mat3) + 7 * sizeof(double) + 5,
              "PointState changed: raise kCheckpointVersion (mpm/run/checkpoint.hpp)");

void save_states(CheckpointWriter& out, const char* tag, const std::vector<PointState>& states) {
  out.section(tag, states.size(), kStateRecord);
  for (const PointState& s : states) {
    for_each_state_member([&](const auto& m) {
      using T = typename std::decay_t<decltype(m)>::Type;
      if constexpr (stored_size<T>() == 1)
        out.value(static_cast<std::uint8_t>(s.*m.member));
      else
        out.value(s.*m.member);
    });
  }
}

void load_states(CheckpointReader& in, const char* tag, std::vector<PointState>& states) {
  in.section(tag, kStateRecord, states.size());
  for (PointState& s : states) {
    for_each_state_member([&](const auto& m) {
      using T = typename std::decay_t<decltype(m)>::Type;
      if constexpr (std::is_same_v<T, bool>) {
        s.*m.member = in.value<std::uint8_t>() != 0;
      } else if constexpr (std::is_same_v<T, FailureCause>) {
        const auto code = in.value<std::uint8_t>();
        if (code > static_cast<std::uint8_t>(kLastFailureCause))
          in.fail(std::string(m.name) + " out of range");
        s.*m.member = static_cast<FailureCause>(code);
      } else if constexpr (std::is_same_v<T, Mat3>) {
        in.bytes(&(s.*m.member), sizeof(T));
      } else {
        s.*m.member = in.value<T>();
      }
    });
  }
}

}  // namespace

void Simulation::save(CheckpointWriter& out) const {
  const Particles& P = particles_;
  for_each_particle_array([&](const auto& a) {
    if constexpr (std::is_same_v<typename std::decay_t<decltype(a)>::Element, PointState>)
      save_states(out, a.name, P.*a.member);
    else
      out.array(a.name, P.*a.member);
  });
  for (int d = 0; d < 3; ++d) out.array(kBoxTags[d], boxes_.axis(d).first_cells());
  out.value(static_cast<std::int64_t>(rebalances_));
  out.section("simulation", 1, 3 * sizeof(double) + 5 * sizeof(std::int64_t));
  out.value(time_);
  out.value(static_cast<std::int64_t>(steps_));
  out.value(max_signal_speed_);
  out.value(static_cast<std::int64_t>(failed_));
  out.value(static_cast<std::int64_t>(converted_));
  out.value(static_cast<std::int64_t>(faulted_));
  out.value(static_cast<std::int64_t>(removed_));
  out.value(static_cast<std::int64_t>(narrowed_));
  const Ledger::State& l = ledger_.state();
  const std::vector<double> record = all_fields(l);  // Ledger::State::kFields order
  out.section("ledger", 1, std::uint32_t(record.size() * sizeof(double)));
  for (const double d : record) out.value(d);
  out.array("ledger_sinks", l.sinks);
}

void Simulation::load(CheckpointReader& in) {
  Particles& P = particles_;
  const std::uint64_t n = P.size();
  for_each_particle_array([&](const auto& a) {
    auto& values = P.*a.member;
    if constexpr (std::is_same_v<typename std::decay_t<decltype(a)>::Element, PointState>)
      load_states(in, a.name, values);
    else
      in.array(a.name, values, a.optional ? values.size() : n);  // optional: sized by the scene
  });
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
  in.section("simulation", 3 * sizeof(double) + 5 * sizeof(std::int64_t), 1);
  time_ = in.value<double>();
  steps_ = static_cast<long>(in.value<std::int64_t>());
  max_signal_speed_ = in.value<double>();
  failed_ = static_cast<long>(in.value<std::int64_t>());
  converted_ = static_cast<long>(in.value<std::int64_t>());
  faulted_ = static_cast<long>(in.value<std::int64_t>());
  removed_ = static_cast<long>(in.value<std::int64_t>());
  narrowed_ = static_cast<long>(in.value<std::int64_t>());
  Ledger::State l;
  std::vector<double> record(field_count<Ledger::State>());
  in.section("ledger", std::uint32_t(record.size() * sizeof(double)), 1);
  for (double& d : record) d = in.value<double>();
  set_all_fields(l, record);
  in.array("ledger_sinks", l.sinks, ledger_.sink_names().size());
  ledger_.restore(l);
  particle_contact_current_ =
      false;  // its forces were the seeded state's: the next step re-evaluates
  if (particle_contact_) particle_contact_->resume();
}

}  // namespace impact::mpm
