// Totals that describe their own fields. Each totals struct of a step (ParticleTotals,
// StressTotals, GridUpdate, ContactTotals) and the ledger's State list their members once, in a
// table `kFields`, as PhaseTimes::kPhases does for the timers; the thread merge, the reduction
// over ranks and the checkpoint walk that table. Why: four hand-ordered lists of the same members
// had to agree, and a ledger column cost 5 to 18 edits; now a total is a member plus its line.
#pragma once

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <vector>

#include "models/core/tensor.hpp"

namespace impact::mpm {

/// How a field combines across threads and ranks.
enum class Merge { sum, max };

/// One line of a `kFields` table: a member and how it combines. A member may itself be a totals
/// struct (its own table then decides).
template <class T, class M>
struct TotalsField {
  M T::*member;
  Merge merge;
};
template <class T, class M>
constexpr TotalsField<T, M> summed(M T::*member) {
  return {member, Merge::sum};
}
template <class T, class M>
constexpr TotalsField<T, M> largest(M T::*member) {
  return {member, Merge::max};
}

/// A field that is saved (all_fields) but never merged.
template <class T, class M>
constexpr TotalsField<T, M> saved(M T::*member) {
  return {member, Merge::sum};
}

template <class T>
concept SelfDescribingTotals = requires {
  T::kFields;
};

namespace totals_detail {

template <class M>
void combine(M& total, const M& part, Merge merge);

template <SelfDescribingTotals T>
void combine_all(T& total, const T& part) {
  std::apply([&](const auto&... f) { (combine(total.*f.member, part.*f.member, f.merge), ...); },
             T::kFields);
}

template <class M>
void combine(M& total, const M& part, Merge merge) {
  if constexpr (SelfDescribingTotals<M>) {
    combine_all(total, part);
  } else if constexpr (std::is_same_v<M, Vec3>) {
    if (merge == Merge::max) throw std::logic_error("totals: a Vec3 has no largest");
    total += part;
  } else {
    total = merge == Merge::sum ? total + part : std::max(total, part);
  }
}

// `which` null: every field (a checkpoint); else those that combine by *which.
template <class M>
void append(const M& m, Merge merge, const Merge* which, std::vector<double>& out) {
  if constexpr (SelfDescribingTotals<M>) {
    std::apply([&](const auto&... f) { (append(m.*f.member, f.merge, which, out), ...); },
               M::kFields);
  } else if (which && merge != *which) {
    return;
  } else if constexpr (std::is_same_v<M, Vec3>) {
    out.insert(out.end(), {m(0), m(1), m(2)});
  } else {
    out.push_back(static_cast<double>(m));
  }
}

template <class M>
void extract(M& m, Merge merge, const Merge* which, const std::vector<double>& in, std::size_t& k) {
  if constexpr (SelfDescribingTotals<M>) {
    std::apply([&](const auto&... f) { (extract(m.*f.member, f.merge, which, in, k), ...); },
               M::kFields);
  } else if (which && merge != *which) {
    return;
  } else if constexpr (std::is_same_v<M, Vec3>) {
    for (int d = 0; d < 3; ++d) m(d) = in.at(k++);
  } else {
    m = static_cast<M>(in.at(k++));
  }
}

}  // namespace totals_detail

/// total (+)= part, field by field: sums add, largest take the max.
template <SelfDescribingTotals T>
void merge_into(T& total, const T& part) {
  totals_detail::combine_all(total, part);
}

/// The fields that combine by `which`, in table order, as doubles (a Vec3 as three, a count
/// converted exactly below 2^53): what a reduction over ranks sends.
template <SelfDescribingTotals T>
void append_fields(const T& t, Merge which, std::vector<double>& out) {
  totals_detail::append(t, which, &which, out);
}

/// The inverse of append_fields, reading from in[k] on; advances k.
template <SelfDescribingTotals T>
void extract_fields(T& t, Merge which, const std::vector<double>& in, std::size_t& k) {
  totals_detail::extract(t, which, &which, in, k);
}

/// Every field in table order (a checkpoint record), and its inverse.
template <SelfDescribingTotals T>
std::vector<double> all_fields(const T& t) {
  std::vector<double> out;
  totals_detail::append(t, Merge::sum, nullptr, out);
  return out;
}
/// How many doubles all_fields() gives.
template <SelfDescribingTotals T>
std::size_t field_count() {
  return all_fields(T{}).size();
}
template <SelfDescribingTotals T>
void set_all_fields(T& t, const std::vector<double>& in) {
  if (in.size() != field_count<T>()) throw std::invalid_argument("totals: record of wrong length");
  std::size_t k = 0;
  totals_detail::extract(t, Merge::sum, nullptr, in, k);
}

}  // namespace impact::mpm
