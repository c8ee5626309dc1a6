// The number of data members of an aggregate, found by brace-initialising it from ever more
// arguments that convert to anything: what lets a table of members (point_state_fields.hpp,
// mpm/particles/particle_fields.hpp) fail to compile when a member is added without its line.
// Valid for aggregates whose members are not themselves aggregates (brace elision would count
// their members instead): tensors, scalars, enums and std::vector qualify.
#pragma once

#include <cstddef>
#include <utility>

namespace impact {

namespace arity_detail {

/// Converts to any type, in unevaluated operands only.
struct AnyMember {
  template <class T>
  operator T() const;  // NOLINT(google-explicit-constructor): the point of the type
};

template <class T, std::size_t... I>
constexpr bool initialisable(std::index_sequence<I...>) {
  return requires {
    T{(void(I), AnyMember{})...};
  };
}

}  // namespace arity_detail

/// The number of members of aggregate T (at most 64).
template <class T, std::size_t N = 0>
constexpr std::size_t aggregate_arity() {
  if constexpr (N < 64 && arity_detail::initialisable<T>(std::make_index_sequence<N + 1>{}))
    return aggregate_arity<T, N + 1>();
  else
    return N;
}

}  // namespace impact
