// PointState's members, one line each: what every member-wise consumer (the MPM checkpoint, the
// particle snapshots, the Python state dict) walks, so a new history variable is one member in
// point_state.hpp, one line here and its use. A member missing from the table fails to compile
// (the static_assert at the end).
#pragma once

#include <cstddef>
#include <cstdint>
#include <tuple>

#include "models/core/aggregate_arity.hpp"
#include "models/core/point_state.hpp"

namespace impact {

/// One PointState member: its name (the key in a checkpoint, a snapshot and a Python state dict),
/// its SI unit ("-" when dimensionless or a code) and where it lives. T is the member's type:
/// Mat3 (a tensor), double (a scalar), bool (a flag), FailureCause or std::uint8_t (a code).
template <class T>
struct StateMember {
  using Type = T;
  const char* name;
  const char* unit;
  T PointState::*member;
};

/// Every member, in declaration order (the order of a checkpoint's state record).
inline constexpr auto kPointStateMembers = std::make_tuple(
    StateMember<Mat3>{"stress", "Pa", &PointState::stress},
    StateMember<Mat3>{"F", "-", &PointState::F}, StateMember<Mat3>{"R", "-", &PointState::R},
    StateMember<double>{"plastic_strain", "-", &PointState::plastic_strain},
    StateMember<double>{"plastic_strain_rate", "1/s", &PointState::plastic_strain_rate},
    StateMember<double>{"temperature", "K", &PointState::temperature},
    StateMember<double>{"internal_energy", "J/kg", &PointState::internal_energy},
    StateMember<double>{"damage", "-", &PointState::damage},
    StateMember<double>{"porosity", "-", &PointState::porosity},
    StateMember<double>{"flow_internal", "Pa", &PointState::flow_internal},
    StateMember<bool>{"melted", "-", &PointState::melted},
    StateMember<bool>{"failed", "-", &PointState::failed},
    StateMember<FailureCause>{"failure_cause", "-", &PointState::failure_cause},
    StateMember<std::uint8_t>{"instability", "-", &PointState::instability},
    StateMember<bool>{"failed_in_tension", "-", &PointState::failed_in_tension});

/// f(member) for every line of kPointStateMembers, in order.
template <class F>
constexpr void for_each_state_member(F&& f) {
  std::apply([&](const auto&... m) { (f(m), ...); }, kPointStateMembers);
}

/// The largest valid FailureCause (what a reader checks a stored code against).
inline constexpr FailureCause kLastFailureCause = FailureCause::becker;

static_assert(aggregate_arity<PointState>() == std::tuple_size_v<decltype(kPointStateMembers)>,
              "a PointState member is missing from kPointStateMembers");

}  // namespace impact
