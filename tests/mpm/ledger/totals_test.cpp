// Self-describing totals (mpm/ledger/totals.hpp): a struct with a sum, a largest, a Vec3, a count
// and a nested totals struct, merged and flattened by its table. The values are exact in binary,
// so every comparison is exact. Also: every ParticleTotals / StressTotals / GridUpdate member
// that a rank reduction must carry is in its table (a member left out would come back zero).
#include <boost/test/unit_test.hpp>

#include "mpm/ledger/ledger.hpp"
#include "mpm/ledger/totals.hpp"
#include "mpm/step/step.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct Inner {
  double heat = 0.0;
  long nodes = 0;
  static constexpr auto kFields = std::tuple{summed(&Inner::heat), summed(&Inner::nodes)};
};

struct Outer {
  double energy = 0.0;
  Vec3 momentum = Vec3::Zero();
  double speed = 0.0;
  Inner inner;
  long removed = 0;
  static constexpr auto kFields =
      std::tuple{summed(&Outer::energy), summed(&Outer::momentum), largest(&Outer::speed),
                 summed(&Outer::inner), summed(&Outer::removed)};
};

Outer make(double e, double speed, long removed) {
  Outer o;
  o.energy = e;
  o.momentum = Vec3(e, -2.0 * e, 0.5);
  o.speed = speed;
  o.inner.heat = 0.25 * e;
  o.inner.nodes = removed + 1;
  o.removed = removed;
  return o;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(totals)

BOOST_AUTO_TEST_CASE(merge_adds_sums_and_keeps_the_largest) {
  Outer total;
  merge_into(total, make(1.0, 7.0, 2));
  merge_into(total, make(3.0, 5.0, 4));
  BOOST_TEST(total.energy == 4.0);
  BOOST_TEST(total.momentum(0) == 4.0);
  BOOST_TEST(total.momentum(1) == -8.0);
  BOOST_TEST(total.momentum(2) == 1.0);
  BOOST_TEST(total.speed == 7.0);  // the largest, not 12
  BOOST_TEST(total.inner.heat == 1.0);
  BOOST_TEST(total.inner.nodes == 8);
  BOOST_TEST(total.removed == 6);
}

BOOST_AUTO_TEST_CASE(fields_flatten_by_merge_and_come_back) {
  const Outer o = make(3.0, 5.0, 4);
  std::vector<double> sums, maxima;
  append_fields(o, Merge::sum, sums);
  append_fields(o, Merge::max, maxima);
  // energy, momentum (3), inner.heat, inner.nodes, removed: in table order.
  BOOST_TEST(sums == (std::vector<double>{3.0, 3.0, -6.0, 0.5, 0.75, 5.0, 4.0}),
             boost::test_tools::per_element());
  BOOST_TEST(maxima == std::vector<double>{5.0}, boost::test_tools::per_element());
  Outer back;
  std::size_t k = 0;
  extract_fields(back, Merge::sum, sums, k);
  BOOST_TEST(k == sums.size());
  k = 0;
  extract_fields(back, Merge::max, maxima, k);
  BOOST_TEST(k == 1u);
  BOOST_TEST(all_fields(back) == all_fields(o), boost::test_tools::per_element());
  BOOST_TEST(field_count<Outer>() == 8u);
  Outer wrong;
  BOOST_CHECK_THROW(set_all_fields(wrong, std::vector<double>(7, 1.0)), std::invalid_argument);
}

// A member missing from a table would not cross threads or ranks (it would come back zero). The
// structured bindings below stop compiling when a member is added; the count of doubles the
// members hold must then equal what the table carries.
template <class M>
std::size_t doubles_in(const M&) {
  if constexpr (SelfDescribingTotals<M>)
    return field_count<M>();
  else if constexpr (std::is_same_v<M, Vec3>)
    return 3;
  else if constexpr (std::is_arithmetic_v<M>)
    return 1;
  else
    return 0;  // a list (StressTotals::faulted), joined separately
}

BOOST_AUTO_TEST_CASE(the_step_totals_tables_name_every_member) {
  {
    const auto& [a, b, c, d] = ContactTotals{};
    BOOST_TEST(field_count<ContactTotals>() ==
               doubles_in(a) + doubles_in(b) + doubles_in(c) + doubles_in(d));
  }
  {
    const auto& [a, b, c, d, e] = GridUpdate{};
    BOOST_TEST(field_count<GridUpdate>() ==
               doubles_in(a) + doubles_in(b) + doubles_in(c) + doubles_in(d) + doubles_in(e));
  }
  {
    const auto& [a, b, c, d, e, f, g, h, i, j] = ParticleTotals{};
    BOOST_TEST(field_count<ParticleTotals>() ==
               doubles_in(a) + doubles_in(b) + doubles_in(c) + doubles_in(d) + doubles_in(e) +
                   doubles_in(f) + doubles_in(g) + doubles_in(h) + doubles_in(i) + doubles_in(j));
  }
  {
    const auto& [a, b, c, d, e, f, g, h] = StressTotals{};
    BOOST_TEST(field_count<StressTotals>() == doubles_in(a) + doubles_in(b) + doubles_in(c) +
                                                  doubles_in(d) + doubles_in(e) + doubles_in(f) +
                                                  doubles_in(g) + doubles_in(h));
  }
  {
    const auto& [a, b, c, d, e, f, g, h, i, j, k, l, m, n] = Ledger::State{};
    BOOST_TEST(field_count<Ledger::State>() ==
               doubles_in(a) + doubles_in(b) + doubles_in(c) + doubles_in(d) + doubles_in(e) +
                   doubles_in(f) + doubles_in(g) + doubles_in(h) + doubles_in(i) + doubles_in(j) +
                   doubles_in(k) + doubles_in(l) + doubles_in(m) + doubles_in(n));
    // The checkpoint record: 8 doubles and 5 Vec3, the ledger section of format version 9.
    BOOST_TEST(field_count<Ledger::State>() == 8u + 5u * 3u);
  }
}

BOOST_AUTO_TEST_SUITE_END()
