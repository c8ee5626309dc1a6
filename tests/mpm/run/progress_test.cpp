// The progress line's durations (mpm/run/progress.hpp duration_text): a person's units for
// ordinary values, two digits and an exponent for absurd ones. Before, the ETA of a run that
// never finishes (max_time 1e30 s) was printed with "%.0f": a number of 37 to 300 digits.
#include <boost/test/unit_test.hpp>
#include <limits>

#include "mpm/run/progress.hpp"

using impact::mpm::duration_text;

BOOST_AUTO_TEST_SUITE(mpm_progress)

BOOST_AUTO_TEST_CASE(durations_read_as_a_person_would_say_them) {
  BOOST_TEST(duration_text(0.0) == "0 s");
  BOOST_TEST(duration_text(42.4) == "42 s");
  BOOST_TEST(duration_text(59.4) == "59 s");
  BOOST_TEST(duration_text(59.6) == "1 min 0 s");
  BOOST_TEST(duration_text(725.0) == "12 min 5 s");
  BOOST_TEST(duration_text(3599.4) == "59 min 59 s");
  BOOST_TEST(duration_text(3600.0) == "1 h 0 min");
  BOOST_TEST(duration_text(12000.0) == "3 h 20 min");
  BOOST_TEST(duration_text(99.0 * 3600.0) == "99 h 0 min");
  BOOST_TEST(duration_text(100.0 * 3600.0) == "3.6e+05 s");
  BOOST_TEST(duration_text(6.2e301) == "6.2e+301 s");
  BOOST_TEST(duration_text(std::numeric_limits<double>::infinity()) == "unknown");
  BOOST_TEST(duration_text(std::numeric_limits<double>::quiet_NaN()) == "unknown");
  BOOST_TEST(duration_text(-1.0) == "0 s");  // a clock's jitter, never a negative duration
}

BOOST_AUTO_TEST_SUITE_END()
