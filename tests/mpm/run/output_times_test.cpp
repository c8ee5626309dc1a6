// When the next history row is due (mpm/run/output_times.hpp): the interval's lattice, the same
// sums as repeated addition while few rows are due, and a bounded amount of work when an interval
// is tiny against the step (1e-18 s over a 4e-8 s step took 150 s a step before).
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "mpm/run/output_times.hpp"

using impact::mpm::next_output_after;

BOOST_AUTO_TEST_CASE(a_few_rows_due_give_the_sums_of_adding_the_interval) {
  const double interval = 1e-7;
  double added = interval;
  while (added <= 3.5e-7 * (1.0 + 1e-12)) added += interval;
  BOOST_TEST(next_output_after(interval, 3.5e-7, interval) == added);  // bit for bit
  // Not yet due: unchanged.
  BOOST_TEST(next_output_after(4e-7, 3.5e-7, interval) == 4e-7);
  // A row's time reached within round-off counts as reached.
  BOOST_TEST(next_output_after(4e-7, 4e-7 * (1.0 - 1e-14), interval) > 4e-7);
}

BOOST_AUTO_TEST_CASE(a_tiny_interval_lands_on_its_lattice_just_after_t) {
  // 1e-18 s against t = 4e-8 s: 4e10 rows behind. Adding one at a time took minutes.
  const double t = 4e-8, interval = 1e-18;
  const double next = next_output_after(interval, t, interval);
  BOOST_TEST(next > t * (1.0 + 1e-12));
  BOOST_TEST(next < t * (1.0 + 1e-12) + 3.0 * interval);
  // Below the rounding of t (its ulp is 6.6e-24 s), the lattice cannot move past t: the next row
  // is due at once, so every step writes one, and the call returns.
  const double below = next_output_after(1e-30, t, 1e-30);
  BOOST_TEST(below <= t * (1.0 + 1e-12));
  BOOST_TEST(std::isfinite(below));
}
